// Drift of the curved camera (pipelines/curved/curved_drift.h): the distances are
// right on hand-made cases, renormalisation keeps both sides on their group, and the counts
// of one step and one renormalisation are the toolbox's.
#include <gtest/gtest.h>

#include "pipelines/curved/curved_drift.h"
#include "pipelines/scene/curved_space.h"

using namespace mb::curved;

TEST(CurvedDrift, DistancesOnHandMadeCases) {
  // (1 + e) times an isometry: M^T eta M = (1 + e)^2 eta, distance 2e + e^2.
  const double e = 1e-3;
  for (int k : {1, -1}) {
    const glm::mat4 m(glm::dmat4(mb::elementaryMatrix(k, 0, 3, 0.7)) * (1.0 + e));
    EXPECT_NEAR(matrixDistance(k, m), 2 * e + e * e, 1e-6);
    EXPECT_LT(matrixDistance(k, glm::mat4(mb::elementaryMatrix(k, 1, 2, 0.3))), 1e-6);
  }
  const float pair[8] = {1.001f, 0, 0, 0, 0.6f, 0.8f, 0, 0};  // |L|^2 = 1.002001, |R|^2 = 1
  EXPECT_NEAR(motorDistance(1, pair), 0.002001, 1e-6);
  const float motor[8] = {1, 0, 0, 0, 0, 0, 0, 0.01f};  // e0123 part 2 * 0.01
  EXPECT_NEAR(motorDistance(-1, motor), 0.02, 1e-6);
}

TEST(CurvedDrift, GramSchmidtRestoresTheGroup) {
  for (int k : {1, -1}) {
    glm::dmat4 m = mb::elementaryMatrix(k, 0, 3, 0.9) * mb::elementaryMatrix(k, 0, 1, 0.4);
    double a[4][4];
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) a[c][r] = m[c][r] * (1.0 + 1e-3 * (c + 2 * r));
    gramSchmidt(k, a);
    glm::mat4 f;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) {
        f[c][r] = float(a[c][r]);
        EXPECT_NEAR(a[c][r], m[c][r], 5e-2);
      }
    EXPECT_LT(matrixDistance(k, f), 1e-6);
  }
}

TEST(CurvedDrift, RenormalisedStaysOnTheGroup) {
  for (int k : {1, -1}) {
    const DriftResult r = measureDrift(k, 20000);
    EXPECT_LT(r.matrix.renormalised, 1e-5) << k;
    EXPECT_LT(r.motor.renormalised, 1e-5) << k;
    EXPECT_EQ(r.matrix.stepOps.mul, 64u);
    EXPECT_EQ(r.matrix.stepOps.add, 48u);
    EXPECT_EQ(r.motor.stepOps.mul, k > 0 ? 32u : 64u);
    EXPECT_EQ(r.motor.renormOps.other, k > 0 ? 2u : 1u);  // inversesqrt
    EXPECT_EQ(r.matrix.renormOps.other, 4u);  // one inversesqrt per column
    EXPECT_EQ(r.matrix.renormOps.div + r.matrix.renormOps.sqrt, 0u);
    std::printf("kappa %+d, %lld steps: matrix raw %.3g renorm %.3g; motor raw %.3g renorm %.3g\n", k,
                (long long)r.steps, r.matrix.raw, r.matrix.renormalised, r.motor.raw, r.motor.renormalised);
  }
}
