#include "pipelines/motor/motor_q_vertices.h"

#include <cmath>

#include "pipelines/motor/companion.h"
#include "pipelines/motor/motor_vertices.h"

namespace mb::motor {

void quantizeRotor(const glm::vec4& rotor, int16_t out[4]) {
  for (int i = 0; i < 4; ++i) out[i] = gl::snorm16(rotor[i]);
}

glm::vec4 dequantizeRotor(const int16_t q[4]) {
  return {gl::fromSnorm16(q[0]), gl::fromSnorm16(q[1]), gl::fromSnorm16(q[2]), gl::fromSnorm16(q[3])};
}

int countBiasedFrames(const std::vector<float>& motorVertices) {
  int n = 0;
  for (size_t v = 3; v < motorVertices.size(); v += size_t(kFloatsPerVertex))
    n += std::abs(motorVertices[v]) == companion::kMinTangentScalar;
  return n;
}

gl::PackedStream interleaveQuantized(const Primitive& p) {
  // motor::interleaveVertices encodes with the bias rule already (companion::encodeTangentRotor);
  // a biased rotor's scalar is exactly +-kMinTangentScalar.
  const VertexStream f = interleaveVertices(p);
  const size_t stride = size_t(kFloatsPerVertex);
  gl::PackedStream out;
  out.zeroScalarFrames = f.zeroScalarFrames;
  out.biasedFrames = countBiasedFrames(f.data);
  out.bytes.reserve(p.positions.size() * 28);
  for (size_t v = 0; v + stride <= f.data.size(); v += stride) {
    const float* x = &f.data[v];
    int16_t q[4];
    quantizeRotor({x[3], x[4], x[5], x[6]}, q);
    gl::appendBytes(out.bytes, x, 3);
    gl::appendBytes(out.bytes, q, 4);
    gl::appendBytes(out.bytes, x + 7, 2);
  }
  return out;
}

}  // namespace mb::motor
