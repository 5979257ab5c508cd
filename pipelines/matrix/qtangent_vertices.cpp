#include "pipelines/matrix/qtangent_vertices.h"

#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "pipelines/matrix/affine_vertices.h"

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
  const std::vector<float> f = interleaveFullFrame(p);  // pos 3, normal 3, tangent 4, uv 2
  const size_t stride = size_t(kFloatsPerVertex);
  gl::PackedStream out;
  out.bytes.reserve(p.positions.size() * 28);
  for (size_t v = 0; v + stride <= f.size(); v += stride) {
    const float* x = &f[v];
    const QTangent q = encodeQTangent({x[3], x[4], x[5]}, {x[6], x[7], x[8]}, x[9]);
    out.biasedFrames += q.biased;
    const int16_t s[4] = {gl::snorm16(q.q.x), gl::snorm16(q.q.y), gl::snorm16(q.q.z),
                          gl::snorm16(q.q.w)};
    gl::appendBytes(out.bytes, x, 3);
    gl::appendBytes(out.bytes, s, 4);
    gl::appendBytes(out.bytes, x + 10, 2);
  }
  return out;
}

}  // namespace mb::affine
