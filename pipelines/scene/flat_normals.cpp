#include "pipelines/scene/flat_normals.h"

#include <cmath>

namespace mb {
namespace {

template <class T>
void expand(std::vector<T>& stream, const std::vector<uint32_t>& idx) {
  if (stream.empty()) return;
  std::vector<T> out;
  out.reserve(idx.size());
  for (uint32_t i : idx) out.push_back(stream[i]);
  stream.swap(out);
}

template <class T>
void append(std::vector<T>& stream, uint32_t src) {
  if (!stream.empty()) stream.push_back(T(stream[src]));
}

}  // namespace

void generateFlatNormals(Primitive& p) {
  const auto& idx = p.indices;
  expand(p.positions, idx);
  expand(p.tangents, idx);
  expand(p.uv0, idx);
  expand(p.uv1, idx);
  expand(p.colors, idx);
  expand(p.joints, idx);
  expand(p.weights, idx);
  size_t n = p.indices.size();  // the loader keeps triangle lists a multiple of 3
  p.normals.assign(n, glm::vec3(0, 0, 1));
  for (size_t t = 0; t < n; t += 3) {
    glm::vec3 fn = glm::cross(p.positions[t + 1] - p.positions[t], p.positions[t + 2] - p.positions[t]);
    float len = glm::length(fn);
    if (std::isfinite(len) && len > 0.0f) p.normals[t] = p.normals[t + 1] = p.normals[t + 2] = fn / len;
  }
  for (size_t i = 0; i < n; ++i) p.indices[i] = uint32_t(i);
  p.generatedNormals = true;
}

uint32_t duplicateVertex(Primitive& p, uint32_t src) {
  append(p.positions, src);
  append(p.normals, src);
  append(p.tangents, src);
  append(p.uv0, src);
  append(p.uv1, src);
  append(p.colors, src);
  append(p.joints, src);
  append(p.weights, src);
  return uint32_t(p.positions.size() - 1);
}

}  // namespace mb
