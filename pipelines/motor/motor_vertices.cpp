#include "pipelines/motor/motor_vertices.h"

#include <cmath>

#include "pipelines/motor/companion.h"

namespace mb::motor {
namespace {

// Any unit vector perpendicular to n (the matrix pipeline's rule, so frames agree).
glm::vec3 perpendicular(const glm::vec3& n) {
  const glm::vec3 axis = std::fabs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::vec3 c = glm::cross(n, axis);
  const float len = glm::length(c);
  return len > 0.0f ? c / len : glm::vec3(1, 0, 0);
}

}  // namespace

VertexFrame vertexFrame(const Primitive& p, size_t v) {
  VertexFrame f;
  f.normal = v < p.normals.size() ? p.normals[v] : glm::vec3(0, 0, 1);
  f.tangent = v < p.tangents.size() ? p.tangents[v] : glm::vec4(perpendicular(f.normal), 1.0f);
  return f;
}

VertexStream interleaveVertices(const Primitive& p) {
  VertexStream out;
  out.data.reserve(p.positions.size() * kFloatsPerVertex);
  for (size_t v = 0; v < p.positions.size(); ++v) {
    const auto [n, t] = vertexFrame(p, v);
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
