// The posed points the automatic camera frames (camera_rule.h): every posed mesh vertex
// reachable from Scene::roots, with their bounds and the area-weighted normal of the drawn
// triangles. Internal to the camera rule (camera_rule.cpp, camera_fit.cpp).
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/scene/scene.h"

namespace mb {

struct PosedPoints {
  std::vector<glm::vec3> points;  // finite points within kMaxFramedCoordinate, in draw order
  glm::vec3 lo{0.0f}, hi{0.0f};   // their bounds (meaningless when points is empty)
  // Some point was skinned: other skinning methods than linear blend may bulge out of them.
  bool skinned = false;
  // Sum over the drawn triangles of cross(b - a, c - a), posed, in world space, turned with a
  // mirrored node's winding so it points to the side the front faces face (half the summed
  // area vectors; instanced draws and Bezier patches do not add to it).
  glm::dvec3 frontArea{0.0};
  glm::dvec3 absoluteArea{0.0};  // the same sum of |cross| per axis (what could face either way)
  bool empty() const { return points.empty(); }
};

// Posed by `world` (worldMatrices) and `weights` (sampleMorphWeights, one list per node):
// skinned vertices by linear blend skinning (joint origins included), instanced nodes by the
// corners of their morphed mesh's bounds per instance, Bezier patches by their control points.
PosedPoints posedPoints(const Scene& scene, const std::vector<glm::mat4>& world,
                        const std::vector<std::vector<float>>& weights);

}  // namespace mb
