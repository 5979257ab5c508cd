// Property tests of normalize_m, sqrt_m, exp_b / log_m (shaders/pga.glsl as C++), 100,000
// seeded cases each, in float and double, plus an independent check of exp_b against the power
// series sum B^k / k! evaluated with gp_mm in double.
#include <gtest/gtest.h>

#include "tests/support/pga_test_support.h"

using namespace mbtest;

template <class S> class PgaNormExp : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(PgaNormExp, Scalars);

namespace {
template <class S> Motor<S> identity() {
  using V4 = typename P<S>::vec4;
  return Motor<S>(V4(S(1), S(0), S(0), S(0)), V4(S(0)));
}
// A Study number a + b e0123 as a motor.
template <class S> Motor<S> study(double a, double b) {
  using V4 = typename P<S>::vec4;
  return Motor<S>(V4(S(a), S(0), S(0), S(0)), V4(S(0), S(0), S(0), S(b)));
}
}  // namespace

// normalize_m(M (a + b e0123)) = M for a unit motor M and any Study number with a > 0 (the
// same rigid motion back), and N ~N = 1 for the normalisation N of any random 8-vector.
TYPED_TEST(PgaNormExp, NormalizeGivesUnitMotorAndSameMotion) {
  using S = TypeParam;
  P<S>& p = mb::pga<S>;
  std::mt19937 g(2001);
  Tracker same, unit;
  for (int i = 0; i < kCases; ++i) {
    const glm::dvec3 t = randomVec(g, -10, 10);
    const Motor<double> M = trsMotor<double>(randomQuat(g), t);
    const double a = uniform(g, 0.1, 10), b = uniform(g, -10, 10);
    const Motor<S> scaled(mb::pga<double>.gp_mm(M, study<double>(a, b)));
    const Motor<S> N = p.normalize_m(scaled);
    // Error unit: the motor's size (1 + |t|/2), amplified by |b|/a through the e0123 correction.
    const double unitSize = 1 + glm::length(t);
    same.check(maxDiff(Motor<double>(N), M), 16 * eps<S>() * unitSize * (1 + std::abs(b) / a), i);

    typename P<S>::vec4 r0, r1;
    for (int k = 0; k < 4; ++k) r0[k] = S(uniform(g, -3, 3)), r1[k] = S(uniform(g, -3, 3));
    const Motor<S> R = p.normalize_m(Motor<S>(r0, r1));
    const double size = maxAbs(Motor<double>(R));
    // dot (4 roundings) + inversesqrt (2) + scaling (1) per factor, squared, plus the check's own
    // product (8): 64 roundings of terms of size |R|^2.
    unit.check(maxDiff(p.gp_mm(R, p.reverse_m(R)), identity<S>()), 64 * eps<S>() * size * size, i);
  }
  EXPECT_LE(same.ratio(), 1.0) << same.report();
  EXPECT_LE(unit.ratio(), 1.0) << unit.report();
}

// sqrt_m(R)^2 = R. 1 + R is normalised, so the error grows like 1 / (1 + s) near s = -1.
TYPED_TEST(PgaNormExp, SqrtSquaredIsTheInput) {
  using S = TypeParam;
  P<S>& p = mb::pga<S>;
  std::mt19937 g(2002);
  Tracker tr;
  for (int i = 0; i < kCases; ++i) {
    const glm::dvec3 t = randomVec(g, -10, 10);
    const Motor<S> R = trsMotor<S>(randomQuat(g), t);
    const double s = double(R[0].x);
    if (s < -0.999) continue;
    const Motor<S> h = p.sqrt_m(R);
    tr.check(maxDiff(p.gp_mm(h, h), R), 32 * eps<S>() * (1 + glm::length(t)) / (1 + s), i);
  }
  EXPECT_LE(tr.ratio(), 1.0) << tr.report();
  // Square roots of a pure translation and a pure rotation are the halves.
  const Motor<S> T = translatorOf<S>(glm::dvec3(2, -4, 6));
  EXPECT_LE(maxDiff(p.sqrt_m(T), translatorOf<S>(glm::dvec3(1, -2, 3))), 4 * eps<S>());
  const Motor<S> Q = rotorOf<S>(glm::angleAxis(1.2, glm::dvec3(0, 0, 1)));
  EXPECT_LE(maxDiff(p.sqrt_m(Q), rotorOf<S>(glm::angleAxis(0.6, glm::dvec3(0, 0, 1)))), 8 * eps<S>());
}

// log_m(exp_b(B)) = B for bivectors with |u| < pi (scalar part > -1). The logarithm divides by
// sin|u|, so the tolerance carries 1 / sin|u| (|u| is kept below 2.8, sin > 0.33).
TYPED_TEST(PgaNormExp, ExpThenLogRoundTrips) {
  using S = TypeParam;
  using L = typename P<S>::line;
  P<S>& p = mb::pga<S>;
  std::mt19937 g(2003);
  Tracker tr;
  for (int i = 0; i < kCases; ++i) {
    const glm::dvec3 u = randomUnit(g) * uniform(g, 0.0, 2.8), v = randomVec(g, -5, 5);
    const L B(vec3Of<S>(u), vec3Of<S>(v));
    const L back = p.log_m(p.exp_b(B));
    const double size = 1 + glm::length(v);
    const double cond = 1 / std::max(std::sin(glm::length(u)), 1e-3);
    tr.check(maxDiff(back, B), 32 * eps<S>() * size * cond, i);
  }
  EXPECT_LE(tr.ratio(), 1.0) << tr.report();
}

// exp_b(log_m(M)) = M for unit motors with scalar part > -0.99. Near s = -1 (a turn by 2 pi,
// the cut locus of log) 1 - s^2 = (1 - s)(1 + s) loses the digits of 1 + s: the condition is
// 1 / (1 + s).
TYPED_TEST(PgaNormExp, LogThenExpRoundTrips) {
  using S = TypeParam;
  P<S>& p = mb::pga<S>;
  std::mt19937 g(2004);
  Tracker tr;
  for (int i = 0; i < kCases; ++i) {
    const glm::dvec3 t = randomVec(g, -10, 10);
    const Motor<S> M = trsMotor<S>(randomQuat(g), t);
    const double s = double(M[0].x);
    if (s < -0.99) continue;
    tr.check(maxDiff(p.exp_b(p.log_m(M)), M), 32 * eps<S>() * (1 + glm::length(t)) / (1 + s), i);
  }
  EXPECT_LE(tr.ratio(), 1.0) << tr.report();
  // Edge cases: the identity and pure translations take the s = 1 branch exactly.
  const Motor<S> T = translatorOf<S>(glm::dvec3(1, 2, 3));
  EXPECT_EQ(maxDiff(p.exp_b(p.log_m(T)), T), 0.0);
  EXPECT_EQ(maxDiff(p.log_m(identity<S>()), typename P<S>::line(Vec3<S>(S(0)), Vec3<S>(S(0)))), 0.0);
}

// Independent definition of exp: the power series with gp_mm, in double (|u| <= 3, 60 terms:
// the remainder is below 3^60/60! ~ 1e-53).
TEST(PgaExpSeries, ExpBEqualsPowerSeries) {
  using S = double;
  using V4 = P<S>::vec4;
  P<S>& p = mb::pga<S>;
  std::mt19937 g(2005);
  Tracker tr;
  for (int i = 0; i < kCases; ++i) {
    const glm::dvec3 u = randomUnit(g) * uniform(g, 0.0, 3.0), v = randomVec(g, -5, 5);
    const Motor<S> Bm(V4(0.0, u.x, u.y, u.z), V4(v.x, v.y, v.z, 0.0));
    Motor<S> term = identity<S>(), sum = identity<S>();
    for (int k = 1; k <= 60; ++k) {
      term = p.gp_mm(term, Bm) * (1.0 / k);
      sum = sum + term;
    }
    const Motor<S> e = p.exp_b(P<S>::line(vec3Of<S>(u), vec3Of<S>(v)));
    tr.check(maxDiff(e, sum), 64 * eps<S>() * (1 + glm::length(v)) * std::exp(glm::length(u)), i);
  }
  EXPECT_LE(tr.ratio(), 1.0) << tr.report();
}
