#include "pipelines/motor/motor_c_vertices.h"

#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include "pipelines/compact/compact_encoding.h"
#include "pipelines/motor/motor_vertices.h"
#include "pipelines/motor/rotor_signs.h"

namespace mb::motor {

gl::PackedStream interleaveCompact(const Primitive& p) {
  // The paper's rotors: handedness in the sign of the scalar part, kept non-zero by the bias
  // rule (so signbit reads it); the compact word carries it as its own bit.
  const VertexStream f = interleaveVertices(p);
  const size_t n = p.positions.size(), stride = size_t(kFloatsPerVertex);
  std::vector<uint32_t> frames(n);
  std::vector<glm::vec2> uv(n);
  for (size_t v = 0; v < n; ++v) {
    const float* x = &f.data[v * stride];
    frames[v] = compact::encodeRotorFrame({x[3], x[4], x[5], x[6]}, std::signbit(x[3]));
    uv[v] = {x[7], x[8]};
  }
  return {compact::interleave(p.positions, frames, uv, compact::positionCube(p.positions)), f.zeroScalarFrames};
}

SignedCompactStream interleaveCompactSigned(const Primitive& p) {
  const VertexStream f = interleaveVertices(p);
  const size_t n = p.positions.size(), stride = size_t(kFloatsPerVertex);
  std::vector<glm::vec4> rotors(n);
  for (size_t v = 0; v < n; ++v) rotors[v] = glm::make_vec4(&f.data[v * stride + 3]);
  SignedRotors s = signRotorsForInterpolation(p, rotors);
  const size_t m = s.primitive.positions.size();
  std::vector<uint32_t> frames(m);
  std::vector<glm::vec2> uv(m);
  std::vector<float> handedness(m);
  for (size_t v = 0; v < m; ++v) {
    const float* x = &f.data[s.source[v] * stride];
    frames[v] = compact::encodeSignedRotorFrame(s.rotors[v]);
    uv[v] = {x[7], x[8]};
    handedness[v] = std::signbit(x[3]) ? -1.0f : 1.0f;
  }
  SignedCompactStream out;
  out.bytes = compact::interleave(s.primitive.positions, frames, uv, compact::positionCube(p.positions), handedness);
  out.primitive = std::move(s.primitive);
  out.zeroScalarFrames = f.zeroScalarFrames;
  out.splitVertices = s.splitVertices;
  out.unresolvedTriangles = s.unresolvedTriangles;
  out.interpolableIndices = s.interpolableIndices;
  return out;
}

}  // namespace mb::motor
