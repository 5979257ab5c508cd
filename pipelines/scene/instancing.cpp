#include "pipelines/scene/instancing.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "pipelines/scene/morph.h"

namespace mb {

MeshBounds meshBounds(const Mesh& mesh, const std::vector<float>& weights) {
  MeshBounds b;
  auto add = [&](const glm::vec3& p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return;
    b.lo = glm::min(b.lo, p);
    b.hi = glm::max(b.hi, p);
  };
  for (const Primitive& p : mesh.primitives) {
    for (size_t v = 0; v < p.positions.size(); ++v) add(morphedPosition(p, v, weights));
    for (const glm::vec3& v : p.patchPoints) add(v);
  }
  return b;
}

bool instanceable(const Scene& scene, const Node& node) {
  if (node.mesh < 0 || size_t(node.mesh) >= scene.meshes.size() || node.skin >= 0) return false;
  for (const Primitive& p : scene.meshes[size_t(node.mesh)].primitives)
    if (!p.patchPoints.empty()) return false;
  return true;
}

int dropUndrawableInstances(Scene& scene) {
  int dropped = 0;
  for (size_t n = 0; n < scene.nodes.size(); ++n) {
    Node& node = scene.nodes[n];
    if (node.instances.empty() || instanceable(scene, node)) continue;
    scene.unsupported.push_back("node " + std::to_string(n) + ": EXT_mesh_gpu_instancing on a " +
                                (node.skin >= 0 ? "skinned node" : "Bezier patch mesh") + ": drawn once, its " +
                                std::to_string(node.instances.size()) + " instances ignored (instancingDrawnOnce)");
    node.instances.clear();
    ++dropped;
  }
  return dropped;
}

int addGridInstances(Scene& scene, int count) {
  if (count <= 1) return 0;
  const int cols = int(std::ceil(std::sqrt(double(count))));
  const int rows = (count + cols - 1) / cols;
  int drawnOnce = 0;
  for (Node& node : scene.nodes) {
    if (node.mesh < 0 || size_t(node.mesh) >= scene.meshes.size()) continue;
    if (!instanceable(scene, node)) {
      ++drawnOnce;
      continue;
    }
    const MeshBounds b = meshBounds(scene.meshes[size_t(node.mesh)]);
    const glm::vec3 extent = b.empty() ? glm::vec3(1.0f) : glm::max(b.hi - b.lo, glm::vec3(1e-3f));
    const glm::vec3 step = 1.25f * glm::max(extent, glm::vec3(0.25f * std::max({extent.x, extent.y, extent.z})));
    const std::vector<TRS> base = node.instances.empty() ? std::vector<TRS>{TRS{}} : node.instances;
    node.instances.clear();
    node.instances.reserve(base.size() * size_t(count));
    for (int i = 0; i < count; ++i) {
      const glm::vec3 offset((float(i % cols) - 0.5f * float(cols - 1)) * step.x, 0.0f,
                             (float(i / cols) - 0.5f * float(rows - 1)) * step.z);
      for (TRS t : base) {
        t.translation += offset;
        node.instances.push_back(t);
      }
    }
  }
  return drawnOnce;
}

}  // namespace mb
