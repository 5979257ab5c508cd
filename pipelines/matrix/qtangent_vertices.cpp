#include "pipelines/matrix/qtangent_vertices.h"

#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "pipelines/gl/frame_vertices.h"

namespace mb::affine {

QTangent encodeQTangent(const glm::vec3& normal, const glm::vec3& tangent, float w) {
  const glm::vec3 n = glm::normalize(normal);
  const glm::vec3 t = glm::normalize(tangent - n * glm::dot(n, tangent));
  const glm::quat r = glm::normalize(glm::quat_cast(glm::mat3(t, glm::cross(n, t), n)));
  QTangent out;
  glm::vec4 q(r.x, r.y, r.z, r.w);
  const bool negative = w < 0.0f;
  if (std::signbit(q.w) != negative) q = -q;  // q and -q are the same rotation
  if (std::abs(q.w) < kMinQuaternionW) {
    // Keep the rotation as close as possible: shrink the vector part so q stays unit.
    const glm::vec3 v(q);
    const float k = std::sqrt(1.0f - kMinQuaternionW * kMinQuaternionW) / glm::length(v);
    q = glm::vec4(v * k, negative ? -kMinQuaternionW : kMinQuaternionW);
    out.biased = true;
  }
  out.q = q;
  return out;
}

gl::PackedStream interleaveQTangent(const Primitive& p) {
  gl::PackedStream out;
  out.bytes = gl::interleave<uint8_t>(p, 28, [&](auto& bytes, size_t v) {
    const auto [n, t] = gl::vertexFrame(p, v);
    const QTangent q = encodeQTangent(n, glm::vec3(t), t.w);
    out.biasedFrames += q.biased;
    const int16_t s[4] = {gl::snorm16(q.q.x), gl::snorm16(q.q.y), gl::snorm16(q.q.z), gl::snorm16(q.q.w)};
    gl::appendSnormFrameVertex(bytes, p.positions[v], s, gl::vertexUv(p, v));
  });
  return out;
}

}  // namespace mb::affine
