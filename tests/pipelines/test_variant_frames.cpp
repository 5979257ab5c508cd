// Quantized vertex frames: the paper's signed-zero handedness rule does not survive
// int16 SNORM storage, the bias rule (|scalar| >= 1/32767) does; QTangent and motor_q frames
// decode, after quantisation, to the frame they encode. References: the input frames
// themselves (normal, tangent, w) and GLM's quaternion -> matrix conversion.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "harness/bench/bench_shaders.h"
#include "pipelines/matrix/qtangent_vertices.h"
#include "pipelines/motor/companion.h"
#include "pipelines/motor/motor_kernels.h"
#include "pipelines/motor/motor_q_vertices.h"

using namespace mb;

namespace {

struct Frame {
  glm::vec3 normal, tangent;
  float w;
};

// The 24 axis-aligned proper frames (tangent and normal along +-x, +-y, +-z, perpendicular),
// each with both handednesses: among them the half turns whose rotor scalar is exactly 0.
std::vector<Frame> axisAlignedFrames() {
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<Frame> out;
  for (const glm::vec3& n : axes)
    for (const glm::vec3& t : axes)
      if (glm::dot(n, t) == 0.0f)
        for (float w : {1.0f, -1.0f}) out.push_back({n, t, w});
  return out;
}

// The paper's rule: the sign of the rotor chosen so that signbit(scalar) = (w < 0), with no
// bias; a zero scalar then carries the handedness as IEEE -0.
glm::vec4 signedZeroRotor(const Frame& f) {
  const glm::vec3 b = glm::cross(f.normal, f.tangent);
  companion::Vec4 r = companion::detail::rotorFromColumns(f.tangent, b, f.normal);
  if (std::signbit(r.x) != (f.w < 0.0f)) r = -r;
  return {r.x, r.y, r.z, r.w};
}

// The vertex shader's handedness (motor_transform.glsl motorHandedness: sign(1 / s)).
float shaderHandedness(const glm::vec4& rotor) {
  return mk().motorHandedness(MK::vec4(rotor.x, rotor.y, rotor.z, rotor.w));
}

// motor_q's rotor as the vertex fetch reads it back (GL's SNORM rule).
glm::vec4 throughInt16(const glm::vec4& rotor) {
  int16_t q[4];
  motor::quantizeRotor(rotor, q);
  return {gl::fromSnorm16(q[0]), gl::fromSnorm16(q[1]), gl::fromSnorm16(q[2]), gl::fromSnorm16(q[3])};
}

}  // namespace

TEST(QuantizedFrames, SignedZeroRuleFailsUnderInt16ButHoldsInFloat) {
  int zeroScalar = 0, wrongAfterInt16 = 0;
  for (const Frame& f : axisAlignedFrames()) {
    const glm::vec4 r = signedZeroRotor(f);
    if (r.x != 0.0f) continue;
    ++zeroScalar;
    EXPECT_EQ(shaderHandedness(r), f.w) << "float storage keeps -0";
    wrongAfterInt16 += shaderHandedness(throughInt16(r)) != f.w;
  }
  ASSERT_GT(zeroScalar, 0) << "no axis-aligned frame has a zero rotor scalar";
  // Every zero-scalar frame with w = -1 decodes as +1: int16 has no -0.
  EXPECT_EQ(wrongAfterInt16 * 2, zeroScalar);
}

TEST(QuantizedFrames, BiasRuleSurvivesInt16OnEveryAxisAlignedFrame) {
  int biased = 0;
  for (const Frame& f : axisAlignedFrames()) {
    const companion::TangentRotor r = companion::encodeTangentRotor(f.normal, f.tangent, f.w);
    biased += r.clamped;
    const glm::vec4 q = throughInt16(r.rotor);
    EXPECT_NE(q.x, 0.0f);
    EXPECT_EQ(shaderHandedness(q), f.w);
    const MK::mat2x3 d = mk().rotorFrame(MK::vec4(q.x, q.y, q.z, q.w));  // the shader's decoding
    EXPECT_LT(glm::length(glm::vec3(d[0].x, d[0].y, d[0].z) - f.normal), 1e-3f);
    EXPECT_LT(glm::length(glm::vec3(d[1].x, d[1].y, d[1].z) - f.tangent), 1e-3f);
  }
  EXPECT_GT(biased, 0);
}

TEST(QuantizedFrames, QTangentDecodesToTheEncodedFrameAfterInt16) {
  AffineShader<float> A;
  std::vector<Frame> frames = axisAlignedFrames();
  // Plus generic frames (normal and a tangent not quite perpendicular, both handednesses).
  for (int i = 0; i < 64; ++i) {
    const float a = 0.37f * float(i), b = 0.23f * float(i) + 0.1f;
    const glm::vec3 n = glm::normalize(glm::vec3(std::cos(a) * std::sin(b), std::sin(a) * std::sin(b), std::cos(b)));
    const glm::vec3 t0 = glm::normalize(glm::cross(n, glm::vec3(0.3f, -0.8f, 0.5f)));
    frames.push_back({n, t0 + 0.05f * n, i % 2 ? -1.0f : 1.0f});
  }
  int biased = 0;
  for (const Frame& f : frames) {
    const affine::QTangent q = affine::encodeQTangent(f.normal, f.tangent, f.w);
    biased += q.biased;
    EXPECT_GE(std::abs(q.q.w), affine::kMinQuaternionW);
    // Reference: GLM's rotation matrix of the (unquantized) quaternion has columns
    // (tangent, bitangent, normal).
    const glm::mat3 m = glm::mat3_cast(glm::quat(q.q.w, q.q.x, q.q.y, q.q.z));
    const glm::vec3 t = glm::normalize(f.tangent - f.normal * glm::dot(f.normal, f.tangent));
    EXPECT_LT(glm::length(m[0] - t), 1e-3f);
    EXPECT_LT(glm::length(m[2] - f.normal), 1e-3f);
    // Through int16 SNORM and the shader's decoder.
    const int16_t s[4] = {gl::snorm16(q.q.x), gl::snorm16(q.q.y), gl::snorm16(q.q.z), gl::snorm16(q.q.w)};
    const AffineShader<float>::vec4 g(gl::fromSnorm16(s[0]), gl::fromSnorm16(s[1]),
                                      gl::fromSnorm16(s[2]), gl::fromSnorm16(s[3]));
    const auto d = A.qtangentFrame(g);
    EXPECT_LT(glm::length(glm::vec3(d[0].x, d[0].y, d[0].z) - f.normal), 1e-3f);
    EXPECT_LT(glm::length(glm::vec3(d[1].x, d[1].y, d[1].z) - t), 1e-3f);
    EXPECT_EQ(d[1].w, f.w);
  }
  EXPECT_GT(biased, 0);  // the axis-aligned half turns have w = 0 before the bias
}
