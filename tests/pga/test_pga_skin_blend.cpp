// motorBlendJoints uses the reference's hemisphere rule (the paper's skinning
// listing): each joint after the first is compared with the running sum of the weighted joints
// before it, and negated when the rotor halves' dot product is <= 0. Checked against a plain
// loop over 8-float arrays written from the listing, on the two cases where the earlier rule
// (compare with the first joint, `<`) gave another motor: a joint exactly orthogonal to the
// first (dot = 0), and a joint on the far side of the first but the near side of the sum.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "pipelines/motor/motor_kernels.h"

using namespace mb;

namespace {

using M8 = std::array<float, 8>;

// A rotor of `angle` about z in the layout [s, e23, e31, e12, e01, e02, e03, e0123], with a
// translation part so the dual half takes part in the blend too.
M8 rotorZ(float angle, float e01 = 0.0f) {
  return {std::cos(angle / 2), 0, 0, -std::sin(angle / 2), e01, 0, 0, 0};
}

// The listing's rule, straight: r = w0 b0; for k > 0: if dot(r.rotor, bk.rotor) <= 0 then
// bk = -bk; r += wk bk. Then normalise (for these pure z-rotations + e01 the motor norm is the
// rotor half's length; the test motors keep the dual half orthogonal, see below).
M8 listingBlend(const std::array<M8, 4>& b, const std::array<float, 4>& w) {
  M8 r{};
  for (int i = 0; i < 8; ++i) r[size_t(i)] = w[0] * b[0][size_t(i)];
  for (size_t k = 1; k < 4; ++k) {
    float d = 0;
    for (int i = 0; i < 4; ++i) d += r[size_t(i)] * b[k][size_t(i)];
    const float sign = d <= 0.0f ? -1.0f : 1.0f;
    for (int i = 0; i < 8; ++i) r[size_t(i)] += w[k] * sign * b[k][size_t(i)];
  }
  return r;
}

Motor toMotor(const M8& m) {
  Motor x;
  for (int k = 0; k < 8; ++k) x[k / 4][k % 4] = m[size_t(k)];
  return x;
}

// normalize_m's contract: the unit motor with the same rotor direction; for the blends below
// (e01 only in the dual half, rotors about z) the result is r / |rotor half| up to the
// orthogonality correction, which is 0 when s*e0123 - e23*e01 - ... = 0 (e01 pairs with e23,
// which is 0 here).
M8 normalisedByRotor(M8 r) {
  const float n = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
  for (float& v : r) v /= n;
  return r;
}

void expectBlend(const std::array<M8, 4>& b, const std::array<float, 4>& w) {
  const M8 expect = normalisedByRotor(listingBlend(b, w));
  const Motor got = mk().motorBlendJoints(toMotor(b[0]), toMotor(b[1]), toMotor(b[2]),
                                          toMotor(b[3]), MK::vec4(w[0], w[1], w[2], w[3]));
  for (int k = 0; k < 8; ++k) EXPECT_NEAR(got[k / 4][k % 4], expect[size_t(k)], 1e-6f) << k;
}

}  // namespace

TEST(SkinBlend, OrthogonalJointIsNegatedAsTheListingDoes) {
  // A half turn about z against the identity: rotor dot product exactly 0.
  const M8 id = rotorZ(0.0f, 0.3f), half = {0, 0, 0, -1, 0.2f, 0, 0, 0};
  expectBlend({id, half, id, id}, {0.5f, 0.5f, 0.0f, 0.0f});
  // By hand: r = 0.5 id - 0.5 half = (0.5, 0, 0, 0.5 | 0.05, ...) -> rotor (1/sqrt2)(1 + e12).
  const Motor got = mk().motorBlendJoints(toMotor(id), toMotor(half), toMotor(id), toMotor(id),
                                          MK::vec4(0.5f, 0.5f, 0.0f, 0.0f));
  EXPECT_NEAR(got[0][0], std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(got[0][3], std::sqrt(0.5f), 1e-6f);
}

TEST(SkinBlend, ComparesWithTheRunningSumNotTheFirstJoint) {
  const float deg = 3.14159265f / 180.0f;
  const M8 j0 = rotorZ(0.0f), j1 = rotorZ(150 * deg, 0.1f), j2 = rotorZ(200 * deg, -0.2f);
  // dot(j0, j2) = cos(100 deg) < 0, but dot(0.2 j0 + 0.6 j1, j2) > 0: the listing keeps j2.
  float d02 = 0, dr2 = 0;
  for (size_t i = 0; i < 4; ++i) {
    d02 += j0[i] * j2[i];
    dr2 += (0.2f * j0[i] + 0.6f * j1[i]) * j2[i];
  }
  ASSERT_LT(d02, 0.0f);
  ASSERT_GT(dr2, 0.0f);
  expectBlend({j0, j1, j2, j0}, {0.2f, 0.6f, 0.2f, 0.0f});
  // The blend turns near the weighted mean 0.6 * 150 + 0.2 * 200 = 130 degrees (about 135);
  // the first-joint rule flipped j2 and gave about 89.
  const Motor got = mk().motorBlendJoints(toMotor(j0), toMotor(j1), toMotor(j2), toMotor(j0),
                                          MK::vec4(0.2f, 0.6f, 0.2f, 0.0f));
  const float angle = 2.0f * std::atan2(-got[0][3], got[0][0]) / deg;
  EXPECT_NEAR(angle, 130.0f, 10.0f);
}
