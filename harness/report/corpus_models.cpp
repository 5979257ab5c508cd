#include "harness/report/corpus_models.h"

#include <algorithm>
#include <cstdio>
#include <map>

namespace mb::report {

const char* const kSameModelDefinition =
    "two files are the same model when their content hashes (FNV-1a 64) are equal. A file with meshes hashes its "
    "mesh content alone: every primitive's decoded attribute streams (position, normal, tangent, uv0, uv1, colour, "
    "joints, weights, morph-target deltas; normals and tangents the loader generated left out) and its triangle "
    "indices, meshes and primitives in file order, so buffer layout, component types, file name, generator, "
    "materials, nodes and animations do not matter. A file without a drawable primitive (../shared/corpus-graph "
    "strips the meshes) and with a skin or an animation hashes what is there: the nodes in file order (parent, "
    "children, TRS or the authored matrix, skin, camera; not their names), the skins (joints, skeleton, inverse "
    "bind matrices) and the animation channels (target node and path, interpolation, input and output data) in "
    "file order, so variants of one character (one rig, the same clips, other meshes) are one model. A file "
    "without a hash is a model of its own: a graph-only file with neither skin nor animation (its nodes alone "
    "cannot tell two models apart: a single identity node is most static scenes), a failed load, or an inspect "
    "JSON older than the hash. Each statistic counts the first file (by path) of each group";

namespace {

using json = nlohmann::json;

// FNV-1a 64 over tagged, length-prefixed streams, so that streams of other lengths or in other
// fields cannot produce the same byte sequence.
class Hasher {
 public:
  void bytes(const void* data, size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < n; ++i) h_ = (h_ ^ p[i]) * 1099511628211ull;
  }
  void tag(const std::string& s) { value(uint64_t(s.size())), bytes(s.data(), s.size()); }
  template <typename T>
  void value(const T& v) { bytes(&v, sizeof v); }
  template <typename T>
  void stream(const char* name, const std::vector<T>& v) {
    tag(name);
    value(uint64_t(v.size()));
    if (!v.empty()) bytes(v.data(), v.size() * sizeof(T));
  }
  std::string hex() const {
    char b[20];
    std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h_));
    return b;
  }

 private:
  uint64_t h_ = 1469598103934665603ull;
};

bool hasDrawablePrimitive(const Scene& scene) {
  for (const Mesh& m : scene.meshes)
    for (const Primitive& p : m.primitives)
      if (!p.positions.empty() || !p.patchPoints.empty()) return true;
  return false;
}

void hashMeshes(const Scene& scene, Hasher& h) {
  h.tag("meshes");
  h.value(uint64_t(scene.meshes.size()));
  for (const Mesh& m : scene.meshes) {
    h.value(uint64_t(m.primitives.size()));
    for (const Primitive& p : m.primitives) {
      h.stream("position", p.positions);
      if (!p.generatedNormals) h.stream("normal", p.normals);
      if (!p.generatedTangents) h.stream("tangent", p.tangents);
      h.stream("uv0", p.uv0);
      h.stream("uv1", p.uv1);
      h.stream("colour", p.colors);
      h.stream("joints", p.joints);
      h.stream("weights", p.weights);
      h.stream("indices", p.indices);
      h.stream("patch", p.patchPoints);
      h.value(uint64_t(p.targets.size()));
      for (const MorphTarget& t : p.targets) {
        h.stream("target position", t.positions);
        h.stream("target normal", t.normals);
        h.stream("target tangent", t.tangents);
      }
    }
  }
}

void hashGraph(const Scene& scene, Hasher& h) {
  h.tag("graph");
  h.value(uint64_t(scene.nodes.size()));
  for (const Node& n : scene.nodes) {
    h.value(n.parent);
    h.stream("children", n.children);
    h.value(n.hasMatrix);
    if (n.hasMatrix) h.value(n.matrix);
    else h.value(n.local.translation), h.value(n.local.rotation), h.value(n.local.scale);
    h.value(n.skin);
    h.value(n.camera);
  }
  h.value(uint64_t(scene.skins.size()));
  for (const Skin& s : scene.skins) {
    h.stream("joints", s.joints);
    h.value(s.skeleton);
    h.stream("inverse bind", s.inverseBind);
  }
  h.value(uint64_t(scene.animations.size()));
  for (const Animation& a : scene.animations) {
    h.value(uint64_t(a.channels.size()));
    for (const Channel& c : a.channels) {
      h.value(c.node), h.value(c.path), h.value(c.interpolation);
      h.stream("input", c.times);
      h.stream("output", c.values);
    }
  }
}

}  // namespace

std::string contentHash(const Scene& scene) {
  Hasher h;
  if (hasDrawablePrimitive(scene)) hashMeshes(scene, h);
  else if (!scene.skins.empty() || !scene.animations.empty()) hashGraph(scene, h);
  else return "";  // a static graph without meshes identifies no model
  return h.hex();
}

DistinctModels distinctModels(const json& files) {
  DistinctModels m;
  m.files = int(files.size());
  std::map<std::string, std::vector<size_t>> groups;  // hash -> files
  std::vector<size_t> alone;
  for (size_t i = 0; i < files.size(); ++i) {
    const json& hash = files[i].value("contentHash", json());
    if (hash.is_string() && !hash.get<std::string>().empty()) groups[hash.get<std::string>()].push_back(i);
    else alone.push_back(i), ++m.withoutHash;
  }
  const auto path = [&](size_t i) { return files[i].value("file", std::string()); };
  m.representatives = alone;
  for (auto& [hash, members] : groups) {
    std::sort(members.begin(), members.end(), [&](size_t a, size_t b) { return path(a) < path(b) || (path(a) == path(b) && a < b); });
    m.representatives.push_back(members.front());
    if (members.size() < 2) continue;
    std::vector<std::string> names;
    for (size_t i : members) names.push_back(path(i));
    m.duplicateGroups.push_back(names);
  }
  std::sort(m.representatives.begin(), m.representatives.end());
  std::stable_sort(m.duplicateGroups.begin(), m.duplicateGroups.end(), [](const auto& a, const auto& b) {
    return a.size() != b.size() ? a.size() > b.size() : a.front() < b.front();
  });
  return m;
}

json toJson(const DistinctModels& m, size_t listed) {
  int inGroups = 0;
  for (const auto& g : m.duplicateGroups) inGroups += int(g.size());
  json largest = json::array();
  for (size_t i = 0; i < m.duplicateGroups.size() && i < listed; ++i) largest.push_back(m.duplicateGroups[i]);
  return {{"files", m.files},
          {"distinctModels", m.representatives.size()},
          {"filesWithoutContentHash", m.withoutHash},
          {"duplicateGroups", m.duplicateGroups.size()},
          {"filesInDuplicateGroups", inGroups},
          {"largestDuplicateGroups", largest},
          {"definition", kSameModelDefinition}};
}

json representativeFiles(const json& files, const DistinctModels& m) {
  json out = json::array();
  for (size_t i : m.representatives) out.push_back(files[i]);
  return out;
}

std::string filesAndModels(const DistinctModels& m) {
  return std::to_string(m.files) + " files, " + std::to_string(m.representatives.size()) + " distinct models";
}

}  // namespace mb::report
