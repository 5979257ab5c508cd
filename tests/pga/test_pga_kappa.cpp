// shaders/pga_kappa.glsl against independent 4x4 matrices: for S3 (kappa = +1)
// O(4) rotations, for H3 (kappa = -1) O(3,1) rotations and boosts, each built directly with
// GLM in double precision from (coordinate plane, angle). Motors of the same elementary
// isometries are written out by hand here (rotors by the glTF mapping, translators as
// [cos, 0 | -sin e_i, 0] of half the distance). Random words of them, 100,000 seeded cases per
// space: composition equals the matrix product, sandwiches equal matrix * vector for points
// and tangent vectors, results stay on the quadric; kappa = 0 counts equal pga.glsl's.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "shaders/shim/counted.h"
#include "shaders/shim/pga_kappa.h"
#include "tests/support/pga_test_support.h"

namespace {

constexpr int kCases = 100000;

template <class S, int K> using PK = mb::PgaK<S, K>;
template <class S, int K> using KMotor = typename PK<S, K>::motor;
template <class S, int K> using KVec4 = typename PK<S, K>::vec4;

// One elementary isometry: rotation of the coordinate plane (i, j) of R^4 by `angle`
// (j = 3: a translation along axis i by `angle`; in H3 a boost).
struct Elementary {
  int i = 0, j = 1;
  double angle = 0;
};

// The space's bilinear form: dot in S3, Minkowski (+ + + -) in H3.
template <int K> double form(const glm::dvec4& a, const glm::dvec4& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z + double(K) * a.w * b.w;
}

// Independent reference: the matrix, element by element (glm is column-major: m[col][row]).
template <int K> glm::dmat4 matrixOf(const Elementary& e) {
  glm::dmat4 m(1.0);
  if (e.j < 3) {  // e_i turns towards e_j
    const double c = std::cos(e.angle), s = std::sin(e.angle);
    m[e.i][e.i] = c, m[e.j][e.j] = c, m[e.i][e.j] = s, m[e.j][e.i] = -s;
  } else if (K > 0) {  // the origin e_w turns towards e_i
    const double c = std::cos(e.angle), s = std::sin(e.angle);
    m[e.i][e.i] = c, m[3][3] = c, m[3][e.i] = s, m[e.i][3] = -s;
  } else {  // boost in the (i, w) plane: the origin moves to (sinh, cosh)
    const double c = std::cosh(e.angle), s = std::sinh(e.angle);
    m[e.i][e.i] = c, m[3][3] = c, m[e.i][3] = s, m[3][e.i] = s;
  }
  return m;
}

// The motor, written out by hand.
template <class S, int K> KMotor<S, K> motorOf(const Elementary& e) {
  using V4 = KVec4<S, K>;
  if (e.j < 3) {  // rotation from e_i towards e_j: about the axis e_i x e_j
    glm::dvec3 a(0.0), b(0.0);
    a[e.i] = 1.0, b[e.j] = 1.0;
    const glm::dquat q = glm::angleAxis(e.angle, glm::cross(a, b));
    return KMotor<S, K>(V4(S(q.w), S(-q.x), S(-q.y), S(-q.z)), V4(S(0)));
  }
  const double h = 0.5 * e.angle;
  const double c = K > 0 ? std::cos(h) : std::cosh(h), s = K > 0 ? std::sin(h) : std::sinh(h);
  V4 d(S(0));
  d[e.i] = S(-s);
  return KMotor<S, K>(V4(S(c), S(0), S(0), S(0)), d);
}

template <int K> Elementary randomElementary(std::mt19937& g) {
  static const int planes[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
  const int k = std::uniform_int_distribution<int>(0, 5)(g);
  Elementary e{planes[k][0], planes[k][1], 0.0};
  const bool boost = K < 0 && e.j == 3;
  e.angle = boost ? mbtest::uniform(g, -1.2, 1.2) : mbtest::uniform(g, -3.1, 3.1);
  return e;
}

// A random point of the space (the origin moved by a random word) and a tangent vector there.
template <int K> glm::dvec4 randomPoint(std::mt19937& g) {
  glm::dvec4 p(0, 0, 0, 1);
  for (int n = 0; n < 2; ++n) p = matrixOf<K>(randomElementary<K>(g)) * p;
  return p;
}
template <int K> glm::dvec4 randomTangent(std::mt19937& g, const glm::dvec4& p) {
  const glm::dvec4 q(mbtest::randomVec(g, -1, 1), mbtest::uniform(g, -1, 1));
  return q - p * (form<K>(q, p) / form<K>(p, p));  // dot(v, p) = 0 in the space's form
}

template <class S, int K> glm::dvec4 toD(const KVec4<S, K>& v) {
  return {double(v.x), double(v.y), double(v.z), double(v.w)};
}
template <class S, int K> KVec4<S, K> fromD(const glm::dvec4& v) {
  return KVec4<S, K>(S(v.x), S(v.y), S(v.z), S(v.w));
}
double maxAbs(const glm::dvec4& v) {
  return std::max(std::max(std::abs(v.x), std::abs(v.y)), std::max(std::abs(v.z), std::abs(v.w)));
}
double maxAbs(const glm::dmat4& m) {
  double r = 0;
  for (int c = 0; c < 4; ++c) r = std::max(r, maxAbs(m[c]));
  return r;
}

// Words of 1..4 elementary isometries: matrix product vs motor product, then the sandwich of
// a point and a tangent vector. Errors relative to (largest matrix entry) * (largest input).
template <class S, int K> void checkSpace(double tolerance, uint32_t seed) {
  PK<S, K>& P = mb::pgaK<S, K>;
  std::mt19937 g(seed);
  double worstPoint = 0, worstTangent = 0, worstQuadric = 0, worstCompose = 0;
  for (int n = 0; n < kCases; ++n) {
    const int length = 1 + n % 4;
    glm::dmat4 m(1.0);
    KMotor<S, K> M = motorOf<S, K>(Elementary{0, 1, 0.0});
    for (int k = 0; k < length; ++k) {
      const Elementary e = randomElementary<K>(g);
      m = m * matrixOf<K>(e);
      M = P.gp_mm_k(M, motorOf<S, K>(e));
    }
    const glm::dvec4 p = randomPoint<K>(g), v = randomTangent<K>(g, p);
    const double scale = maxAbs(m);
    const glm::dvec4 pm = m * p, vm = m * v;
    const glm::dvec4 ps = toD<S, K>(P.sw_mp_k(M, fromD<S, K>(p)));
    const glm::dvec4 vs = toD<S, K>(P.sw_mp_k(M, fromD<S, K>(v)));
    worstPoint = std::max(worstPoint, maxAbs(ps - pm) / (scale * maxAbs(p)));
    worstTangent = std::max(worstTangent, maxAbs(vs - vm) / (scale * maxAbs(v)));
    // On the quadric: the form of the image equals the form of the input (+-1 for points).
    worstQuadric = std::max(worstQuadric, std::abs(form<K>(ps, ps) - form<K>(p, p)) /
                                              (scale * scale * maxAbs(p) * maxAbs(p)));
    // Composition: the matrix of M (its sandwich of the basis) equals the product.
    if (n % 16 == 0)
      for (int c = 0; c < 4; ++c) {
        glm::dvec4 b(0.0);
        b[c] = 1.0;
        const glm::dvec4 col = toD<S, K>(P.sw_mp_k(M, fromD<S, K>(b)));
        worstCompose = std::max(worstCompose, maxAbs(col - m[c]) / scale);
      }
  }
  EXPECT_LT(worstPoint, tolerance) << "kappa " << K;
  EXPECT_LT(worstTangent, tolerance) << "kappa " << K;
  EXPECT_LT(worstQuadric, 4 * tolerance) << "kappa " << K;
  EXPECT_LT(worstCompose, tolerance) << "kappa " << K;
  std::printf("kappa %+d %s: worst point %.3g tangent %.3g quadric %.3g compose %.3g\n", K,
              sizeof(S) == 4 ? "float" : "double", worstPoint, worstTangent, worstQuadric,
              worstCompose);
}

}  // namespace

TEST(PgaKappa, SphericalMatchesO4Matrices) {
  checkSpace<double, 1>(1e-12, 11);
  checkSpace<float, 1>(2e-5, 12);
}

TEST(PgaKappa, HyperbolicMatchesO31Matrices) {
  checkSpace<double, -1>(1e-12, 21);
  checkSpace<float, -1>(2e-5, 22);
}

// The independent matrices are what they claim: O(4) and O(3,1) (guards the reference).
TEST(PgaKappa, ReferenceMatricesPreserveTheForm) {
  std::mt19937 g(3);
  for (int n = 0; n < 1000; ++n) {
    const glm::dmat4 s = matrixOf<1>(randomElementary<1>(g)), h = matrixOf<-1>(randomElementary<-1>(g));
    const glm::dmat4 eta(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1);
    const glm::dmat4 a = glm::transpose(s) * s, b = glm::transpose(h) * eta * h;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) {
        EXPECT_NEAR(a[c][r], c == r ? 1.0 : 0.0, 1e-12);
        EXPECT_NEAR(b[c][r], eta[c][r], 1e-9);
      }
  }
}

// S3's quaternion pair: same sandwich and composition as the PGA form, round trip exact.
TEST(PgaKappa, SphericalPairFormMatchesMatrices) {
  PK<double, 1>& P = mb::pgaK<double, 1>;
  std::mt19937 g(31);
  double worst = 0;
  for (int n = 0; n < kCases; ++n) {
    const Elementary e1 = randomElementary<1>(g), e2 = randomElementary<1>(g);
    const auto A = P.pair_from_motor(motorOf<double, 1>(e1));
    const auto B = P.pair_from_motor(motorOf<double, 1>(e2));
    const glm::dmat4 m = matrixOf<1>(e1) * matrixOf<1>(e2);
    const glm::dvec4 p = randomPoint<1>(g);
    const glm::dvec4 q = toD<double, 1>(P.sw_pair(P.gp_pair(A, B), fromD<double, 1>(p)));
    worst = std::max(worst, maxAbs(q - m * p));
    const auto back = P.pair_from_motor(P.motor_from_pair(A));
    for (int c = 0; c < 2; ++c) worst = std::max(worst, maxAbs(toD<double, 1>(back[c] - A[c])));
  }
  EXPECT_LT(worst, 1e-12);
}

// normalize_m_k repairs a perturbed unit motor: M ~M = 1 to second order, same motion.
template <int K> void checkNormalize(uint32_t seed) {
  PK<double, K>& P = mb::pgaK<double, K>;
  std::mt19937 g(seed);
  for (int n = 0; n < 10000; ++n) {
    KMotor<double, K> M = P.gp_mm_k(motorOf<double, K>(randomElementary<K>(g)),
                                     motorOf<double, K>(randomElementary<K>(g)));
    KMotor<double, K> D = M;
    for (int c = 0; c < 2; ++c)
      for (int r = 0; r < 4; ++r) D[c][r] += mbtest::uniform(g, -1e-5, 1e-5);
    const KMotor<double, K> N = P.normalize_m_k(D);
    const KMotor<double, K> NN = P.gp_mm_k(N, P.reverse_m(N));
    EXPECT_NEAR(double(NN[0].x), 1.0, 1e-8);
    EXPECT_NEAR(double(NN[1].w), 0.0, 1e-8);
    for (int c = 0; c < 2; ++c)
      for (int r = 0; r < 4; ++r) EXPECT_NEAR(double(N[c][r]), double(M[c][r]), 1e-4);
  }
}
TEST(PgaKappa, NormalizeRepairsDrift) {
  checkNormalize<1>(41);
  checkNormalize<-1>(42);
}

// translator_k moves the origin by `dist` along u: the matrices' translation column.
TEST(PgaKappa, TranslatorMovesTheOriginByTheDistance) {
  for (int axis = 0; axis < 3; ++axis)
    for (double dist : {-1.0, 0.3, 2.0}) {
      glm::dvec3 u(0.0);
      u[axis] = 1.0;
      const Elementary e{axis, 3, dist};
      auto& S = mb::pgaK<double, 1>;
      auto& H = mb::pgaK<double, -1>;
      const glm::dvec4 o(0, 0, 0, 1);
      const auto uS = typename PK<double, 1>::vec3(u.x, u.y, u.z);
      const auto uH = typename PK<double, -1>::vec3(u.x, u.y, u.z);
      const glm::dvec4 s = toD<double, 1>(S.sw_mp_k(S.translator_k(dist, uS), fromD<double, 1>(o)));
      const glm::dvec4 h = toD<double, -1>(H.sw_mp_k(H.translator_k(dist, uH), fromD<double, -1>(o)));
      EXPECT_LT(maxAbs(s - matrixOf<1>(e) * o), 1e-14);
      EXPECT_LT(maxAbs(h - matrixOf<-1>(e) * o), 1e-13);
    }
}

// ---- op counts ------------------------------------------------------------------------------

namespace {
template <int K, class F> mb::OpCounts count(F f) {
  using C = mb::Counted;
  PK<C, K>& P = mb::pgaK<C, K>;
  const KMotor<C, K> a(KVec4<C, K>(C(0.5), C(0.1), C(0.2), C(0.3)), KVec4<C, K>(C(0.4), C(0.5), C(0.6), C(0.7)));
  const KMotor<C, K> b(KVec4<C, K>(C(0.7), C(0.6), C(0.5), C(0.4)), KVec4<C, K>(C(0.3), C(0.2), C(0.1), C(0.9)));
  mb::OpCounter::reset();
  f(P, a, b);
  return mb::OpCounter::snapshot();
}
void expectCount(const mb::OpCounts& c, uint64_t mul, uint64_t add, const char* what) {
  EXPECT_EQ(c.mul, mul) << what;
  EXPECT_EQ(c.add, add) << what;
}
}  // namespace

// kappa = 0 reproduces pga.glsl exactly: gp_mm 48/40, sw_mp 21/18, normalize_m 22/10.
TEST(PgaKappaOpCount, EuclideanVariantCountsAsToday) {
  expectCount(count<0>([](auto& P, auto a, auto b) { P.gp_mm_k(a, b); }), 48, 40, "gp_mm_k");
  expectCount(count<0>([](auto& P, auto a, auto) { P.sw_mp_k(a, typename std::decay_t<decltype(P)>::vec3(0.1, 0.2, 0.3)); }), 21, 18, "sw_mp_k");
  const auto n = count<0>([](auto& P, auto a, auto) { P.normalize_m_k(a); });
  expectCount(n, 22, 10, "normalize_m_k");
  EXPECT_EQ(n.other, 1u);
}

// The "measured:" lines of pga_kappa.glsl for kappa = +1 and -1.
template <int K> void curvedCounts() {
  using V4 = KVec4<mb::Counted, K>;
  expectCount(count<K>([](auto& P, auto a, auto b) { P.gp_mm_k(a, b); }), 64, 56, "gp_mm_k");
  expectCount(count<K>([](auto& P, auto a, auto) { P.sw_mp_k(a, V4(0.1, 0.2, 0.3, 0.9)); }), 64, 48, "sw_mp_k");
  const auto n = count<K>([](auto& P, auto a, auto) { P.normalize_m_k(a); });
  expectCount(n, 30, 18, "normalize_m_k");
  EXPECT_EQ(n.other, 1u);
  const auto t = count<K>([](auto& P, auto, auto) {
    P.translator_k(mb::Counted(0.3), typename std::decay_t<decltype(P)>::vec3(0.0, 1.0, 0.0));
  });
  expectCount(t, K > 0 ? 5 : 6, K > 0 ? 0 : 2, "translator_k");
  EXPECT_EQ(t.div, K > 0 ? 0u : 1u);
  EXPECT_EQ(t.other, K > 0 ? 2u : 1u);
}
TEST(PgaKappaOpCount, CurvedVariants) {
  curvedCounts<1>();
  curvedCounts<-1>();
}

TEST(PgaKappaOpCount, SphericalPairForm) {
  using V4 = KVec4<mb::Counted, 1>;
  expectCount(count<1>([](auto& P, auto a, auto b) { P.gp_pair(a, b); }), 32, 24, "gp_pair");
  expectCount(count<1>([](auto& P, auto a, auto) { P.sw_pair(a, V4(0.1, 0.2, 0.3, 0.9)); }), 32, 24, "sw_pair");
  expectCount(count<1>([](auto& P, auto a, auto) { P.pair_from_motor(a); }), 0, 8, "pair_from_motor");
  expectCount(count<1>([](auto& P, auto a, auto) { P.motor_from_pair(a); }), 8, 8, "motor_from_pair");
  const auto n = count<1>([](auto& P, auto a, auto) { P.normalize_pair(a); });
  expectCount(n, 16, 6, "normalize_pair");
  EXPECT_EQ(n.other, 2u);
}

// Per vertex of the curved pipelines (shaders/curved_transform.glsl): position and normal.
template <int K> void vertexCounts(uint64_t motorMul, uint64_t motorAdd) {
  using C = mb::Counted;
  using V4 = KVec4<C, K>;
  auto& P = mb::pgaK<C, K>;
  const typename PK<C, K>::mat4 m(C(0.5));
  const V4 p(C(0.1), C(0.2), C(0.3), C(0.9)), n(C(0.3), C(0.2), C(0.1), C(0.0));
  const KMotor<C, K> a(V4(C(0.5), C(0.1), C(0.2), C(0.3)), V4(C(0.4), C(0.5), C(0.6), C(0.7)));
  expectCount(mb::countOps([&] { P.curvedMatrixVertex(m, m, p, n); }), 64, 48, "curvedMatrixVertex");
  expectCount(mb::countOps([&] { P.curvedMotorVertex(a, a, p, n); }), motorMul, motorAdd, "curvedMotorVertex");
}
TEST(PgaKappaOpCount, CurvedVertexTransforms) {
  vertexCounts<1>(96, 72);
  vertexCounts<-1>(192, 152);
}
