// Morph targets on the CPU (glTF 2.0 3.7.2.2): a vertex's attribute plus its weighted target
// deltas, in target order, a zero weight skipped, as shaders/morph.glsl sums them on the GPU.
// Used where the CPU needs posed vertices (automatic framing, camera_rule.h).
#pragma once
#include <vector>

#include "pipelines/scene/scene.h"

namespace mb {

// Position of vertex v of p under `weights` (one per target; fewer: the rest count as 0).
inline glm::vec3 morphedPosition(const Primitive& p, size_t v, const std::vector<float>& weights) {
  glm::vec3 out = p.positions[v];
  for (size_t i = 0; i < p.targets.size() && i < weights.size(); ++i)
    if (weights[i] != 0.0f && v < p.targets[i].positions.size()) out += weights[i] * p.targets[i].positions[v];
  return out;
}

}  // namespace mb
