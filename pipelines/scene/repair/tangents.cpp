#include "pipelines/scene/repair/tangents.h"

#include <cmath>
#include <cstring>
#include <map>
#include <unordered_map>

#include "pipelines/scene/repair/flat_normals.h"
#include "pipelines/scene/repair/hygiene.h"

namespace mb {
namespace {

// Exact-equality weld key over position, normal and uv bit patterns.
struct Key {
  float v[8];
  bool operator==(const Key& o) const { return std::memcmp(v, o.v, sizeof v) == 0; }
};
struct KeyHash {
  size_t operator()(const Key& k) const {
    uint32_t bits[8];
    std::memcpy(bits, k.v, sizeof bits);
    size_t h = 1469598103934665603ull;
    for (uint32_t b : bits) h = (h ^ b) * 1099511628211ull;
    return h;
  }
};

std::vector<uint32_t> weld(const Primitive& p, const std::vector<glm::vec2>& uv) {
  std::unordered_map<Key, uint32_t, KeyHash> first;
  std::vector<uint32_t> rep(p.positions.size());
  for (size_t i = 0; i < rep.size(); ++i) {
    Key k{{p.positions[i].x, p.positions[i].y, p.positions[i].z, p.normals[i].x, p.normals[i].y,
           p.normals[i].z, uv[i].x, uv[i].y}};
    rep[i] = first.emplace(k, uint32_t(i)).first->second;
  }
  return rep;
}

glm::vec3 inPlane(const glm::vec3& v, const glm::vec3& n) { return v - n * glm::dot(n, v); }

glm::vec3 safeNormalize(const glm::vec3& v, bool* ok) {
  float len = glm::length(v);
  *ok = std::isfinite(len) && len > 1e-20f;
  return *ok ? v / len : glm::vec3(0.0f);
}

}  // namespace

void generateTangents(Primitive& p, int uvSet, LoadStats& stats) {
  const std::vector<glm::vec2> uv = uvSet == 1 ? p.uv1 : p.uv0;
  size_t nv = p.positions.size(), nt = p.indices.size() / 3;
  std::vector<uint32_t> rep = weld(p, uv);
  // acc[2*rep + orient]: orient 1 = positive uv area (w = +1).
  std::vector<glm::vec3> acc(2 * nv, glm::vec3(0.0f));
  std::vector<int8_t> faceOrient(nt, -1);  // -1: degenerate

  for (size_t f = 0; f < nt; ++f) {
    const uint32_t* c = &p.indices[3 * f];
    glm::vec3 d1 = p.positions[c[1]] - p.positions[c[0]], d2 = p.positions[c[2]] - p.positions[c[0]];
    glm::vec2 t1 = uv[c[1]] - uv[c[0]], t2 = uv[c[2]] - uv[c[0]];
    float area = t1.x * t2.y - t1.y * t2.x;
    glm::vec3 dPdu = t2.y * d1 - t1.y * d2;
    bool ok = false;
    glm::vec3 t = safeNormalize(area < 0.0f ? -dPdu : dPdu, &ok);
    if (!(std::fabs(area) > 0.0f) || !ok) {
      ++stats.degenerateUvTriangles;
      continue;
    }
    faceOrient[f] = area > 0.0f ? 1 : 0;
    for (int k = 0; k < 3; ++k) {
      const glm::vec3& n = p.normals[c[k]];
      bool okT = false, okA = false, okB = false;
      glm::vec3 tp = safeNormalize(inPlane(t, n), &okT);
      glm::vec3 ea = safeNormalize(inPlane(p.positions[c[(k + 1) % 3]] - p.positions[c[k]], n), &okA);
      glm::vec3 eb = safeNormalize(inPlane(p.positions[c[(k + 2) % 3]] - p.positions[c[k]], n), &okB);
      if (!okT) continue;
      float angle = okA && okB ? std::acos(glm::clamp(glm::dot(ea, eb), -1.0f, 1.0f)) : 0.0f;
      acc[2 * size_t(rep[c[k]]) + size_t(faceOrient[f])] += angle * tp;
    }
  }

  auto resolve = [&](uint32_t v, int orient, glm::vec4* out) {
    const glm::vec3& n = p.normals[v];
    size_t r = rep[v];
    int o = orient;
    if (o < 0) o = glm::length(acc[2 * r + 1]) > 0.0f ? 1 : glm::length(acc[2 * r]) > 0.0f ? 0 : 1;
    bool ok = false;
    glm::vec3 t = safeNormalize(inPlane(acc[2 * r + size_t(o)], n), &ok);
    *out = glm::vec4(ok ? t : fallbackTangent(n), o == 1 ? 1.0f : -1.0f);
  };

  // Per corner result; a vertex used with both orientations is split.
  p.tangents.assign(nv, glm::vec4(0.0f));
  std::vector<int8_t> assigned(nv, -1);
  std::map<std::pair<uint32_t, int>, uint32_t> splits;
  for (size_t f = 0; f < nt; ++f) {
    for (int k = 0; k < 3; ++k) {
      uint32_t v = p.indices[3 * f + size_t(k)];
      glm::vec4 t;
      resolve(v, faceOrient[f], &t);
      int o = t.w > 0.0f ? 1 : 0;
      if (assigned[v] < 0) {
        assigned[v] = int8_t(o);
        p.tangents[v] = t;
      } else if (assigned[v] != o) {
        auto it = splits.find({v, o});
        if (it == splits.end()) {
          uint32_t copy = duplicateVertex(p, v);
          p.tangents[copy] = t;
          it = splits.emplace(std::make_pair(v, o), copy).first;
          ++stats.tangentSplitVertices;
        }
        p.indices[3 * f + size_t(k)] = it->second;
      }
    }
  }
  for (size_t v = 0; v < nv; ++v)  // vertices no triangle uses
    if (assigned[v] < 0) p.tangents[v] = glm::vec4(fallbackTangent(p.normals[v]), 1.0f);
  p.generatedTangents = true;
}

}  // namespace mb
