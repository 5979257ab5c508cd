// Tests of the CPU companion (pipelines/motor/companion.h): matrix <-> motor with the scale
// check and tangent rotors with the handedness rule, exhaustively on frames whose rotor scalar
// part is exactly 0.
#include <gtest/gtest.h>

#include "pipelines/motor/companion.h"
#include "tests/support/pga_test_support.h"

using namespace mbtest;
namespace c = mb::companion;
using F = P<float>;

namespace {

constexpr double kEps = eps<float>();

glm::dmat4 scaled(const glm::dmat4& m, const glm::dvec3& s) {
  return m * glm::scale(glm::dmat4(1.0), s);
}
double maxDiffF(const glm::mat4& a, const glm::dmat4& b) { return maxDiff(glm::dmat4(a), b); }

}  // namespace

TEST(PgaCompanion, MotorToMatrixToMotorRoundTripsUpToSign) {
  std::mt19937 g(3001);
  Tracker mat, back;
  for (int i = 0; i < kCases; ++i) {
    const glm::dquat q = randomQuat(g);
    const glm::dvec3 t = randomVec(g, -10, 10);
    const c::Motor M = trsMotor<float>(q, t);
    const glm::mat4 G = c::motorToMatrix(M);
    mat.check(maxDiffF(G, trsMatrix(q, t)), 16 * kEps * (1 + glm::length(t)), i);
    const c::MatrixMotor mm = c::motorFromMatrix(G);
    EXPECT_EQ(mm.kind, c::ScaleKind::Rigid);
    EXPECT_FALSE(mm.negative || mm.sheared || mm.degenerate);
    back.check(diffUpToSign<float>(mm.motor, M), 16 * kEps * (1 + glm::length(t)), i);
  }
  EXPECT_LE(mat.ratio(), 1.0) << mat.report();
  EXPECT_LE(back.ratio(), 1.0) << back.report();
}

// matrix = T R diag(scale): the companion returns the motor T R and the scale, classifies it,
// flags reflections (all three scales negated, so that motor-matrix * diag(scale) = matrix).
// A mirror of one axis with equal magnitudes is a uniform negative scale times a half turn.
TEST(PgaCompanion, ScaleCheckClassifiesAndReconstructs) {
  std::mt19937 g(3002);
  Tracker rebuild, motor;
  for (int i = 0; i < kCases; ++i) {
    const glm::dquat q = randomQuat(g);
    const glm::dvec3 t = randomVec(g, -10, 10);
    // uniform, non-uniform, negative uniform, one mirrored axis, non-uniform + mirrored axis
    const int kind = i % 5;
    double s = uniform(g, 0.1, 10);
    if (std::abs(s - 1) < 0.1) s += 0.2;  // keep clear of the rigid class (|s - 1| <= 1e-4)
    glm::dvec3 sc(s);
    if (kind == 1 || kind == 4) sc = glm::dvec3(s, s * uniform(g, 1.01, 3), s / uniform(g, 1.01, 3));
    if (kind == 2) sc = -sc;
    if (kind == 3 || kind == 4) sc.y = -sc.y;
    const glm::dmat4 G = scaled(trsMatrix(q, t), sc);
    const c::MatrixMotor mm = c::motorFromMatrix(glm::mat4(G));
    const bool neg = kind >= 2;
    EXPECT_EQ(mm.negative, neg) << i;
    EXPECT_FALSE(mm.sheared) << i;
    const c::ScaleKind want = kind == 1 || kind == 4 ? c::ScaleKind::NonUniform : c::ScaleKind::Uniform;
    EXPECT_EQ(mm.kind, want) << i;
    // Reflections move the sign into the scale: -|s| on every axis.
    const glm::dvec3 expectScale = neg ? -glm::abs(sc) : sc;
    const double smax = std::max({std::abs(sc.x), std::abs(sc.y), std::abs(sc.z)});
    rebuild.check(maxDiff(glm::dvec3(mm.scale), expectScale), 8 * kEps * smax, i);
    const glm::dmat4 R = scaled(glm::dmat4(c::motorToMatrix(mm.motor)), glm::dvec3(mm.scale));
    rebuild.check(maxDiff(R, G), 32 * kEps * (smax + glm::length(t)), i);
    if (kind == 0) {
      motor.check(diffUpToSign<float>(mm.motor, trsMotor<float>(q, t)), 32 * kEps * (1 + glm::length(t)), i);
      EXPECT_NEAR(mm.uniformScale(), s, 8 * kEps * s);
    }
  }
  EXPECT_LE(rebuild.ratio(), 1.0) << rebuild.report();
  EXPECT_LE(motor.ratio(), 1.0) << motor.report();
  // The exact-1 case.
  EXPECT_EQ(c::motorFromMatrix(glm::mat4(1.0f)).kind, c::ScaleKind::Rigid);
}

TEST(PgaCompanion, ShearAndDegenerateMatricesAreFlagged) {
  glm::mat4 shear(1.0f);
  shear[1][0] = 0.3f;  // y column leans towards x
  EXPECT_TRUE(c::motorFromMatrix(shear).sheared);
  glm::mat4 flat(1.0f);
  flat[2] = glm::vec4(0.0f);
  flat[3] = glm::vec4(1, 2, 3, 1);
  const c::MatrixMotor d = c::motorFromMatrix(flat);
  EXPECT_TRUE(d.degenerate);
  // Still the translation.
  EXPECT_EQ(glm::vec3(c::motorToMatrix(d.motor)[3]), glm::vec3(1, 2, 3));
}

// ---- tangent rotors -------------------------------------------------------------------------

namespace {

// Encode -> decode error bound: float rounding of the conversion (16 eps) plus the documented
// clamp, which turns the frame by at most 2 * kMinTangentScalar.
double frameTolerance(bool clamped) { return 16 * kEps + (clamped ? 2 * c::kMinTangentScalar : 0.0); }

struct FrameCheck {
  Tracker tr;
  int wrongSign = 0, zeroScalar = 0, cases = 0;
  void run(const glm::dvec3& n, const glm::dvec3& t, float w, int i) {
    const c::TangentRotor r = c::encodeTangentRotor(glm::vec3(n), glm::vec3(t), w);
    // Decoded by the vertex shader's functions (motor_transform.glsl), normalised as forward.fs does.
    const mb::MK::vec4 R(r.rotor.x, r.rotor.y, r.rotor.z, r.rotor.w);
    const mb::MK::mat2x3 f = mb::mk().rotorFrame(R);
    auto unit = [&f](int c) { return glm::normalize(glm::dvec3(f[c].x, f[c].y, f[c].z)); };
    ++cases;
    zeroScalar += r.scalarWasZero;
    // Handedness must be exact, by every decoder the GPU side may use (motorHandedness: sign(1 / s)).
    if (mb::mk().motorHandedness(R) != w || (r.rotor.x < 0) != (w < 0) || r.rotor.x == 0.0f) ++wrongSign;
    // 16-bit SNORM storage keeps it (|s| >= 1/32767 rounds to a non-zero integer).
    if (std::lround(double(r.rotor.x) * 32767.0) == 0) ++wrongSign;
    tr.check(std::max(maxDiff(unit(0), n), maxDiff(unit(1), t)), frameTolerance(r.clamped), i);
    // The rotor is unit (within rounding).
    tr.check(std::abs(double(glm::length(r.rotor)) - 1), 16 * kEps, i);
  }
};

}  // namespace

TEST(PgaTangentRotor, RandomFramesRoundTripWithExactHandedness) {
  std::mt19937 g(3005);
  FrameCheck fc;
  for (int i = 0; i < kCases; ++i) {
    const glm::dvec3 n = randomUnit(g), a = randomUnit(g);
    const glm::dvec3 t = glm::normalize(a - n * glm::dot(n, a));
    fc.run(n, t, (i & 1) ? 1.0f : -1.0f, i);
  }
  EXPECT_EQ(fc.wrongSign, 0);
  EXPECT_LE(fc.tr.ratio(), 1.0) << fc.tr.report();
}

// All 24 axis-aligned frames (normal and tangent along +-x, +-y, +-z) with both handedness
// values. Nine of them are 180-degree turns of the basis frame, whose rotor scalar is exactly
// 0 (the reference implementation stores the wrong handedness for these when w = +1).
TEST(PgaTangentRotor, AxisAlignedFramesIncludingZeroScalarExhaustive) {
  const glm::dvec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  FrameCheck fc;
  int i = 0;
  for (const auto& n : axes)
    for (const auto& t : axes) {
      if (glm::dot(n, t) != 0.0) continue;
      for (float w : {1.0f, -1.0f}) fc.run(n, t, w, i++);
    }
  EXPECT_EQ(fc.cases, 48);
  EXPECT_EQ(fc.zeroScalar, 18);  // 9 frames x 2 handedness values
  EXPECT_EQ(fc.wrongSign, 0);
  EXPECT_LE(fc.tr.ratio(), 1.0) << fc.tr.report();
}

// The reference's rule (negate when Math.sign(s) != w, decode sign(1/s)) on the same frames:
// documents the failure the companion's rule fixes.
TEST(PgaTangentRotor, ReferenceRuleFailsOnZeroScalarFrames) {
  const glm::vec3 n(0, 0, -1), t(-1, 0, 0);  // 180 degrees about y: scalar part exactly 0
  const c::TangentRotor ours = c::encodeTangentRotor(n, t, 1.0f);
  ASSERT_TRUE(ours.scalarWasZero);
  // Reference: rotor with s = +-0; Math.sign(+-0) = +-0 != 1, so it negates.
  glm::vec4 ref = ours.rotor;
  ref.x = 0.0f;
  // (component-wise: GLM's unary minus computes 0 - x, which turns -0 into +0)
  if (!(F::sign(ref.x) == 1.0f)) ref = glm::vec4(-ref.x, -ref.y, -ref.z, -ref.w);
  EXPECT_EQ(F::sign(1.0f / ref.x), -1.0f);  // wrong: w was +1
  EXPECT_EQ(F::sign(1.0f / ours.rotor.x), 1.0f);  // ours: right
}

// Frames near and at 180-degree turns about random axes (R = 2 a a^T - I, then a tiny
// perturbation): the scalar is 0 or tiny with either sign.
TEST(PgaTangentRotor, HalfTurnFramesAboutRandomAxes) {
  std::mt19937 g(3006);
  FrameCheck fc;
  for (int i = 0; i < kCases; ++i) {
    const glm::dvec3 a = randomUnit(g);
    glm::dmat3 R = 2.0 * glm::outerProduct(a, a) - glm::dmat3(1.0);
    if (i % 2) R = glm::dmat3(glm::mat4_cast(glm::angleAxis(uniform(g, -1e-4, 1e-4), randomUnit(g)))) * R;
    fc.run(R[2], R[0], (i & 2) ? 1.0f : -1.0f, i);
  }
  EXPECT_EQ(fc.wrongSign, 0);
  EXPECT_LE(fc.tr.ratio(), 1.0) << fc.tr.report();
}

// What motor.vs does: compose the world rotor with the vertex rotor (gp_rr), extract normal and
// tangent: equals the world motor applied to the vertex's normal and tangent.
TEST(PgaTangentRotor, WorldCompositionMatchesSandwichedFrame) {
  std::mt19937 g(3007);
  F& p = mb::pga<float>;
  Tracker tr;
  for (int i = 0; i < kCases; ++i) {
    const glm::dquat q = randomQuat(g);
    const c::Motor W = trsMotor<float>(q, randomVec(g, -10, 10));
    const glm::dvec3 n = randomUnit(g), a = randomUnit(g);
    const glm::dvec3 t = glm::normalize(a - n * glm::dot(n, a));
    const c::TangentRotor r = c::encodeTangentRotor(glm::vec3(n), glm::vec3(t), 1.0f);
    const c::Motor vr(F::vec4(r.rotor.x, r.rotor.y, r.rotor.z, r.rotor.w), F::vec4(0.0f));
    const F::mat2x3 nt = p.extractNormalTangent(p.gp_rr(W, vr));
    const glm::dmat3 Q = glm::mat3_cast(q);
    tr.check(std::max(maxDiff(2.0 * toD<float>(nt[0]), Q * n), maxDiff(2.0 * toD<float>(nt[1]), Q * t)),
             32 * kEps + (r.clamped ? 2 * c::kMinTangentScalar : 0.0), i);
  }
  EXPECT_LE(tr.ratio(), 1.0) << tr.report();
}
