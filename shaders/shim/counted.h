// shaders/shim/counted.h: mb::Counted, an op-counting scalar for the GLSL shim.
//
// Every arithmetic operation on a Counted increments a thread_local counter:
//   a * b  -> mul          a + b, a - b -> add (subtraction counts as addition)
//   a / b  -> div          sqrt(a)      -> sqrt
//   any other built-in (inversesqrt, sin, cos, tan, asin, acos, atan, exp, log, exp2, log2, pow,
//   abs, sign, floor, ceil, min, max) -> other, and per function in OpCounts::fn.
// Free: unary minus and plus (a sign flip is a modifier on GPUs), comparisons, copies,
// construction from literals, conversions. Composite built-ins (dot, cross, length, normalize,
// mix, clamp, fract, mod) are counted through the scalar operations they expand to in the shim,
// e.g. dot(vec3, vec3) = 3 mul + 2 add, normalize(vec3) = 6 mul + 2 add + 1 inversesqrt.
//
// Literals mix in: `0.5 - x`, `x * 2.`, `1. / x` convert the double to Counted (free) and
// count the operation. The value is carried in double precision so that branches taken while
// counting (e.g. `if (l == 0.)`) behave like the real computation.
//
// Usage:
//   mb::OpCounter::reset();
//   ... run code on mb::Counted ...
//   mb::OpCounts c = mb::OpCounter::snapshot();   // c.mul, c.add, c.div, c.sqrt, c.other
//   // or scoped: mb::OpCounts c = mb::countOps([&] { ... });
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>

#include "shaders/shim/glsl.h"

namespace mb {

// The built-ins that count as "other", in OpCounts::fn order.
enum class OpFn : int {
  inversesqrt, sin, cos, tan, asin, acos, atan, exp, log, exp2, log2, pow, abs, sign, floor,
  ceil, min, max, count_
};
inline constexpr const char* kOpFnNames[] = {"inversesqrt", "sin", "cos", "tan", "asin", "acos",
                                             "atan", "exp", "log", "exp2", "log2", "pow", "abs",
                                             "sign", "floor", "ceil", "min", "max"};
static_assert(sizeof(kOpFnNames) / sizeof(kOpFnNames[0]) == size_t(OpFn::count_));

struct OpCounts {
  uint64_t mul = 0, add = 0, div = 0, sqrt = 0, other = 0;
  std::array<uint64_t, size_t(OpFn::count_)> fn{};  // "other", per built-in

  // "2 acos, 1 sin" style list of the non-zero per-function counts ("" when none).
  std::string otherCalls() const {
    std::string s;
    for (size_t i = 0; i < fn.size(); ++i) {
      if (!fn[i]) continue;
      if (!s.empty()) s += ", ";
      s += std::to_string(fn[i]) + " " + kOpFnNames[i];
    }
    return s;
  }
  OpCounts operator-(const OpCounts& o) const {
    OpCounts r;
    r.mul = mul - o.mul, r.add = add - o.add, r.div = div - o.div, r.sqrt = sqrt - o.sqrt;
    r.other = other - o.other;
    for (size_t i = 0; i < fn.size(); ++i) r.fn[i] = fn[i] - o.fn[i];
    return r;
  }
  bool operator==(const OpCounts&) const = default;
};

class OpCounter {
public:
  static OpCounts& current() {
    thread_local OpCounts counts;
    return counts;
  }
  static void reset() { current() = OpCounts{}; }
  static OpCounts snapshot() { return current(); }
  static void fn(OpFn f) {
    OpCounts& c = current();
    ++c.other;
    ++c.fn[size_t(f)];
  }
};

// Counts what `f` does on the calling thread (leaves the running totals untouched).
template <class F> OpCounts countOps(F&& f) {
  const OpCounts before = OpCounter::snapshot();
  f();
  return OpCounter::snapshot() - before;
}

struct Counted {
  double v;  // left uninitialised by the default constructor, like float

  Counted() = default;
  template <class T>
    requires std::is_arithmetic_v<T>
  constexpr Counted(T x) : v(double(x)) {}  // implicit, so that literals mix in
  constexpr double value() const { return v; }
  explicit constexpr operator double() const { return v; }

  friend Counted operator+(Counted a, Counted b) {
    ++OpCounter::current().add;
    return Counted(a.v + b.v);
  }
  friend Counted operator-(Counted a, Counted b) {
    ++OpCounter::current().add;
    return Counted(a.v - b.v);
  }
  friend Counted operator*(Counted a, Counted b) {
    ++OpCounter::current().mul;
    return Counted(a.v * b.v);
  }
  friend Counted operator/(Counted a, Counted b) {
    ++OpCounter::current().div;
    return Counted(a.v / b.v);
  }
  friend constexpr Counted operator-(Counted a) { return Counted(-a.v); }
  friend constexpr Counted operator+(Counted a) { return a; }
  Counted& operator+=(Counted b) { return *this = *this + b; }
  Counted& operator-=(Counted b) { return *this = *this - b; }
  Counted& operator*=(Counted b) { return *this = *this * b; }
  Counted& operator/=(Counted b) { return *this = *this / b; }

  friend constexpr bool operator==(Counted a, Counted b) { return a.v == b.v; }
  friend constexpr bool operator<(Counted a, Counted b) { return a.v < b.v; }
  friend constexpr bool operator>(Counted a, Counted b) { return a.v > b.v; }
  friend constexpr bool operator<=(Counted a, Counted b) { return a.v <= b.v; }
  friend constexpr bool operator>=(Counted a, Counted b) { return a.v >= b.v; }
};

}  // namespace mb

template <> struct glsl::scalar_ops<mb::Counted> {
  using C = mb::Counted;
  using F = mb::OpFn;
  static C sqrt(C x) {
    ++mb::OpCounter::current().sqrt;
    return C(std::sqrt(x.v));
  }
  static C call(F f, double r) {
    mb::OpCounter::fn(f);
    return C(r);
  }
  static C inversesqrt(C x) { return call(F::inversesqrt, 1.0 / std::sqrt(x.v)); }
  static C sin(C x) { return call(F::sin, std::sin(x.v)); }
  static C cos(C x) { return call(F::cos, std::cos(x.v)); }
  static C tan(C x) { return call(F::tan, std::tan(x.v)); }
  static C asin(C x) { return call(F::asin, std::asin(x.v)); }
  static C acos(C x) { return call(F::acos, std::acos(x.v)); }
  static C atan(C x) { return call(F::atan, std::atan(x.v)); }
  static C atan2(C y, C x) { return call(F::atan, std::atan2(y.v, x.v)); }
  static C exp(C x) { return call(F::exp, std::exp(x.v)); }
  static C log(C x) { return call(F::log, std::log(x.v)); }
  static C exp2(C x) { return call(F::exp2, std::exp2(x.v)); }
  static C log2(C x) { return call(F::log2, std::log2(x.v)); }
  static C pow(C x, C y) { return call(F::pow, std::pow(x.v, y.v)); }
  static C abs(C x) { return call(F::abs, std::abs(x.v)); }
  static C sign(C x) { return call(F::sign, x.v > 0 ? 1.0 : (x.v < 0 ? -1.0 : 0.0)); }
  static C floor(C x) { return call(F::floor, std::floor(x.v)); }
  static C ceil(C x) { return call(F::ceil, std::ceil(x.v)); }
  static C min(C x, C y) { return call(F::min, y.v < x.v ? y.v : x.v); }
  static C max(C x, C y) { return call(F::max, x.v < y.v ? y.v : x.v); }
};
