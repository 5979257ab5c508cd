// EXT_mesh_gpu_instancing: a node's per-instance TRANSLATION / ROTATION / SCALE accessors ->
// Node::instances (world of instance i = node world * instance TRS i). Accessor types as the
// extension allows them (KHR_mesh_quantization widens TRANSLATION and SCALE to integers);
// counts must agree; values must be finite. Nodes that cannot draw instanced (skinned, Bezier
// patches) are drawn once: instancing.h dropUndrawableInstances, called after the meshes.
#include <tiny_gltf.h>

#include <cmath>
#include <string>

#include "pipelines/scene/gltf/accessors.h"
#include "pipelines/scene/gltf/gltf_convert.h"

namespace mb {
namespace {

bool integerType(int c) {
  return c == TINYGLTF_COMPONENT_TYPE_BYTE || c == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
         c == TINYGLTF_COMPONENT_TYPE_SHORT || c == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
}

// The accessor of one instancing attribute, its type checked, decoded as floats.
Result<AccessorData<float>> readInstanceAttribute(const tinygltf::Model& m, int accessor,
                                                  const std::string& name, const std::string& where) {
  using R = Result<AccessorData<float>>;
  if (accessor < 0 || size_t(accessor) >= m.accessors.size())
    return R::fail(where + ": " + name + " accessor " + std::to_string(accessor) + " does not exist");
  const tinygltf::Accessor& a = m.accessors[size_t(accessor)];
  const bool rotation = name == "ROTATION";
  const int wantType = rotation ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3;
  const int c = a.componentType;
  // ROTATION: float or normalized signed byte/short; TRANSLATION/SCALE: float, or (quantized)
  // byte/short.
  const bool typeOk = c == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                      (rotation ? a.normalized && (c == TINYGLTF_COMPONENT_TYPE_BYTE || c == TINYGLTF_COMPONENT_TYPE_SHORT)
                                : integerType(c));
  if (a.type != wantType || !typeOk)
    return R::fail(where + ": " + name + " accessor " + std::to_string(accessor) + " must be " +
                   (rotation ? "VEC4 float or normalized byte/short" : "VEC3 float (or byte/short, KHR_mesh_quantization)"));
  auto data = readAccessorFloat(m, accessor, "instance " + name);
  if (!data) return R::fail(where + ": " + data.error());
  for (float v : data->values)
    if (!std::isfinite(v)) return R::fail(where + ": " + name + " accessor " + std::to_string(accessor) + " has a non-finite value");
  return data;
}

}  // namespace

Status convertInstancing(const tinygltf::Model& m, size_t nodeIndex, Scene& scene) {
  const auto found = m.nodes[nodeIndex].extensions.find(kInstancingExtension);
  if (found == m.nodes[nodeIndex].extensions.end()) return {};
  const std::string where = "node " + std::to_string(nodeIndex) + ": " + kInstancingExtension;
  Node& node = scene.nodes[nodeIndex];
  const tinygltf::Value& ext = found->second;
  const tinygltf::Value attributes = ext.Get("attributes");
  const std::string none = where + ": no attributes (TRANSLATION, ROTATION or SCALE)";
  if (!ext.IsObject() || !attributes.IsObject()) return Status::fail(none);  // {} parses as null
  static const char* kNames[3] = {"TRANSLATION", "ROTATION", "SCALE"};
  AccessorData<float> values[3];
  size_t count = 0;
  bool any = false;
  for (int k = 0; k < 3; ++k) {
    const tinygltf::Value v = attributes.Get(kNames[k]);
    if (!attributes.Has(kNames[k])) continue;
    const double index = v.IsInt() ? double(v.Get<int>()) : v.IsNumber() ? v.Get<double>() : -1.0;
    if (!(index >= 0.0 && index == std::floor(index) && index < 2147483647.0))
      return Status::fail(where + ": " + kNames[k] + " is not an accessor index");
    auto data = readInstanceAttribute(m, int(index), kNames[k], where);
    if (!data) return Status::fail(data.error());
    if (any && data->count != count)
      return Status::fail(where + ": " + kNames[k] + " has " + std::to_string(data->count) +
                          " instances, an earlier attribute " + std::to_string(count) + " (counts must agree)");
    count = data->count;
    any = true;
    values[k] = data.take();
  }
  if (!any) return Status::fail(none);
  if (node.mesh < 0) {
    scene.unsupported.push_back(where + " on a node without a mesh: ignored");
    return {};
  }
  node.instances.assign(count, TRS{});
  for (size_t i = 0; i < count; ++i) {
    TRS& t = node.instances[i];
    const float* tv = values[0].values.empty() ? nullptr : &values[0].values[3 * i];
    const float* rv = values[1].values.empty() ? nullptr : &values[1].values[4 * i];
    const float* sv = values[2].values.empty() ? nullptr : &values[2].values[3 * i];
    if (tv) t.translation = glm::vec3(tv[0], tv[1], tv[2]);
    if (sv) t.scale = glm::vec3(sv[0], sv[1], sv[2]);
    if (rv) {
      glm::quat q(rv[3], rv[0], rv[1], rv[2]);
      const float len = glm::length(q);
      if (!(std::fabs(len - 1.0f) <= kUnitQuaternionTolerance)) ++scene.stats.instanceRotationsNormalised;
      t.rotation = len > 0.0f && std::isfinite(len) ? q / len : glm::quat(1, 0, 0, 0);
    }
  }
  return {};
}

}  // namespace mb
