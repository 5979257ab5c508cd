#include "pipelines/motor/motor_c_vertices.h"

#include <cmath>

#include "pipelines/compact/compact_encoding.h"
#include "pipelines/motor/motor_vertices.h"

namespace mb::motor {

CompactStream interleaveCompact(const Primitive& p) {
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

}  // namespace mb::motor
