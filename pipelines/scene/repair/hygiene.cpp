#include "pipelines/scene/repair/hygiene.h"

#include <cmath>

namespace mb {

bool isFinite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

int fixPositions(std::vector<glm::vec3>& positions) {
  int fixed = 0;
  for (auto& p : positions)
    if (!isFinite(p)) {
      p = glm::vec3(0.0f);
      ++fixed;
    }
  return fixed;
}

glm::vec3 fallbackTangent(const glm::vec3& n) {
  glm::vec3 a = std::fabs(n.x) > 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  glm::vec3 t = a - n * glm::dot(n, a);
  float len = glm::length(t);
  return len > 1e-6f && std::isfinite(len) ? t / len : glm::vec3(1, 0, 0);
}

namespace {
bool usable(const glm::vec3& v, float* len) {
  *len = glm::length(v);
  return std::isfinite(*len) && *len > 1e-12f;
}
}  // namespace

void fixNormals(Primitive& p, LoadStats& stats) {
  std::vector<size_t> bad;
  for (size_t i = 0; i < p.normals.size(); ++i) {
    float len = 0.0f;
    if (!usable(p.normals[i], &len)) {
      bad.push_back(i);
      continue;
    }
    if (std::fabs(len - 1.0f) > 1e-3f) ++stats.normalsRenormalised;
    p.normals[i] /= len;
  }
  if (bad.empty()) return;
  // Face normals only where needed: accumulate area-weighted normals of adjacent faces.
  std::vector<glm::vec3> acc(p.normals.size(), glm::vec3(0.0f));
  for (size_t t = 0; t + 2 < p.indices.size(); t += 3) {
    uint32_t a = p.indices[t], b = p.indices[t + 1], c = p.indices[t + 2];
    glm::vec3 fn = glm::cross(p.positions[b] - p.positions[a], p.positions[c] - p.positions[a]);
    if (!isFinite(fn)) continue;
    acc[a] += fn;
    acc[b] += fn;
    acc[c] += fn;
  }
  for (size_t i : bad) {
    float len = 0.0f;
    p.normals[i] = usable(acc[i], &len) ? acc[i] / len : glm::vec3(0, 0, 1);
    ++stats.badNormalsReplaced;
  }
}

void fixTangents(Primitive& p, LoadStats& stats) {
  for (size_t i = 0; i < p.tangents.size(); ++i) {
    glm::vec4& t = p.tangents[i];
    const glm::vec3& n = p.normals[i];
    glm::vec3 xyz(t);
    glm::vec3 ortho = xyz - n * glm::dot(n, xyz);
    float len = glm::length(ortho), orig = glm::length(xyz);
    bool ok = std::isfinite(len) && std::isfinite(orig) && orig > 1e-12f && len > 1e-3f * orig;
    bool wOk = std::isfinite(t.w) && t.w != 0.0f;
    float w = t.w < 0.0f ? -1.0f : 1.0f;
    if (!ok || !wOk) ++stats.badTangentsReplaced;
    t = glm::vec4(ok ? ortho / len : fallbackTangent(n), w);
  }
}

}  // namespace mb
