// Curved-space helpers shared by the curved scenes and the curved matrix pipeline:
// the 4x4 matrix of an elementary isometry, the camera path, the built-in curved scenes.
#pragma once
#include <string>
#include <vector>

#include "pipelines/result.h"
#include "pipelines/scene/scene.h"

namespace mb {

// +1 for Spherical, -1 for Hyperbolic, 0 for Euclidean.
int kappaOf(Space space);
const char* spaceName(Space space);  // "Euclidean", "spherical (S3)", "hyperbolic (H3)"

// Matrix (column-major, acting on (x, y, z, w)) of the CurvedMove (i, j) at `angle`: a Givens
// rotation, or for j = 3 in H3 the boost [[cosh, sinh], [sinh, cosh]] of the (i, w) plane.
// The origin moves to (sin, cos) / (sinh, cosh) along +e_i for j = 3.
glm::dmat4 elementaryMatrix(int kappa, int i, int j, double angle);

// Camera -> world of `scene` at time t (product of the moves); world -> view is its inverse.
glm::dmat4 cameraToWorld(const CurvedScene& scene, double t);

// The built-in curved scenes: "s3_tiling", "h3_tiling".
const std::vector<std::string>& curvedSceneNames();
bool isCurvedScene(const std::string& name);
// The space of curved scene `name` without building it (Euclidean for any other name).
Space curvedSceneSpace(const std::string& name);
// Builds one (deterministic). Scene::source is the name; one Animation "camera_path" with no
// channels carries the camera path's duration so render/compare/report pick times in it.
Result<Scene> buildCurvedScene(const std::string& name);

}  // namespace mb
