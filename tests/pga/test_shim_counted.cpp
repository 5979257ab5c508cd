// The op-counting scalar (shaders/shim/counted.h): hand-derived counts of known expressions,
// the counting rules (subtraction = add, negation and comparisons free, literals mix in),
// per-thread counters, and the counts of the shim's vector and matrix operators.
#include <thread>

#include <gtest/gtest.h>

#include "shaders/shim/counted.h"
#include "shaders/shim/glsl.h"

namespace {

#define MB_GLSL_CLASS Builtins
#include "shaders/shim/glsl_begin.h"
#include "shaders/shim/glsl_end.h"

using mb::Counted;
using mb::OpCounts;
using B = Builtins<Counted>;

OpCounts ops(uint64_t mul, uint64_t add, uint64_t div = 0, uint64_t sqrt = 0, uint64_t other = 0) {
  OpCounts c;
  c.mul = mul, c.add = add, c.div = div, c.sqrt = sqrt, c.other = other;
  return c;
}
// Compares the five totals (the per-function array is checked separately).
void expectOps(const OpCounts& got, const OpCounts& want, const char* what) {
  EXPECT_EQ(got.mul, want.mul) << what;
  EXPECT_EQ(got.add, want.add) << what;
  EXPECT_EQ(got.div, want.div) << what;
  EXPECT_EQ(got.sqrt, want.sqrt) << what;
  EXPECT_EQ(got.other, want.other) << what;
}

}  // namespace

TEST(ShimCounted, ScalarRules) {
  const Counted a = 1.5, b = -2.0, c = 4.0;
  Counted r;
  expectOps(mb::countOps([&] { r = a * b + c; }), ops(1, 1), "a*b + c");
  EXPECT_EQ(r.value(), 1.0);
  expectOps(mb::countOps([&] { r = (a - b) / c; }), ops(0, 1, 1), "(a-b)/c");
  expectOps(mb::countOps([&] { r = -a * -b; }), ops(1, 0), "negation is free");
  expectOps(mb::countOps([&] { r = 0.5 - a; }), ops(0, 1), "literal 0.5 - a");
  EXPECT_EQ(r.value(), -1.0);
  expectOps(mb::countOps([&] { r = a * 2. + 1; }), ops(1, 1), "literals mix in");
  expectOps(mb::countOps([&] { r = 1. / a; }), ops(0, 0, 1), "1/a");
  expectOps(mb::countOps([&] { (void)(a < b || a == c || a >= b); }), ops(0, 0), "comparisons are free");
  expectOps(mb::countOps([&] { r = a; r += b; r *= c; r -= a; r /= c; }), ops(1, 2, 1), "compound");
  // Horner a x^2 + b x + c: 2 mul, 2 add.
  expectOps(mb::countOps([&] { r = (a * c + b) * c + a; }), ops(2, 2), "Horner");
}

TEST(ShimCounted, BuiltinsCountAsSqrtOrOther) {
  const Counted x = 0.25;
  OpCounts c = mb::countOps([&] { (void)B::sqrt(x); });
  expectOps(c, ops(0, 0, 0, 1), "sqrt");
  c = mb::countOps([&] { (void)B::inversesqrt(x); (void)B::acos(x); (void)B::sin(x); (void)B::cos(x); });
  expectOps(c, ops(0, 0, 0, 0, 4), "inversesqrt acos sin cos");
  EXPECT_EQ(c.fn[size_t(mb::OpFn::inversesqrt)], 1u);
  EXPECT_EQ(c.fn[size_t(mb::OpFn::acos)], 1u);
  EXPECT_EQ(c.otherCalls(), "1 inversesqrt, 1 sin, 1 cos, 1 acos");
  EXPECT_DOUBLE_EQ(B::inversesqrt(x).value(), 2.0);
}

TEST(ShimCounted, VectorAndMatrixOperators) {
  const B::vec3 a(1, 2, 3), b(4, 5, 6);
  const B::vec4 v(1, 2, 3, 1);
  const B::mat4 M(2.0);
  const B::mat3 R(2.0);
  const B::mat3x4 affine(v, v, v);
  expectOps(mb::countOps([&] { (void)B::dot(a, b); }), ops(3, 2), "dot vec3");
  expectOps(mb::countOps([&] { (void)B::cross(a, b); }), ops(6, 3), "cross");
  expectOps(mb::countOps([&] { (void)B::length(v); }), ops(4, 3, 0, 1), "length vec4");
  expectOps(mb::countOps([&] { (void)B::normalize(a); }), ops(6, 2, 0, 0, 1), "normalize vec3");
  expectOps(mb::countOps([&] { (void)B::mix(a, b, Counted(0.5)); }), ops(3, 6), "mix vec3");
  expectOps(mb::countOps([&] { (void)(a * 2. + b); }), ops(3, 3), "s*v + w");
  expectOps(mb::countOps([&] { (void)(-a); }), ops(0, 0), "-v");
  expectOps(mb::countOps([&] { (void)(M * v); }), ops(16, 12), "mat4*vec4");
  expectOps(mb::countOps([&] { (void)(M * M); }), ops(64, 48), "mat4*mat4");
  expectOps(mb::countOps([&] { (void)(R * a); }), ops(9, 6), "mat3*vec3");
  expectOps(mb::countOps([&] { (void)(v * affine); }), ops(12, 9), "vec4*mat3x4");
  expectOps(mb::countOps([&] { (void)B::mat2x4(1., a, b, 2.); }), ops(0, 0), "constructors are free");
}

TEST(ShimCounted, CountersArePerThreadWithResetAndSnapshot) {
  mb::OpCounter::reset();
  const Counted a = 3.0;
  (void)(a * a);
  std::thread other([&] {
    mb::OpCounter::reset();
    for (int i = 0; i < 10; ++i) (void)(a + a);
    EXPECT_EQ(mb::OpCounter::snapshot().add, 10u);
    EXPECT_EQ(mb::OpCounter::snapshot().mul, 0u);
  });
  other.join();
  const OpCounts here = mb::OpCounter::snapshot();
  EXPECT_EQ(here.mul, 1u);
  EXPECT_EQ(here.add, 0u);
  mb::OpCounter::reset();
  EXPECT_EQ(mb::OpCounter::snapshot(), OpCounts{});
}
