#include "pipelines/motor/motor_vertices.h"

#include <cmath>

#include "pipelines/gl/frame_vertices.h"
#include "pipelines/motor/companion.h"

namespace mb::motor {

glm::vec4 vertexRotor(const Primitive& p, size_t v, int& zeroScalarFrames) {
  const auto [n, t] = gl::vertexFrame(p, v);
  const companion::TangentRotor r = companion::encodeTangentRotor(n, glm::vec3(t), t.w);
  zeroScalarFrames += r.scalarWasZero;
  return r.rotor;
}

VertexStream interleaveVertices(const Primitive& p) {
  VertexStream out;
  out.data = gl::interleave<float>(p, kFloatsPerVertex, [&](auto& data, size_t v) {
    const glm::vec4 r = vertexRotor(p, v, out.zeroScalarFrames);
    out.biasedFrames += std::abs(r.x) == companion::kMinTangentScalar;  // exactly where the rule puts it
    const glm::vec2 uv = gl::vertexUv(p, v);
    const glm::vec3& x = p.positions[v];
    data.insert(data.end(), {x.x, x.y, x.z, r.x, r.y, r.z, r.w, uv.x, uv.y});
  });
  return out;
}

}  // namespace mb::motor
