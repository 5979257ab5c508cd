#include "pipelines/motor/motor_vertices.h"

#include "pipelines/gl/frame_vertices.h"
#include "pipelines/motor/companion.h"

namespace mb::motor {

VertexStream interleaveVertices(const Primitive& p) {
  VertexStream out;
  out.data.reserve(p.positions.size() * kFloatsPerVertex);
  for (size_t v = 0; v < p.positions.size(); ++v) {
    const auto [n, t] = gl::vertexFrame(p, v);
    const companion::TangentRotor r = companion::encodeTangentRotor(n, glm::vec3(t), t.w);
    out.zeroScalarFrames += r.scalarWasZero;
    const glm::vec2 uv = v < p.uv0.size() ? p.uv0[v] : glm::vec2(0.0f);
    const glm::vec3& x = p.positions[v];
    out.data.insert(out.data.end(),
                    {x.x, x.y, x.z, r.rotor.x, r.rotor.y, r.rotor.z, r.rotor.w, uv.x, uv.y});
  }
  return out;
}

}  // namespace mb::motor
