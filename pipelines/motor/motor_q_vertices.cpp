#include "pipelines/motor/motor_q_vertices.h"

#include <cmath>

#include "pipelines/gl/frame_vertices.h"
#include "pipelines/motor/companion.h"
#include "pipelines/motor/motor_vertices.h"

namespace mb::motor {

void quantizeRotor(const glm::vec4& rotor, int16_t out[4]) {
  for (int i = 0; i < 4; ++i) out[i] = gl::snorm16(rotor[i]);
}

gl::PackedStream interleaveQuantized(const Primitive& p) {
  gl::PackedStream out;
  out.bytes = gl::interleave<uint8_t>(p, 28, [&](auto& bytes, size_t v) {
    const glm::vec4 r = vertexRotor(p, v, out.zeroScalarFrames);
    // vertexRotor applies the bias rule already: a biased rotor's scalar is exactly
    // +-kMinTangentScalar (as motor::interleaveVertices counts it).
    out.biasedFrames += std::abs(r.x) == companion::kMinTangentScalar;
    int16_t q[4];
    quantizeRotor(r, q);
    gl::appendSnormFrameVertex(bytes, p.positions[v], q, gl::vertexUv(p, v));
  });
  return out;
}

}  // namespace mb::motor
