// Where the motor family's rotor method (b) breaks: one target turning the tangent
// about the normal by theta, at weight w. The matrix pipeline's frame (and method (a), which
// re-forms the rotor from the morphed frame) turns by atan2(w sin theta, 1 - w + w cos theta);
// a blend of rotors turns by 2 atan2(w sin(theta/2), 1 - w + w cos(theta/2)). Equal at w = 0,
// 1/2 and 1; apart elsewhere by an angle that grows with theta (hand-derived values below).
#include <gtest/gtest.h>

#include <cmath>

#include "pipelines/motor/companion.h"
#include "pipelines/motor/motor_kernels.h"

using namespace mb;

namespace {

constexpr float kDeg = 3.14159265f / 180.0f;

// The angle of the tangent a rotor encodes (the shader's rotorFrame), about +z from +x.
float tangentAngle(const glm::vec4& rotor) {
  const MK::vec3 t = mk().rotorFrame(MK::vec4(rotor.x, rotor.y, rotor.z, rotor.w))[1];
  return std::atan2(t.y, t.x);
}

glm::vec4 toGlm(const MK::vec4& v) { return {v.x, v.y, v.z, v.w}; }

}  // namespace

TEST(MorphRotorTurn, FrameMethodFollowsTheMatrixAndRotorMethodDriftsWithTheTurn) {
  const glm::vec3 n(0, 0, 1), t(1, 0, 0);
  const glm::vec4 base = companion::encodeTangentRotor(n, t, 1.0f).rotor;
  const MK::vec4 r0(base.x, base.y, base.z, base.w);
  // {theta, w, method (b)'s error in degrees, hand-derived from the two formulas above}
  const struct { float theta, w, errorDeg; } cases[] = {
      {30, 0.25f, 0.098f}, {90, 0.25f, 3.163f}, {150, 0.25f, 19.833f}, {90, 0.5f, 0.0f}, {150, 0.75f, 19.833f}};
  for (const auto& c : cases) {
    const float th = c.theta * kDeg;
    const glm::vec3 dt(std::cos(th) - 1.0f, std::sin(th), 0.0f);  // the target's tangent delta
    const glm::vec4 target = companion::encodeTangentRotor(n, t + dt, 1.0f).rotor;
    const glm::vec4 delta = (glm::dot(target, base) < 0.0f ? -target : target) - base;
    const float matrix = std::atan2(c.w * std::sin(th), 1.0f - c.w + c.w * std::cos(th));
    const float frame = tangentAngle(toGlm(mk().morphRotorFrame(r0, MK::vec3(0.0f), MK::vec3(dt.x, dt.y, dt.z) * c.w)));
    const glm::vec4 d = delta * c.w;
    const float rotor = tangentAngle(toGlm(mk().morphRotorBlend(r0, MK::vec4(d.x, d.y, d.z, d.w))));
    EXPECT_NEAR(frame, matrix, 1e-5f) << c.theta << " " << c.w;
    EXPECT_NEAR(rotor, 2.0f * std::atan2(c.w * std::sin(th / 2), 1.0f - c.w + c.w * std::cos(th / 2)), 1e-5f);
    EXPECT_NEAR(std::fabs(rotor - matrix) / kDeg, c.errorDeg, 0.01f) << c.theta << " " << c.w;
  }
}

// The compact rotors' method (a) (motor_c: morphRotorFrameHanded; motor_cf: morphSignedRotorFrame):
// the decoded rotor comes with either sign and the handedness apart. A 90-degree tangent turn at
// weight 1/2 turns the tangent by 45 degrees (atan2(1/2, 1/2), the rule above) whichever sign the
// input has; the Handed form's scalar carries the handedness, the Signed form stays in the stored
// rotor's hemisphere.
TEST(MorphRotorTurn, CompactRotorsMorphTheFrameWhateverTheirSign) {
  const glm::vec3 n(0, 0, 1), t(1, 0, 0);
  const MK::vec3 none(0.0f), half(-0.5f, 0.5f, 0.0f);  // 0.5 x ((0, 1, 0) - (1, 0, 0))
  for (float handedness : {1.0f, -1.0f}) {
    const glm::vec4 base = companion::encodeTangentRotor(n, t, handedness).rotor;
    for (float sign : {1.0f, -1.0f}) {
      const MK::vec4 stored(sign * base.x, sign * base.y, sign * base.z, sign * base.w);
      const glm::vec4 handed = toGlm(mk().morphRotorFrameHanded(stored, handedness, none, half));
      EXPECT_NEAR(tangentAngle(handed), 45.0f * kDeg, 1e-5f) << handedness << " " << sign;
      EXPECT_EQ(handed.x < 0.0f, handedness < 0.0f) << "the scalar's sign is the handedness";
      const glm::vec4 signed_ = toGlm(mk().morphSignedRotorFrame(stored, handedness, none, half));
      EXPECT_NEAR(tangentAngle(signed_), 45.0f * kDeg, 1e-5f);
      EXPECT_GT(glm::dot(signed_, toGlm(stored)), 0.0f) << "kept in the stored rotor's hemisphere";
      EXPECT_NEAR(glm::length(signed_), 1.0f, 1e-6f);
    }
  }
}
