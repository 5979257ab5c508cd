// The hostile-input catalogue: malformed and extreme glTF/GLB files, built in
// memory, each with what the loader must do with it:
//   Error     load fails; the message names the file and contains one of `reasons`
//   Fallback  load succeeds; LoadStats::*counter >= atLeast (the documented repair was counted)
//   Loads     load succeeds (extreme but valid input)
// and, whenever a scene loads, `check` (case specific) and checkSceneInvariants must pass.
// Shared by tests/scene/test_scene_hostile.cpp, tests/cli/test_cli_hostile_corpus.cpp and the fuzz
// seed generator; the cases themselves are compiled once, in hostile_cases.cpp.
#pragma once
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "pipelines/scene/scene.h"
#include "tests/hostile/gltf_builder.h"
#include "tests/hostile/scene_checks.h"
#include "tests/support/compressed_gltf.h"

namespace mb::hostile {

enum class Outcome { Error, Fallback, Loads };

struct Case {
  std::string file;  // file name, extension included (.glb or .gltf)
  Bytes bytes;
  std::vector<std::pair<std::string, Bytes>> sidecars;  // files written next to it
  Outcome outcome = Outcome::Error;
  std::vector<std::string> reasons;  // Error: the message contains one (case-insensitive)
  int LoadStats::*counter = nullptr;  // Fallback: this counter...
  int atLeast = 1;                    // ...is at least this
  std::function<std::string(const Scene&)> check;  // extra check on a loaded scene ("" = ok)
  std::string why;  // what is hostile, one line
  // Non-empty while the loader still fails this case (a finding awaiting its fix): the test is
  // skipped with this note unless MB_HOSTILE_STRICT=1. Empty once fixed.
  std::string pendingFix;
};

// ---------------------------------------------------------------------------------------------
// Base documents.

struct QuadIds {
  int pos = -1, nrm = -1, uv = -1, idx = -1;
};

inline std::vector<glm::vec3> quadPositions() {
  return {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
}

// A unit quad (4 vertices, 2 triangles) on node 0 of scene 0. Not finished: call finish().
inline QuadIds quad(Doc& d, bool normals = true, bool uv = true, int material = -1) {
  QuadIds q;
  q.pos = d.positions(quadPositions());
  if (normals) q.nrm = d.vec3(std::vector<glm::vec3>(4, {0, 0, 1}));
  if (uv) q.uv = d.vec2(std::vector<glm::vec2>{{0, 1}, {1, 1}, {1, 0}, {0, 0}});
  q.idx = d.indices16({0, 1, 2, 0, 2, 3});
  Json prim = {{"attributes", {{"POSITION", q.pos}}}, {"indices", q.idx}};
  if (normals) prim["attributes"]["NORMAL"] = q.nrm;
  if (uv) prim["attributes"]["TEXCOORD_0"] = q.uv;
  if (material >= 0) prim["material"] = material;
  d.mesh(prim);
  d.node({{"mesh", 0}, {"name", "quad"}});
  d.scene({0});
  return q;
}

// A normal-mapped material (base colour + normal texture from one embedded PNG).
inline int normalMappedMaterial(Doc& d) {
  int img = d.image(checkerPng());
  int tex = d.texture(img);
  return d.material({{"name", "normal-mapped"},
                     {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", tex}}}}},
                     {"normalTexture", {{"index", tex}}}});
}

// A skinned ribbon: node 0 carries the mesh and skin 0; nodes 1..J are the joints. `chain`:
// each joint is the child of the previous one (else all are children of joint 1).
// Vertex pair k is bound to joint min(k, J-1) and the next one, weights 0.5/0.5.
inline void skinnedRibbon(Doc& d, int jointCount, bool chain = true, bool animate = true) {
  const int J = jointCount;
  std::vector<glm::vec3> pos, nrm;
  std::vector<glm::u16vec4> jnt;
  std::vector<glm::vec4> wgt;
  std::vector<uint32_t> ix;
  for (int k = 0; k <= J; ++k) {
    for (int side = 0; side < 2; ++side) {
      pos.push_back({side ? 0.1f : -0.1f, 0.1f * float(k), 0});
      nrm.push_back({0, 0, 1});
      uint16_t a = uint16_t(std::min(k, J - 1)), b = uint16_t(std::min(k + 1, J - 1));
      jnt.push_back({a, b, 0, 0});
      wgt.push_back({0.5f, 0.5f, 0, 0});
    }
    if (k < J) {
      uint32_t v = uint32_t(2 * k);
      ix.insert(ix.end(), {v, v + 1, v + 3, v, v + 3, v + 2});
    }
  }
  Json prim = {{"attributes",
                {{"POSITION", d.positions(pos)}, {"NORMAL", d.vec3(nrm)}, {"JOINTS_0", d.joints(jnt)},
                 {"WEIGHTS_0", d.vec4(wgt)}}},
               {"indices", d.indices32(ix)}};
  int mesh = d.mesh(prim);
  std::vector<glm::mat4> ibm;
  std::vector<int> joints;
  d.node({{"mesh", mesh}, {"skin", 0}, {"name", "skinned"}});
  for (int k = 0; k < J; ++k) {
    Json n = {{"name", "joint" + std::to_string(k)}};
    const float y = chain ? (k ? 0.1f : 0.0f) : 0.1f * float(k);
    if (y != 0) n["translation"] = {0, y, 0};
    int id = d.node(n);
    joints.push_back(id);
    if (k > 0) {
      int parent = chain ? id - 1 : joints[0];
      d.j["nodes"][parent]["children"].push_back(id);
    }
    glm::mat4 inv(1.0f);
    inv[3][1] = -0.1f * float(k);
    ibm.push_back(inv);
  }
  d.arr("skins").push_back({{"joints", joints}, {"inverseBindMatrices", d.mat4(ibm)}, {"skeleton", joints[0]}});
  d.scene({0, joints[0]});
  if (animate) {
    int in = d.scalars({0.0f, 1.0f});
    int out = d.vec4(std::vector<glm::vec4>{{0, 0, 0, 1}, {0, 0, 0.3826834f, 0.9238795f}});
    d.arr("animations").push_back({{"name", "bend"},
                                   {"samplers", {{{"input", in}, {"output", out}}}},
                                   {"channels", {{{"sampler", 0}, {"target", {{"node", joints[J > 1 ? 1 : 0]}, {"path", "rotation"}}}}}}});
  }
}

// A document with a bit of everything the loader handles: embedded PNG textures, a normal-mapped
// material without TANGENT, a skinned ribbon with LINEAR / STEP / CUBICSPLINE channels, a sparse
// accessor, uint8 indices, a camera, a matrix-authored node. Used as the source for truncation
// series and as a fuzz seed.
inline Doc richDoc() {
  Doc d;
  skinnedRibbon(d, 3);
  int mat = normalMappedMaterial(d);
  d.j["meshes"][0]["primitives"][0]["material"] = mat;
  d.j["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] =
      d.vec2(std::vector<glm::vec2>{{0, 0}, {1, 0}, {0, 0.3f}, {1, 0.3f}, {0, 0.6f}, {1, 0.6f}, {0, 1}, {1, 1}});
  d.arr("samplers").push_back({{"magFilter", 9728}, {"minFilter", 9728}, {"wrapS", 33071}, {"wrapT", 33648}});
  d.j["textures"][0]["sampler"] = 0;
  // Second mesh: a triangle with uint8 indices and sparse-substituted positions.
  std::vector<glm::vec3> tri = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  int pos = d.positions(tri);
  std::vector<uint8_t> sparseIdx = {2, 0, 0, 0};
  std::vector<glm::vec3> sparseVal = {{0, 2, 0}};
  int siv = d.view(sparseIdx.data(), 1);
  int svv = d.view(sparseVal.data(), 12);
  d.j["accessors"][pos]["sparse"] = {{"count", 1},
                                     {"indices", {{"bufferView", siv}, {"componentType", kUByte}}},
                                     {"values", {{"bufferView", svv}}}};
  d.j["accessors"][pos]["max"] = {1, 2, 0};
  std::vector<uint8_t> ix8 = {0, 1, 2, 0};
  int ibv = d.view(ix8.data(), 3);
  int ia = d.accessor(ibv, kUByte, 3, "SCALAR");
  int m2 = d.mesh({{"attributes", {{"POSITION", pos}}}, {"indices", ia}});
  int n2 = d.node({{"mesh", m2}, {"name", "matrix-node"},
                   {"matrix", {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 1, 0, 0, 1}}});
  d.arr("cameras").push_back({{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.1}, {"zfar", 50}}}});
  int cn = d.node({{"camera", 0}, {"translation", {0, 0.2, 3}}});
  d.j["scenes"][0]["nodes"].push_back(n2);
  d.j["scenes"][0]["nodes"].push_back(cn);
  // More channels: STEP scale on node n2, CUBICSPLINE translation on the camera node.
  int in = d.scalars({0.0f, 0.5f, 1.0f});
  int sc = d.vec3(std::vector<glm::vec3>{{1, 1, 1}, {1.5f, 1.5f, 1.5f}, {1, 1, 1}});
  int cs = d.vec3(std::vector<glm::vec3>{{0, 0, 0}, {0, 0.2f, 3}, {0, 0, 0},
                                         {0, 0, 0}, {0.5f, 0.2f, 3}, {0, 0, 0},
                                         {0, 0, 0}, {0, 0.2f, 3}, {0, 0, 0}});
  auto& anim = d.j["animations"][0];
  anim["samplers"].push_back({{"input", in}, {"output", sc}, {"interpolation", "STEP"}});
  anim["samplers"].push_back({{"input", in}, {"output", cs}, {"interpolation", "CUBICSPLINE"}});
  anim["channels"].push_back({{"sampler", 1}, {"target", {{"node", n2}, {"path", "scale"}}}});
  anim["channels"].push_back({{"sampler", 2}, {"target", {{"node", cn}, {"path", "translation"}}}});
  d.finish();
  return d;
}

// ---------------------------------------------------------------------------------------------
// Checks used by several cases.

inline std::function<std::string(const Scene&)> nodeScaleIs(int node, glm::vec3 s) {
  return [=](const Scene& sc) -> std::string {
    if (node >= int(sc.nodes.size())) return "node missing";
    glm::vec3 got = sc.nodes[size_t(node)].local.scale;
    if (glm::length(got - s) > 1e-5f) return "scale not as authored";
    return "";
  };
}

// The local TRS of `node` recomposes the authored matrix (unless the loader flagged shear).
inline std::function<std::string(const Scene&)> trsMatchesMatrix(int node) {
  return [=](const Scene& sc) -> std::string {
    const Node& n = sc.nodes.at(size_t(node));
    if (!n.hasMatrix) return "hasMatrix not set";
    if (n.matrixHasShear) return "";
    glm::mat4 r = glm::mat4_cast(n.local.rotation);
    glm::mat4 m(1.0f);
    for (int c = 0; c < 3; ++c) m[c] = r[c] * n.local.scale[c];
    m[3] = glm::vec4(n.local.translation, 1.0f);
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 4; ++k)
        if (std::abs(m[c][k] - n.matrix[c][k]) > 1e-4f) return "TRS decomposed from the matrix does not recompose it";
    return "";
  };
}

inline std::function<std::string(const Scene&)> positionsEqual(std::vector<glm::vec3> want) {
  return [=](const Scene& sc) -> std::string {
    if (sc.meshes.empty() || sc.meshes[0].primitives.empty()) return "no primitive";
    const auto& got = sc.meshes[0].primitives[0].positions;
    if (got.size() != want.size()) return "wrong vertex count";
    for (size_t i = 0; i < got.size(); ++i)
      if (glm::length(got[i] - want[i]) > 1e-6f) return "position " + std::to_string(i) + " differs from the file";
    return "";
  };
}

// Scene::unsupported has a line containing `needle` ("" = any line).
inline std::function<std::string(const Scene&)> listsUnsupported(std::string needle, std::string what) {
  return [=](const Scene& sc) -> std::string {
    for (const auto& u : sc.unsupported)
      if (u.find(needle) != std::string::npos) return "";
    return what + " not listed in Scene::unsupported";
  };
}

inline std::function<std::string(const Scene&)> hasTangents() {
  return [](const Scene& sc) -> std::string {
    for (const Mesh& m : sc.meshes)
      for (const Primitive& p : m.primitives)
        if (p.tangents.size() != p.positions.size()) return "normal-mapped primitive without tangents";
    return "";
  };
}

// ---------------------------------------------------------------------------------------------
// The catalogue.

namespace detail {

inline Case error(std::string file, Bytes bytes, std::vector<std::string> reasons, std::string why) {
  Case c;
  c.file = std::move(file);
  c.bytes = std::move(bytes);
  c.outcome = Outcome::Error;
  c.reasons = std::move(reasons);
  c.why = std::move(why);
  return c;
}
inline Case fallback(std::string file, Bytes bytes, int LoadStats::*counter, int atLeast, std::string why) {
  Case c;
  c.file = std::move(file);
  c.bytes = std::move(bytes);
  c.outcome = Outcome::Fallback;
  c.counter = counter;
  c.atLeast = atLeast;
  c.why = std::move(why);
  return c;
}
// An image that cannot be decoded (corrupt, oversized, missing file) does not fail the load: it
// is replaced by 1x1 white, counted in LoadStats::imagesNotDecoded and listed in unsupported.
// `reasons` must then appear in that unsupported line.
inline Case imageFallback(std::string file, Bytes bytes, std::vector<std::string> reasons, std::string why) {
  Case c = fallback(std::move(file), std::move(bytes), &LoadStats::imagesNotDecoded, 1, std::move(why) + ": replaced, counted");
  c.check = [reasons](const Scene& s) -> std::string {
    for (const auto& u : s.unsupported)
      for (const auto& r : reasons)
        if (u.find(r) != std::string::npos) return "";
    return "undecoded image not listed in Scene::unsupported with its reason";
  };
  return c;
}
inline Case loads(std::string file, Bytes bytes, std::string why) {
  Case c;
  c.file = std::move(file);
  c.bytes = std::move(bytes);
  c.outcome = Outcome::Loads;
  c.why = std::move(why);
  return c;
}

// A finished quad document modified by `edit` (which may mutate JSON or bytes).
inline Doc quadDoc(const std::function<void(Doc&, QuadIds&)>& edit = {}, bool normals = true, bool uv = true) {
  Doc d;
  QuadIds q = quad(d, normals, uv);
  if (edit) edit(d, q);
  d.finish();
  return d;
}

template <class T>
inline void pokeBin(Doc& d, int accessor, size_t element, int component, T value) {
  const Json& a = d.j["accessors"][accessor];
  const Json& v = d.j["bufferViews"][a["bufferView"].get<int>()];
  size_t off = v["byteOffset"].get<size_t>() + a.value("byteOffset", size_t(0));
  size_t comps = a["type"] == "SCALAR" ? 1 : a["type"] == "VEC2" ? 2 : a["type"] == "VEC3" ? 3 : 4;
  off += (element * comps + size_t(component)) * sizeof(T);
  std::memcpy(d.bin.data() + off, &value, sizeof(T));
}

}  // namespace detail

// The catalogue, by kind (hostile_cases.cpp: compiled once, not in every file that includes this).
std::vector<Case> containerCases();
std::vector<Case> jsonCases();
std::vector<Case> accessorCases();
std::vector<Case> numericCases();
std::vector<Case> graphCases();
std::vector<Case> contentCases();
std::vector<Case> conformanceCases();
std::vector<Case> compressionCases();
std::vector<Case> instancingCases();
std::vector<Case> allCases();

// ---------------------------------------------------------------------------------------------
// Truncation series of a valid .glb: cut at every 1/64 of its size and at each header/chunk
// boundary (+-1). `fixLengths`: also patch the GLB header and chunk lengths so the container
// is consistent and the cut reaches the JSON parser / buffer checks.
struct Truncation {
  std::string file;
  Bytes bytes;
};

inline std::vector<Truncation> truncations(const std::string& stem, const Bytes& glb) {
  std::vector<size_t> cuts = {0, 1, 4, 8, 11, 12, 16, 19, 20, 21};
  const GlbLayout L = glbLayout(glb);
  for (size_t c : {L.jsonEnd - 1, L.jsonEnd, L.jsonEnd + 4, L.jsonEnd + 8, L.jsonEnd + 9, glb.size() - 1}) cuts.push_back(c);
  for (size_t k = 1; k < 64; ++k) cuts.push_back(glb.size() * k / 64);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  std::vector<Truncation> out;
  for (size_t c : cuts) {
    if (c >= glb.size()) continue;
    Bytes b(glb.begin(), glb.begin() + long(c));
    out.push_back({stem + "_cut" + std::to_string(c) + ".glb", b});
    // Same cut, lengths patched to match (only where a consistent header is possible).
    if (c >= 24) {
      Bytes f = b;
      f.resize(c & ~size_t(3));
      put32(f, 8, uint32_t(f.size()));
      if (f.size() <= L.jsonEnd) {
        put32(f, 12, uint32_t(f.size() - 20));
      } else if (L.hasBin && f.size() >= L.binStart + 4) {
        put32(f, L.binHeader, uint32_t(f.size() - L.binStart));
      } else {
        f.resize(L.jsonEnd);
        put32(f, 8, uint32_t(f.size()));
      }
      out.push_back({stem + "_cut" + std::to_string(c) + "_fixed.glb", f});
    }
  }
  return out;
}

}  // namespace mb::hostile
