#include "pipelines/motor/rotor_signs.h"

#include <array>

#include "pipelines/scene/repair/flat_normals.h"

namespace mb::motor {

SignedRotors signRotorsForInterpolation(const Primitive& p, const std::vector<glm::vec4>& rotors) {
  SignedRotors out{p, rotors, {}, 0, 0};
  const size_t n = p.positions.size();
  for (uint32_t v = 0; v < n; ++v) out.source.push_back(v);
  // Per original vertex: the sign its own slot was given (0: none yet), and its twin with the
  // opposite sign (-1: none yet).
  std::vector<int> sign(n, 0);
  std::vector<int64_t> twin(n, -1);
  auto slot = [&](uint32_t v, int s) -> uint32_t {
    if (sign[v] == 0) {
      sign[v] = s;
      out.rotors[v] = rotors[v] * float(s);
    }
    if (sign[v] == s) return v;
    if (twin[v] < 0) {
      twin[v] = duplicateVertex(out.primitive, v);  // morph deltas follow
      out.rotors.push_back(rotors[v] * float(s));
      out.source.push_back(v);
      ++out.splitVertices;
    }
    return uint32_t(twin[v]);
  };
  std::vector<uint32_t>& idx = out.primitive.indices;
  std::vector<char> unresolved(idx.size() / 3, 0);  // per triangle
  for (size_t t = 0; t + 2 < idx.size(); t += 3) {
    const std::array<uint32_t, 3> v = {p.indices[t], p.indices[t + 1], p.indices[t + 2]};
    if (v[0] >= n || v[1] >= n || v[2] >= n) continue;  // the loader rejects these; stay safe
    // Signs relative to the first corner, then the overall sign most earlier choices agree with.
    std::array<int, 3> rel = {1, 1, 1};
    for (int k = 1; k < 3; ++k) rel[k] = glm::dot(rotors[v[0]], rotors[v[k]]) >= 0.0f ? 1 : -1;
    int vote = 0;
    for (int k = 0; k < 3; ++k) vote += sign[v[k]] * rel[k];
    const int overall = vote < 0 ? -1 : 1;
    for (int k = 0; k < 3; ++k) idx[t + size_t(k)] = slot(v[k], overall * rel[k]);
    const glm::vec4 &a = out.rotors[idx[t]], &b = out.rotors[idx[t + 1]], &c = out.rotors[idx[t + 2]];
    unresolved[t / 3] = glm::dot(b, c) < 0.0f || glm::dot(a, b) < 0.0f || glm::dot(a, c) < 0.0f;
    out.unresolvedTriangles += unresolved[t / 3];
  }
  // Interpolable triangles first, in their order; the unresolved ones after them (a trailing
  // partial triangle, which no triangle list has, keeps the order as it is).
  out.interpolableIndices = idx.size();
  if (out.unresolvedTriangles == 0 || idx.size() % 3 != 0) return out;
  std::vector<uint32_t> ordered;
  ordered.reserve(idx.size());
  for (char last : {0, 1})
    for (size_t t = 0; t < unresolved.size(); ++t)
      if (unresolved[t] == last) ordered.insert(ordered.end(), idx.begin() + long(3 * t), idx.begin() + long(3 * t + 3));
  out.interpolableIndices = idx.size() - 3 * size_t(out.unresolvedTriangles);
  idx = std::move(ordered);
  return out;
}

}  // namespace mb::motor
