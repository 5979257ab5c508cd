#include "pipelines/motor/motor_c_vertices.h"

#include <cmath>

#include "pipelines/compact/compact_encoding.h"
#include "pipelines/gl/frame_vertices.h"
#include "pipelines/motor/motor_vertices.h"

namespace mb::motor {

gl::PackedStream interleaveCompact(const Primitive& p) {
  // The paper's rotors: handedness in the sign of the scalar part, kept non-zero by the bias
  // rule (so signbit reads it); the compact word carries it as its own bit.
  const compact::PositionCube cube = compact::positionCube(p.positions);
  gl::PackedStream out;
  out.bytes = gl::interleave<uint8_t>(p, compact::kVertexBytes, [&](auto& bytes, size_t v) {
    const glm::vec4 r = vertexRotor(p, v, out.zeroScalarFrames);
    compact::appendVertex(bytes, p.positions[v], cube, compact::encodeRotorFrame(r, std::signbit(r.x)), gl::vertexUv(p, v));
  });
  return out;
}

SignedCompactStream interleaveCompactSigned(const Primitive& p) {
  int zeroScalarFrames = 0;
  std::vector<glm::vec4> rotors(p.positions.size());
  for (size_t v = 0; v < rotors.size(); ++v) rotors[v] = vertexRotor(p, v, zeroScalarFrames);
  SignedCompactStream out{signRotorsForInterpolation(p, rotors), {}, zeroScalarFrames};
  const compact::PositionCube cube = compact::positionCube(p.positions);
  for (size_t v = 0; v < out.primitive.positions.size(); ++v) {
    const float handedness = std::signbit(rotors[out.source[v]].x) ? -1.0f : 1.0f;
    compact::appendVertex(out.bytes, out.primitive.positions[v], cube, compact::encodeSignedRotorFrame(out.rotors[v]),
                          gl::vertexUv(p, out.source[v]), handedness);
  }
  return out;
}

}  // namespace mb::motor
