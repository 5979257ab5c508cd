// The GLSL shim (shaders/shim/glsl.h) against GLM: GLSL semantics of the matrix and vector
// operators (column-major, m[i] = column i, mat*vec, vec*mat), constructors, swizzles and
// built-ins, on 100,000 seeded random cases where random data is involved.
#include <random>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "shaders/shim/glsl.h"

namespace {

// A shader class with the prelude only, to reach the built-ins as GLSL code sees them.
#define MB_GLSL_CLASS Builtins
#include "shaders/shim/glsl_begin.h"
#include "shaders/shim/glsl_end.h"

using B = Builtins<float>;
constexpr int kCases = 100000;
constexpr float kEps = 1.1920929e-07f;

float rnd(std::mt19937& g) { return std::uniform_real_distribution<float>(-4.0f, 4.0f)(g); }
B::vec4 rvec4(std::mt19937& g) { return B::vec4(rnd(g), rnd(g), rnd(g), rnd(g)); }
B::vec3 rvec3(std::mt19937& g) { return B::vec3(rnd(g), rnd(g), rnd(g)); }
glm::vec4 G(const B::vec4& v) { return {v.x, v.y, v.z, v.w}; }
glm::vec3 G(const B::vec3& v) { return {v.x, v.y, v.z}; }
glm::mat4 G(const B::mat4& m) { return glm::mat4(G(m[0]), G(m[1]), G(m[2]), G(m[3])); }
glm::mat3 G(const B::mat3& m) { return glm::mat3(G(m[0]), G(m[1]), G(m[2])); }
B::mat4 rmat4(std::mt19937& g) { return B::mat4(rvec4(g), rvec4(g), rvec4(g), rvec4(g)); }
B::mat3 rmat3(std::mt19937& g) { return B::mat3(rvec3(g), rvec3(g), rvec3(g)); }

template <class A, class Bv> float maxDiff(const A& a, const Bv& b, int n) {
  float m = 0;
  for (int i = 0; i < n; ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

}  // namespace

// Same sums in possibly different order: |error| <= n eps sum|a_i b_i| <= n eps n 16.
TEST(ShimGlsl, MatrixProductsMatchGlm) {
  std::mt19937 g(4001);
  float worst = 0;
  for (int i = 0; i < kCases; ++i) {
    const B::mat4 A = rmat4(g), C = rmat4(g);
    const B::mat3 R = rmat3(g);
    const B::vec4 v = rvec4(g);
    const B::vec3 v3 = rvec3(g);
    const float tol4 = 4 * kEps * 4 * 16, tol3 = 3 * kEps * 3 * 16;
    worst = std::max(worst, maxDiff(G(A * v), G(A) * G(v), 4) / tol4);
    worst = std::max(worst, maxDiff(G(v * A), G(v) * G(A), 4) / tol4);  // row vector
    worst = std::max(worst, maxDiff(G(R * v3), G(R) * G(v3), 3) / tol3);
    const B::mat4 AC = A * C;
    const glm::mat4 gAC = G(A) * G(C);
    for (int c = 0; c < 4; ++c) worst = std::max(worst, maxDiff(G(AC[c]), gAC[c], 4) / tol4);
    const B::mat3 RR = R * R;
    const glm::mat3 gRR = G(R) * G(R);
    for (int c = 0; c < 3; ++c) worst = std::max(worst, maxDiff(G(RR[c]), gRR[c], 3) / tol3);
  }
  EXPECT_LE(worst, 1.0f);
}

TEST(ShimGlsl, ColumnMajorLayoutAndConstructors) {
  // m[i] is column i; mat2x4(s, vec3, vec3, s) consumes components column by column.
  const B::mat2x4 m(1.0, B::vec3(2, 3, 4), B::vec3(5, 6, 7), 8.0);
  EXPECT_EQ(m[0], B::vec4(1, 2, 3, 4));
  EXPECT_EQ(m[1], B::vec4(5, 6, 7, 8));
  EXPECT_EQ(B::mat2x4(B::vec4(1, 2, 3, 4), B::vec4(5, 6, 7, 8)), m);
  EXPECT_EQ(B::mat2x4(1.0, m[0].yzw, m[1]), m);
  EXPECT_EQ(B::vec4(1.0f, B::vec3(2, 3, 4)), B::vec4(1, 2, 3, 4));
  EXPECT_EQ(B::vec4(B::vec3(1, 2, 3), 4.0), B::vec4(1, 2, 3, 4));
  EXPECT_EQ(B::vec4(B::vec2(1, 2), B::vec2(3, 4)), B::vec4(1, 2, 3, 4));
  EXPECT_EQ(B::vec4(2.5), B::vec4(2.5, 2.5, 2.5, 2.5));
  EXPECT_EQ(B::vec3(B::vec4(1, 2, 3, 4)), B::vec3(1, 2, 3));
  // mat(s) is s * identity; mat3(mat4) the upper-left block; mat4(mat3) pads with identity.
  const B::mat3 d(2.0);
  EXPECT_EQ(d[0], B::vec3(2, 0, 0));
  EXPECT_EQ(d[2], B::vec3(0, 0, 2));
  std::mt19937 g(4002);
  const B::mat4 A = rmat4(g);
  const B::mat3 A3(A);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(A3[c], B::vec3(A[c]));
  const B::mat4 A4(A3);
  EXPECT_EQ(A4[3], B::vec4(0, 0, 0, 1));
  EXPECT_EQ(A4[0], B::vec4(A3[0], 0.0));
  // GLM agrees on the layout of a translation.
  const glm::mat4 gt = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3));
  const B::mat4 st(B::vec4(1, 0, 0, 0), B::vec4(0, 1, 0, 0), B::vec4(0, 0, 1, 0), B::vec4(1, 2, 3, 1));
  EXPECT_EQ(G(st), gt);
  EXPECT_EQ(B::transpose(st)[3], B::vec4(0, 0, 0, 1));
  EXPECT_EQ(B::transpose(st)[0], B::vec4(1, 0, 0, 1));
  // Scalar-type conversion.
  using D3 = glsl::vec<double, 3>;
  EXPECT_EQ(D3(B::vec3(1, 2, 3)), D3(1, 2, 3));
}

TEST(ShimGlsl, SwizzlesReadTheSharedStorage) {
  B::mat2x4 m(B::vec4(1, 2, 3, 4), B::vec4(5, 6, 7, 8));
  EXPECT_EQ(B::vec3(m[0].yzw), B::vec3(2, 3, 4));
  EXPECT_EQ(B::vec3(m[1].xyz), B::vec3(5, 6, 7));
  EXPECT_EQ(B::vec2(m[0].zw), B::vec2(3, 4));
  EXPECT_EQ(B::vec2(m[0].xy), B::vec2(1, 2));
  const B::vec3 v(1, 2, 3);
  EXPECT_EQ(B::vec2(v.xy), B::vec2(1, 2));
  EXPECT_EQ(B::vec2(v.yz), B::vec2(2, 3));
  EXPECT_EQ(B::vec2(B::vec2(1, 2).yx), B::vec2(2, 1));
  // Swizzles take part in arithmetic through implicit conversion, as in GLSL.
  EXPECT_EQ(2.0f * m[0].yzw + m[1].xyz, B::vec3(9, 12, 15));
  EXPECT_EQ(-m[0].yzw, B::vec3(-2, -3, -4));
  EXPECT_EQ(B::dot(m[0].yzw, m[1].xyz), 2 * 5 + 3 * 6 + 4 * 7.0f);
  // Component writes go to the vector (and are seen by the swizzles).
  m[0].w = 10;
  m[1][0] = -1;
  EXPECT_EQ(B::vec3(m[0].yzw), B::vec3(2, 3, 10));
  EXPECT_EQ(m[1].x, -1.0f);
  // Literals mix in and stay float.
  const B::vec3 h = v * 0.5 + 1.0;
  EXPECT_EQ(h, B::vec3(1.5, 2, 2.5));
}

TEST(ShimGlsl, BuiltinsMatchGlm) {
  std::mt19937 g(4003);
  float worst = 0;
  for (int i = 0; i < kCases; ++i) {
    const B::vec3 a = rvec3(g), b = rvec3(g);
    const float t = std::uniform_real_distribution<float>(0, 1)(g);
    const float tol = 16 * kEps * 16;  // a few roundings of terms up to 4 * 4
    worst = std::max(worst, std::abs(B::dot(a, b) - glm::dot(G(a), G(b))) / tol);
    worst = std::max(worst, maxDiff(G(B::cross(a, b)), glm::cross(G(a), G(b)), 3) / tol);
    worst = std::max(worst, std::abs(B::length(a) - glm::length(G(a))) / tol);
    worst = std::max(worst, std::abs(B::distance(a, b) - glm::distance(G(a), G(b))) / tol);
    worst = std::max(worst, maxDiff(G(B::normalize(a)), glm::normalize(G(a)), 3) / (8 * kEps));
    worst = std::max(worst, maxDiff(G(B::mix(a, b, t)), glm::mix(G(a), G(b), t), 3) / tol);
    worst = std::max(worst, maxDiff(G(B::reflect(a, b)), glm::reflect(G(a), G(b)), 3) / (tol * 16));
    EXPECT_EQ(G(B::min(a, b)), glm::min(G(a), G(b)));
    EXPECT_EQ(G(B::max(a, b)), glm::max(G(a), G(b)));
    EXPECT_EQ(G(B::clamp(a, -1.0, 2.0)), glm::clamp(G(a), -1.0f, 2.0f));
    EXPECT_EQ(G(B::abs(a)), glm::abs(G(a)));
    EXPECT_EQ(G(B::sign(a)), glm::sign(G(a)));
    EXPECT_EQ(G(B::floor(a)), glm::floor(G(a)));
    EXPECT_EQ(B::fract(a.x), a.x - std::floor(a.x));
    worst = std::max(worst, std::abs(B::inversesqrt(std::abs(a.x) + 0.1f) -
                                     glm::inversesqrt(std::abs(a.x) + 0.1f)) / (4 * kEps * 4));
  }
  EXPECT_LE(worst, 1.0f);
  EXPECT_EQ(B::sign(0.0f), 0.0f);
  EXPECT_EQ(B::sign(-3.0f), -1.0f);
  EXPECT_EQ(B::step(1.0f, 0.5f), 0.0f);
  EXPECT_EQ(B::step(1.0f, 1.0f), 1.0f);
  EXPECT_FLOAT_EQ(B::atan(1.0f, 1.0f), std::atan2(1.0f, 1.0f));
  EXPECT_FLOAT_EQ(B::mod(-1.0f, 3.0f), 2.0f);  // GLSL mod: x - y floor(x / y)
}

TEST(ShimGlsl, TypesAreTriviallyCopyableAndPacked) {
  static_assert(std::is_trivially_copyable_v<B::vec3> && std::is_trivially_copyable_v<B::mat4>);
  static_assert(sizeof(B::vec2) == 8 && sizeof(B::vec3) == 12 && sizeof(B::vec4) == 16);
  static_assert(sizeof(B::mat2x3) == 24 && sizeof(B::mat2x4) == 32 && sizeof(B::mat4) == 64);
  SUCCEED();
}
