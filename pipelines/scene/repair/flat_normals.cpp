#include "pipelines/scene/repair/flat_normals.h"

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

// Applies f to every per-vertex stream of p.
template <class F>
void forEachStream(Primitive& p, F&& f) {
  f(p.positions);
  f(p.normals);
  f(p.tangents);
  f(p.uv0);
  f(p.uv1);
  f(p.colors);
  f(p.joints);
  f(p.weights);
  for (MorphTarget& t : p.targets) {  // deltas follow their vertex through every split
    f(t.positions);
    f(t.normals);
    f(t.tangents);
  }
}

}  // namespace

void generateFlatNormals(Primitive& p) {
  forEachStream(p, [&](auto& stream) { expand(stream, p.indices); });
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
  forEachStream(p, [&](auto& stream) { append(stream, src); });
  return uint32_t(p.positions.size() - 1);
}

}  // namespace mb
