// Mesh conversion: attributes -> tight streams, indices -> triangle list, then hygiene.
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "pipelines/scene/gltf/accessors.h"
#include "pipelines/scene/drawable.h"
#include "pipelines/scene/repair/flat_normals.h"
#include "pipelines/scene/gltf/gltf_convert.h"
#include "pipelines/scene/repair/hygiene.h"
#include "pipelines/scene/repair/skin_weights.h"
#include "pipelines/scene/repair/tangents.h"

namespace mb {
namespace {

constexpr int kTriangles = 4, kStrip = 5, kFan = 6;

// "mode 1 (lines)": the glTF name of a primitive mode that is not drawn.
std::string modeName(int mode) {
  static const char* names[] = {"points", "lines", "line loop", "line strip"};
  return "mode " + std::to_string(mode) + " (" + (mode >= 0 && mode < 4 ? names[mode] : "unknown") + ")";
}

// Reads attribute `name` when present; checks component count (any of `allowed`) and count.
Result<AccessorData<float>> attribute(const tinygltf::Model& m, const tinygltf::Primitive& prim,
                                      const std::string& name, std::initializer_list<int> allowed,
                                      size_t vertexCount) {
  using R = Result<AccessorData<float>>;
  auto it = prim.attributes.find(name);
  if (it == prim.attributes.end()) return AccessorData<float>{};
  auto data = readAccessorFloat(m, it->second, name);
  if (!data) return data;
  if (std::find(allowed.begin(), allowed.end(), data->components) == allowed.end())
    return R::fail("accessor " + std::to_string(it->second) + " (" + name + ") has " +
                   std::to_string(data->components) + " components");
  if (vertexCount != size_t(-1) && data->count != vertexCount)
    return R::fail("accessor " + std::to_string(it->second) + " (" + name + ") has " +
                   std::to_string(data->count) + " elements, POSITION has " +
                   std::to_string(vertexCount));
  return data;
}

template <class V>
std::vector<V> unpack(const AccessorData<float>& a, float fill) {
  std::vector<V> out(a.count, V(fill));
  for (size_t i = 0; i < a.count; ++i)
    for (int c = 0; c < std::min(a.components, int(V::length())); ++c)
      out[i][c] = a.values[i * size_t(a.components) + size_t(c)];
  return out;
}

// Strip/fan -> list following the glTF 2.0 vertex order rules for each mode.
std::vector<uint32_t> toTriangleList(const std::vector<uint32_t>& idx, int mode) {
  std::vector<uint32_t> out;
  if (idx.size() < 3) return out;
  out.reserve((idx.size() - 2) * 3);
  for (size_t i = 0; i + 2 < idx.size(); ++i) {
    if (mode == kStrip) {
      out.insert(out.end(), {idx[i], idx[i + 1 + i % 2], idx[i + 2 - i % 2]});
    } else {
      out.insert(out.end(), {idx[i + 1], idx[i + 2], idx[0]});
    }
  }
  return out;
}

// JOINTS_n/WEIGHTS_n sets -> 4 influences per vertex.
Status skinInfluences(const tinygltf::Model& m, const tinygltf::Primitive& prim, size_t nv,
                      uint32_t jointCount, Primitive& p, LoadStats& stats) {
  std::vector<AccessorData<uint32_t>> js;
  std::vector<AccessorData<float>> ws;
  for (int set = 0;; ++set) {
    auto ji = prim.attributes.find("JOINTS_" + std::to_string(set));
    auto wi = prim.attributes.find("WEIGHTS_" + std::to_string(set));
    if (ji == prim.attributes.end() || wi == prim.attributes.end()) break;
    auto j = readAccessorUint(m, ji->second, ji->first);
    if (!j) return Status::fail(j.error());
    auto w = attribute(m, prim, wi->first, {4}, nv);
    if (!w) return Status::fail(w.error());
    if (j->components != 4 || j->count != nv)
      return Status::fail("accessor " + std::to_string(ji->second) + " (" + ji->first +
                          ") must be VEC4 with one element per vertex");
    js.push_back(j.take());
    ws.push_back(w.take());
  }
  if (js.empty()) return {};
  p.joints.resize(nv);
  p.weights.resize(nv);
  std::vector<uint32_t> jv(4 * js.size());
  std::vector<float> wv(4 * js.size());
  for (size_t v = 0; v < nv; ++v) {
    for (size_t s = 0; s < js.size(); ++s)
      for (size_t c = 0; c < 4; ++c) {
        jv[4 * s + c] = js[s].values[4 * v + c];
        wv[4 * s + c] = ws[s].values[4 * v + c];
      }
    InfluenceReport r;
    reduceInfluences(jv.data(), wv.data(), int(jv.size()), jointCount, &p.joints[v], &p.weights[v], &r);
    stats.weightsRenormalised += r.renormalised;
    stats.weightsZeroSum += r.zeroSum;
    stats.influencesTruncated += r.truncated;
    stats.jointsOutOfRange += r.jointsOutOfRange;
  }
  return {};
}

// Where a message points: "mesh 2 primitive 0".
struct PrimitiveSource {
  const tinygltf::Primitive& prim;
  std::string where;
};

// POSITION and the optional attributes (NORMAL, TANGENT, TEXCOORD_0/1, COLOR_0) unpacked into
// `p`, each checked against POSITION's count; attributes not drawn are named in the scene.
// Returns the vertex count.
Result<size_t> readVertexAttributes(const tinygltf::Model& m, const PrimitiveSource& src, Primitive& p, Scene& scene) {
  using R = Result<size_t>;
  const tinygltf::Primitive& prim = src.prim;
  auto pos = attribute(m, prim, "POSITION", {3}, size_t(-1));
  if (!pos) return R::fail(pos.error());
  size_t nv = pos->count;
  p.positions = unpack<glm::vec3>(*pos, 0.0f);
  auto nrm = attribute(m, prim, "NORMAL", {3}, nv);
  auto tan = attribute(m, prim, "TANGENT", {4}, nv);
  auto uv0 = attribute(m, prim, "TEXCOORD_0", {2}, nv);
  auto uv1 = attribute(m, prim, "TEXCOORD_1", {2}, nv);
  auto col = attribute(m, prim, "COLOR_0", {3, 4}, nv);
  for (auto* a : {&nrm, &tan, &uv0, &uv1, &col})
    if (!*a) return R::fail(a->error());
  // No repair is defined for these (normals, tangents and weights have theirs): a NaN or Inf
  // would sample textures / shade with undefined values.
  for (auto [a, name] : {std::pair{&uv0, "TEXCOORD_0"}, std::pair{&uv1, "TEXCOORD_1"}, std::pair{&col, "COLOR_0"}})
    for (float v : (*a)->values)
      if (!std::isfinite(v)) return R::fail(src.where + ": " + name + " has a non-finite value");
  p.normals = unpack<glm::vec3>(*nrm, 0.0f);
  p.tangents = unpack<glm::vec4>(*tan, 0.0f);
  p.uv0 = unpack<glm::vec2>(*uv0, 0.0f);
  p.uv1 = unpack<glm::vec2>(*uv1, 0.0f);
  p.colors = unpack<glm::vec4>(*col, 1.0f);
  p.hadTangents = !p.tangents.empty();
  for (const auto& [name, acc] : prim.attributes) {
    bool known = name == "POSITION" || name == "NORMAL" || name == "TANGENT" ||
                 name == "TEXCOORD_0" || name == "TEXCOORD_1" || name == "COLOR_0" ||
                 name.rfind("JOINTS_", 0) == 0 || name.rfind("WEIGHTS_", 0) == 0;
    if (!known) scene.unsupported.push_back(src.where + ": attribute " + name + " ignored");
  }
  return nv;
}

// The indices (or 0..nv-1 without an accessor), each in range, as a triangle list: strips and
// fans converted, trailing indices of no whole triangle dropped and named.
Status readIndices(const tinygltf::Model& m, const PrimitiveSource& src, size_t nv, Primitive& p, Scene& scene) {
  const tinygltf::Primitive& prim = src.prim;
  if (prim.indices >= 0) {
    auto idx = readAccessorUint(m, prim.indices, "indices");
    if (!idx) return Status::fail(idx.error());
    if (idx->components != 1) return Status::fail("accessor " + std::to_string(prim.indices) + " (indices) is not SCALAR");
    for (uint32_t i : idx->values)
      if (i >= nv)
        return Status::fail(src.where + ": index " + std::to_string(i) + " out of range (" + std::to_string(nv) +
                            " vertices)");
    p.indices = std::move(idx->values);
  } else {
    p.indices.resize(nv);
    for (size_t i = 0; i < nv; ++i) p.indices[i] = uint32_t(i);
  }
  if (prim.mode == kStrip || prim.mode == kFan) {
    p.indices = toTriangleList(p.indices, prim.mode);
    ++scene.stats.stripsFansConverted;
  }
  if (p.indices.size() % 3) {
    scene.unsupported.push_back(src.where + ": " + std::to_string(p.indices.size() % 3) +
                                " trailing indices ignored (not a whole triangle)");
    p.indices.resize(p.indices.size() - p.indices.size() % 3);
  }
  return {};
}

// Tangents for a primitive without TANGENT whose material has a normal map: generated from its
// uv set, or arbitrary ones (named) when that set is absent.
void completeTangents(Primitive& p, const std::string& where, Scene& scene) {
  const Material* mat = p.material >= 0 ? &scene.materials[size_t(p.material)] : nullptr;
  if (!mat || mat->normal.texture < 0) return;
  int set = mat->normal.texCoord;
  if (set > 1 || (set == 1 ? p.uv1 : p.uv0).empty()) {
    scene.unsupported.push_back(where + ": normal map uses absent TEXCOORD_" + std::to_string(set) +
                                " (arbitrary tangents used)");
    p.tangents.resize(p.positions.size());
    for (size_t i = 0; i < p.tangents.size(); ++i) p.tangents[i] = glm::vec4(fallbackTangent(p.normals[i]), 1.0f);
    scene.stats.badTangentsReplaced += int(p.tangents.size());
  } else {
    generateTangents(p, set, scene.stats);
  }
  ++scene.stats.tangentsGenerated;
}

// Hygiene, in dependency order: positions -> normals -> tangents (each repair counted).
void repairPrimitive(Primitive& p, const std::string& where, Scene& scene) {
  scene.stats.nonFinitePositions += fixPositions(p.positions);
  if (!p.indices.empty() && !hasAreaAtRest(p)) {  // kept (a skin or morph may give it area), named
    ++scene.stats.zeroAreaPrimitives;
    scene.unsupported.push_back(where + ": all " + std::to_string(p.indices.size() / 3) +
                                " triangles have zero area (nothing drawn at rest)");
  }
  if (p.normals.empty()) {
    generateFlatNormals(p);
    ++scene.stats.flatNormalsGenerated;
  }
  fixNormals(p, scene.stats);
  if (p.hadTangents) fixTangents(p, scene.stats);
  else completeTangents(p, where, scene);
}

// One triangle primitive (a Bezier patch primitive: convertPatchPrimitive): its attributes,
// skin influences, morph targets and indices read, then repaired. Empty when it is skipped
// (not triangles, or no POSITION: named and counted in the scene).
Result<std::optional<Primitive>> convertPrimitive(const tinygltf::Model& m, int index, size_t pi, uint32_t jointCount,
                                                  Scene& scene) {
  using R = Result<std::optional<Primitive>>;
  const PrimitiveSource src{m.meshes[size_t(index)].primitives[pi], "mesh " + std::to_string(index) + " primitive " +
                                                                        std::to_string(pi)};
  const tinygltf::Primitive& prim = src.prim;
  const std::string& where = src.where;
  auto skip = [&](const std::string& why) -> R {
    scene.unsupported.push_back(where + ": " + why + " (primitive skipped)");
    scene.skipped.push_back({index, int(pi), why});
    ++scene.stats.skippedPrimitives;
    return std::optional<Primitive>{};
  };
  if (prim.extensions.count(kBezierPatchesExtension)) {
    auto patches = convertPatchPrimitive(m, prim, int(scene.materials.size()));
    if (!patches) return R::fail(where + ": " + patches.error());
    return std::optional<Primitive>{patches.take()};
  }
  if (prim.mode != kTriangles && prim.mode != kStrip && prim.mode != kFan && prim.mode != -1)
    return skip(modeName(prim.mode) + " not supported");
  // KHR_draco_mesh_compression was decoded into the accessors (draco_decode.cpp).
  for (const auto& [ext, v] : prim.extensions)
    if (ext != "KHR_draco_mesh_compression") scene.unsupported.push_back(where + ": extension " + ext + " ignored");
  if (!prim.attributes.count("POSITION")) return skip("no POSITION");
  if (prim.indices < -1) return R::fail(where + ": indices accessor " + std::to_string(prim.indices) + " does not exist");
  if (prim.material >= int(scene.materials.size()) || prim.material < -1)
    return R::fail(where + ": material " + std::to_string(prim.material) + " does not exist");

  Primitive p;
  p.material = prim.material;
  auto nv = readVertexAttributes(m, src, p, scene);
  if (!nv) return R::fail(nv.error());
  if (Status s = skinInfluences(m, prim, *nv, jointCount, p, scene.stats); !s) return R::fail(s.error());
  if (Status s = convertMorphTargets(m, prim, *nv, where, p, scene); !s) return R::fail(s.error());
  if (Status s = readIndices(m, src, *nv, p, scene); !s) return R::fail(s.error());
  repairPrimitive(p, where, scene);
  return std::optional<Primitive>{std::move(p)};
}

}  // namespace

Result<Mesh> convertMesh(const tinygltf::Model& m, int index, uint32_t jointCount, Scene& scene) {
  using R = Result<Mesh>;
  const auto& src = m.meshes[size_t(index)];
  Mesh mesh;
  mesh.name = src.name;
  for (size_t pi = 0; pi < src.primitives.size(); ++pi) {
    auto p = convertPrimitive(m, index, pi, jointCount, scene);
    if (!p) return R::fail(p.error());
    if (*p) mesh.primitives.push_back(std::move(**p));
  }
  if (Status s = convertMeshWeights(m, index, mesh); !s) return R::fail(s.error());
  return mesh;
}

}  // namespace mb
