// Morph targets (glTF 2.0 3.7.2.2): a primitive's POSITION / NORMAL / TANGENT deltas per
// target (sparse accessors included: readAccessorFloat applies them over zeros or the view) and
// the mesh's default weights. Deltas are read before hygiene; the hygiene's vertex splits and
// unwelds copy them with every other stream (flat_normals.cpp).
#include <tiny_gltf.h>

#include <cmath>

#include "pipelines/scene/gltf/accessors.h"
#include "pipelines/scene/gltf/gltf_convert.h"

namespace mb {
namespace {

// Target attribute `name` as vec3 deltas (TANGENT deltas are VEC3 in glTF), or empty when the
// target does not have it.
Result<std::vector<glm::vec3>> targetDeltas(const tinygltf::Model& m, const std::map<std::string, int>& target,
                                            const std::string& name, size_t vertexCount, const std::string& where) {
  using R = Result<std::vector<glm::vec3>>;
  auto it = target.find(name);
  if (it == target.end()) return std::vector<glm::vec3>{};
  auto data = readAccessorFloat(m, it->second, where + " " + name);
  if (!data) return R::fail(data.error());
  if (data->components != 3)
    return R::fail(where + ": " + name + " delta accessor " + std::to_string(it->second) + " has " +
                   std::to_string(data->components) + " components (VEC3 required)");
  if (data->count != vertexCount)
    return R::fail(where + ": " + name + " delta accessor " + std::to_string(it->second) + " has " +
                   std::to_string(data->count) + " elements, POSITION has " + std::to_string(vertexCount));
  std::vector<glm::vec3> out(vertexCount);
  for (size_t i = 0; i < vertexCount; ++i) {
    out[i] = glm::vec3(data->values[3 * i], data->values[3 * i + 1], data->values[3 * i + 2]);
    if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y) || !std::isfinite(out[i].z))
      return R::fail(where + ": " + name + " delta of vertex " + std::to_string(i) + " is not finite");
  }
  return out;
}

}  // namespace

Status convertMorphTargets(const tinygltf::Model& m, const tinygltf::Primitive& prim, size_t vertexCount,
                           const std::string& where, Primitive& p, Scene& scene) {
  for (size_t t = 0; t < prim.targets.size(); ++t) {
    const auto& target = prim.targets[t];
    const std::string at = where + " target " + std::to_string(t);
    MorphTarget out;
    for (auto [name, stream] : {std::pair{"POSITION", &out.positions}, std::pair{"NORMAL", &out.normals},
                                std::pair{"TANGENT", &out.tangents}}) {
      auto d = targetDeltas(m, target, name, vertexCount, at);
      if (!d) return Status::fail(d.error());
      *stream = d.take();
    }
    for (const auto& [name, accessor] : target)
      if (name != "POSITION" && name != "NORMAL" && name != "TANGENT")
        scene.unsupported.push_back(at + ": " + name + " deltas ignored");
    p.targets.push_back(std::move(out));
  }
  return {};
}

Status convertMeshWeights(const tinygltf::Model& m, int index, Mesh& mesh) {
  const auto& src = m.meshes[size_t(index)];
  const size_t targets = morphTargetCount(mesh);
  for (const Primitive& p : mesh.primitives)
    if (p.patchPoints.empty() && p.targets.size() != targets)
      return Status::fail("mesh " + std::to_string(index) + ": primitives have " + std::to_string(targets) +
                          " and " + std::to_string(p.targets.size()) + " morph targets (glTF requires one count)");
  if (!src.weights.empty() && src.weights.size() != targets)
    return Status::fail("mesh " + std::to_string(index) + ": " + std::to_string(src.weights.size()) +
                        " weights for " + std::to_string(targets) + " morph targets");
  mesh.weights.assign(targets, 0.0f);
  for (size_t i = 0; i < src.weights.size(); ++i) {
    mesh.weights[i] = float(src.weights[i]);
    if (!std::isfinite(mesh.weights[i])) return Status::fail("mesh " + std::to_string(index) + ": weight is not finite");
  }
  return {};
}

void checkNodeWeights(Scene& scene) {
  for (size_t n = 0; n < scene.nodes.size(); ++n) {
    Node& node = scene.nodes[n];
    if (node.weights.empty()) continue;
    const size_t targets = node.mesh >= 0 ? morphTargetCount(scene.meshes[size_t(node.mesh)]) : 0;
    if (node.weights.size() == targets) continue;
    scene.unsupported.push_back("node " + std::to_string(n) + ": " + std::to_string(node.weights.size()) +
                                " morph weights for " + std::to_string(targets) + " targets ignored (mesh weights used)");
    node.weights.clear();
  }
}

}  // namespace mb
