// Property tests of shaders/pga.glsl (compiled as C++) against GLM in double precision:
// sandwiches equal the node's 4x4 matrix, gp_mm equals the matrix product, every specialised
// product equals gp_mm on its domain, and the glTF conventions, exp_r/exp_t and project().
// Each property runs on 100,000 seeded random cases, in float and in double. Tolerances are
// K * epsilon(S) * (magnitude of the data): K counts rounding steps, so the double run proves
// the formulas exact while the float run bounds the GPU-precision error.
#define GLM_ENABLE_EXPERIMENTAL  // glm::rotation (shortest-arc quaternion)
#include <cstring>

#include <glm/gtx/quaternion.hpp>
#include <gtest/gtest.h>

#include "pipelines/motor/companion.h"
#include "tests/support/pga_test_support.h"

using namespace mbtest;

template <class S> class PgaProducts : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(PgaProducts, Scalars);

// Points and translations up to 10 in each coordinate; the data magnitude is 1 + |t| + |p|.
TYPED_TEST(PgaProducts, SandwichOfPointAndDirectionEqualsMatrix) {
  using S = TypeParam;
  P<S>& p = mb::pga<S>;
  std::mt19937 g(1001);
  Tracker point, naive, dir;
  for (int i = 0; i < kCases; ++i) {
    const glm::dquat q = randomQuat(g);
    const glm::dvec3 t = randomVec(g, -10, 10), x = randomVec(g, -10, 10), d = randomVec(g, -1, 1);
    const Motor<S> M = trsMotor<S>(q, t);
    const glm::dmat4 G = trsMatrix(q, t);
    const double scale = 1 + glm::length(t) + glm::length(x);
    const glm::dvec3 want = glm::dvec3(G * glm::dvec4(x, 1.0));
    point.check(maxDiff(toD<S>(p.sw_mp(M, vec3Of<S>(x))), want), 16 * eps<S>() * scale, i);
    naive.check(maxDiff(toD<S>(p.sw_mp_naive(M, vec3Of<S>(x))), want), 16 * eps<S>() * scale, i);
    dir.check(maxDiff(toD<S>(p.sw_md(M, vec3Of<S>(d))), glm::dvec3(G * glm::dvec4(d, 0.0))),
              16 * eps<S>(), i);
  }
  EXPECT_LE(point.ratio(), 1.0) << "sw_mp " << point.report();
  EXPECT_LE(naive.ratio(), 1.0) << "sw_mp_naive " << naive.report();
  EXPECT_LE(dir.ratio(), 1.0) << "sw_md " << dir.report();
}

// sw_mx/my/mz are half the matrix's basis columns, sw_mo its translation column.
TYPED_TEST(PgaProducts, BasisSandwichesAreHalfTheMatrixColumns) {
  using S = TypeParam;
  P<S>& p = mb::pga<S>;
  std::mt19937 g(1002);
  Tracker cols, origin;
  for (int i = 0; i < kCases; ++i) {
    const glm::dquat q = randomQuat(g);
    const glm::dvec3 t = randomVec(g, -10, 10);
    const Motor<S> M = trsMotor<S>(q, t);
    const glm::dmat4 G = trsMatrix(q, t);
    const double e = std::max({maxDiff(2.0 * toD<S>(p.sw_mx(M)), glm::dvec3(G[0])),
                               maxDiff(2.0 * toD<S>(p.sw_my(M)), glm::dvec3(G[1])),
                               maxDiff(2.0 * toD<S>(p.sw_mz(M)), glm::dvec3(G[2]))});
    cols.check(e, 8 * eps<S>(), i);
    origin.check(maxDiff(toD<S>(p.sw_mo(M)), glm::dvec3(G[3])), 8 * eps<S>() * (1 + glm::length(t)), i);
    // extractNormalTangent = (sw_mz, sw_mx) on the rotor half.
    const typename P<S>::mat2x3 nt = p.extractNormalTangent(M);
    EXPECT_EQ(toD<S>(nt[0]), toD<S>(p.sw_mz(M)));
    EXPECT_EQ(toD<S>(nt[1]), toD<S>(p.sw_mx(M)));
  }
  EXPECT_LE(cols.ratio(), 1.0) << cols.report();
  EXPECT_LE(origin.ratio(), 1.0) << origin.report();
}

TYPED_TEST(PgaProducts, GpMmEqualsMatrixProduct) {
  using S = TypeParam;
  P<S>& p = mb::pga<S>;
  std::mt19937 g(1003);
  Tracker tr;
  for (int i = 0; i < kCases; ++i) {
    const glm::dquat q1 = randomQuat(g), q2 = randomQuat(g);
    const glm::dvec3 t1 = randomVec(g, -10, 10), t2 = randomVec(g, -10, 10);
    const Motor<S> M = p.gp_mm(trsMotor<S>(q1, t1), trsMotor<S>(q2, t2));
    const glm::dmat4 G = trsMatrix(q1, t1) * trsMatrix(q2, t2);
    tr.check(maxDiff(matrixOf<S>(M), G), 32 * eps<S>() * (1 + glm::length(t1) + glm::length(t2)), i);
  }
  EXPECT_LE(tr.ratio(), 1.0) << tr.report();
}

// Every gp_xy equals gp_mm on its domain (r: rotor about the origin, t: translator, m: any
// motor). The products are bilinear, so unnormalised operands are used; the error unit is
// |a| |b| (largest coefficients).
TYPED_TEST(PgaProducts, SpecialisedProductsEqualGpMm) {
  using S = TypeParam;
  using V4 = typename P<S>::vec4;
  P<S>& p = mb::pga<S>;
  std::mt19937 g(1004);
  auto r4 = [&] { return V4(S(uniform(g, -2, 2)), S(uniform(g, -2, 2)), S(uniform(g, -2, 2)), S(uniform(g, -2, 2))); };
  auto rotor = [&] { return Motor<S>(r4(), V4(S(0))); };
  auto trans = [&] { return Motor<S>(V4(S(1), S(0), S(0), S(0)), V4(S(uniform(g, -5, 5)), S(uniform(g, -5, 5)), S(uniform(g, -5, 5)), S(0))); };
  auto general = [&] { return Motor<S>(r4(), r4()); };
  Tracker tr[8];
  const char* names[8] = {"gp_rr", "gp_tt", "gp_rt", "gp_tr", "gp_rm", "gp_mr", "gp_tm", "gp_mt"};
  for (int i = 0; i < kCases; ++i) {
    const Motor<S> r1 = rotor(), r2 = rotor(), t1 = trans(), t2 = trans(), m1 = general();
    auto chk = [&](int k, const Motor<S>& got, const Motor<S>& a, const Motor<S>& b) {
      tr[k].check(maxDiff(got, p.gp_mm(a, b)), 16 * eps<S>() * maxAbs(a) * maxAbs(b), i);
    };
    chk(0, p.gp_rr(r1, r2), r1, r2);
    chk(1, p.gp_tt(t1, t2), t1, t2);
    chk(2, p.gp_rt(r1, t1), r1, t1);
    chk(3, p.gp_tr(t1, r1), t1, r1);
    chk(4, p.gp_rm(r1, m1), r1, m1);
    chk(5, p.gp_mr(m1, r1), m1, r1);
    chk(6, p.gp_tm(t1, m1), t1, m1);
    chk(7, p.gp_mt(m1, t1), m1, t1);
  }
  for (int k = 0; k < 8; ++k) EXPECT_LE(tr[k].ratio(), 1.0) << names[k] << " " << tr[k].report();
}

// gp_vv(b, a) of unit vectors is the rotor of twice the angle a -> b; its square root moves a
// onto b (and is the rotor GLM's shortest-arc quaternion gives).
TYPED_TEST(PgaProducts, GpVvSquareRootRotatesAOntoB) {
  using S = TypeParam;
  P<S>& p = mb::pga<S>;
  std::mt19937 g(1005);
  Tracker tr;
  int tested = 0;
  for (int i = 0; i < kCases; ++i) {
    const glm::dvec3 a = randomUnit(g), b = randomUnit(g);
    const double c = glm::dot(a, b);
    if (c < -0.9) continue;  // sqrt_m is ill-conditioned near a = -b (documented)
    ++tested;
    const Motor<S> R = p.sqrt_m(p.gp_vv(vec3Of<S>(b), vec3Of<S>(a)));
    tr.check(maxDiff(toD<S>(p.sw_md(R, vec3Of<S>(a))), b), 32 * eps<S>() / (1 + c), i);
    const glm::dquat gq = glm::rotation(a, b);
    tr.check(diffUpToSign<S>(R, rotorOf<S>(gq)), 32 * eps<S>() / (1 + c), i);
  }
  EXPECT_GT(tested, kCases * 9 / 10);
  EXPECT_LE(tr.ratio(), 1.0) << tr.report();
}

// exp_r(angle, B) = [cos angle, sin angle B[0]]: the quaternion angleAxis(-2 angle, axis);
// exp_t(d, B) translates by -2 d B[1] (the reference's conventions).
TYPED_TEST(PgaProducts, ExpRAndExpTFollowTheReferenceConventions) {
  using S = TypeParam;
  using L = typename P<S>::line;
  P<S>& p = mb::pga<S>;
  std::mt19937 g(1006);
  Tracker rot, trn;
  for (int i = 0; i < kCases; ++i) {
    const glm::dvec3 axis = randomUnit(g), dir = randomVec(g, -3, 3), x = randomVec(g, -10, 10);
    const double angle = uniform(g, -4, 4), dist = uniform(g, -4, 4);
    const Motor<S> R = p.exp_r(S(angle), L(vec3Of<S>(axis), Vec3<S>(S(0))));
    rot.check(maxDiff(R, rotorOf<S>(glm::angleAxis(-2.0 * angle, axis))), 8 * eps<S>() * (1 + std::abs(angle)), i);
    const Motor<S> T = p.exp_t(S(dist), L(Vec3<S>(S(0)), vec3Of<S>(dir)));
    trn.check(maxDiff(toD<S>(p.sw_mp(T, vec3Of<S>(x))), x - 2.0 * dist * dir),
              8 * eps<S>() * (1 + glm::length(x) + 2 * std::abs(dist) * glm::length(dir)), i);
  }
  EXPECT_LE(rot.ratio(), 1.0) << rot.report();
  EXPECT_LE(trn.ratio(), 1.0) << trn.report();
}

// project(n, f, minfov, aspect, p) = perspective(minfov, aspect, n, f) * (-p.x, p.y, -p.z, 1).
TYPED_TEST(PgaProducts, ProjectEqualsGlmPerspectiveOfTheTurnedPoint) {
  using S = TypeParam;
  P<S>& p = mb::pga<S>;
  std::mt19937 g(1007);
  Tracker tr;
  for (int i = 0; i < kCases; ++i) {
    const double n = uniform(g, 0.01, 1), f = n * uniform(g, 10, 1000), fov = uniform(g, 0.2, 2.5),
                 aspect = uniform(g, 0.5, 3);
    const glm::dvec3 x = glm::dvec3(uniform(g, -10, 10), uniform(g, -10, 10), uniform(g, n, f));
    const glm::dvec4 want = glm::perspective(fov, aspect, n, f) * glm::dvec4(-x.x, x.y, -x.z, 1.0);
    const typename P<S>::vec4 got = p.project(S(n), S(f), S(fov), S(aspect), vec3Of<S>(x));
    double err = 0, mag = 1;
    for (int k = 0; k < 4; ++k) {
      err = std::max(err, std::abs(double(got[k]) - want[k]));
      mag = std::max(mag, std::abs(want[k]));
    }
    // fa = 2fn/(n-f) and fb = (n+f)/(n-f) are recomputed from rounded inputs: relative error
    // of a few eps on terms of the size of the output.
    tr.check(err, 32 * eps<S>() * mag, i);
  }
  EXPECT_LE(tr.ratio(), 1.0) << tr.report();
}

// The glTF mapping of the companion (float) against GLM's TRS matrix.
TEST(PgaGltf, CompanionTrsMotorMatchesGlmMatrix) {
  namespace c = mb::companion;
  std::mt19937 g(1008);
  Tracker tr;
  for (int i = 0; i < kCases; ++i) {
    const glm::dquat q = randomQuat(g);
    const glm::dvec3 t = randomVec(g, -10, 10);
    const c::Motor M = c::motorFromTRS(glm::vec3(t), glm::quat(q));
    tr.check(maxDiff(matrixOf<float>(M), trsMatrix(q, t)), 16 * eps<float>() * (1 + glm::length(t)), i);
  }
  EXPECT_LE(tr.ratio(), 1.0) << tr.report();
}

TEST(PgaGltf, ShimLayoutIsTheGpuLayout) {
  using P = mb::Pga<float>;
  static_assert(sizeof(P::vec3) == 12 && sizeof(P::vec4) == 16 && sizeof(P::motor) == 32);
  static_assert(std::is_trivially_copyable_v<P::motor>);
  const P::motor M(P::vec4(1, 2, 3, 4), P::vec4(5, 6, 7, 8));
  float f[8];
  std::memcpy(f, &M, sizeof f);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(f[i], float(i + 1));
}
