// Morph targets on the CPU (glTF 2.0 3.7.2.2): a vertex's attribute plus its weighted target
// deltas, in target order, a zero weight skipped, as shaders/morph.glsl sums them on the GPU.
// Used where the CPU needs posed vertices (automatic framing, camera_rule.h; the motor blend's
// reference, harness/render/skin_reference.h).
#pragma once
#include <vector>

#include "pipelines/scene/scene.h"

namespace mb {

// Attribute `base` of vertex v of p plus its weighted deltas, `stream` picking the attribute's
// delta stream of a target (empty: that target does not morph it).
template <class Stream>
glm::vec3 morphedVec3(glm::vec3 base, const Primitive& p, size_t v, const std::vector<float>& weights, Stream stream) {
  for (size_t i = 0; i < p.targets.size() && i < weights.size(); ++i) {
    const std::vector<glm::vec3>& deltas = stream(p.targets[i]);
    if (weights[i] != 0.0f && v < deltas.size()) base += weights[i] * deltas[v];
  }
  return base;
}

// Position, normal and tangent (xyz; w is never morphed) of vertex v of p under `weights` (one
// per target; fewer: the rest count as 0).
inline glm::vec3 morphedPosition(const Primitive& p, size_t v, const std::vector<float>& weights) {
  return morphedVec3(p.positions[v], p, v, weights, [](const MorphTarget& t) -> const auto& { return t.positions; });
}
inline glm::vec3 morphedNormal(const Primitive& p, size_t v, const std::vector<float>& weights) {
  return morphedVec3(p.normals[v], p, v, weights, [](const MorphTarget& t) -> const auto& { return t.normals; });
}
inline glm::vec4 morphedTangent(const Primitive& p, size_t v, const std::vector<float>& weights) {
  return {morphedVec3(glm::vec3(p.tangents[v]), p, v, weights, [](const MorphTarget& t) -> const auto& { return t.tangents; }),
          p.tangents[v].w};
}

}  // namespace mb
