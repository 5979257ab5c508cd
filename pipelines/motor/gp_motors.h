// The motor product of the CPU update (hierarchy and palettes compose one motor per node and
// joint per frame), bit-identical to gp_mm of shaders/pga.glsl.
//
// Why not the shim's gp_mm: GCC -O2 compiles it to about 400 instructions of shuffles and
// spills. Why not Highway (kernels/simd): one product is 8 floats, inlined into a loop whose
// next iteration reads this one's result; a dispatched call per node costs more than the
// product, and Highway 1.0.3 has no baseline-x86-64 (SSE2) static target to inline into.
// So: GCC/Clang 4-lane vector extensions, which compile to SSE2 on any x86-64 (NEON on arm64),
// the same width GCC gives GLM's mat4 product in the matrix pipelines' hierarchy (4-lane
// columns, auto-vectorised) — equal care on both sides.
#pragma once
#include <cstring>

#include "pipelines/motor/motor_kernels.h"

namespace mb::motor {

#if defined(__GNUC__) && (defined(__clang__) || __GNUC__ >= 12)
namespace lanes {
typedef float f4 __attribute__((vector_size(16)));
inline f4 load(const Motor& m, int half) {
  f4 v;
  std::memcpy(&v, &m[half][0], sizeof v);
  return v;
}
inline f4 splat(float x) { return f4{x, x, x, x}; }
}  // namespace lanes

// gp_mm 4 lanes at a time. Every lane evaluates gp_mm's expression tree (same products, same
// order of additions), so the result is the same bits (test_update_phases checks 100k motors);
// the two lanes whose trees differ from their neighbours' (the scalar part's dot, e0123's two
// dots) are computed as scalars and put in place. 36 vector + 12 scalar arithmetic instructions.
// bDualScale: b's dual half is taken times this first (scaled_motor.h: the hierarchy's
// parent scale), in registers — a scaled copy of b built in memory by the caller
// would be stored as scalars and read back as vectors, a store-forwarding stall per node.
inline void gpMotors(const Motor& a, const Motor& b, Motor& r, float bDualScale = 1.0f) {
  using lanes::f4;
  const float ds = bDualScale;
  const f4 a0 = lanes::load(a, 0), a1 = lanes::load(a, 1);  // (s, A) and (Ad, e0123)
  const f4 b0 = lanes::load(b, 0), b1 = lanes::load(b, 1) * lanes::splat(ds);
  const f4 as = lanes::splat(a0[0]), bs = lanes::splat(b0[0]);
  // Rotor half, lanes 1-3: (as B + bs A) + cross(B, A).
  f4 r0 = (as * b0 + bs * a0) + (__builtin_shufflevector(b0, b0, 0, 2, 3, 1) * __builtin_shufflevector(a0, a0, 0, 3, 1, 2) -
                                 __builtin_shufflevector(b0, b0, 0, 3, 1, 2) * __builtin_shufflevector(a0, a0, 0, 2, 3, 1));
  // The scalar lanes read their inputs from memory (loads are cheaper than lane extractions).
  r0[0] = a[0][0] * b[0][0] - (a[0][1] * b[0][1] + a[0][2] * b[0][2] + a[0][3] * b[0][3]);
  // Dual half, lanes 0-2: (as Bd + bs Ad) + cross(B, Ad) + cross(Bd, A) - bp A - ap B; lane 3
  // (e0123) is (as bp + bs ap) + dot(A, Bd) + dot(Ad, B).
  const f4 sum = as * b1 + bs * a1;
  const f4 crossBAd = __builtin_shufflevector(b0, b0, 2, 3, 1, 0) * __builtin_shufflevector(a1, a1, 2, 0, 1, 3) -
                      __builtin_shufflevector(b0, b0, 3, 1, 2, 0) * __builtin_shufflevector(a1, a1, 1, 2, 0, 3);
  const f4 crossBdA = __builtin_shufflevector(b1, b1, 1, 2, 0, 3) * __builtin_shufflevector(a0, a0, 3, 1, 2, 0) -
                      __builtin_shufflevector(b1, b1, 2, 0, 1, 3) * __builtin_shufflevector(a0, a0, 2, 3, 1, 0);
  const f4 A = __builtin_shufflevector(a0, a0, 1, 2, 3, 0), B = __builtin_shufflevector(b0, b0, 1, 2, 3, 0);
  const float bp = b[1][3] * ds;
  f4 r1 = sum + crossBAd + crossBdA - lanes::splat(bp) * A - lanes::splat(a[1][3]) * B;
  r1[3] = (a[0][0] * bp + b[0][0] * a[1][3]) +
          (a[0][1] * (b[1][0] * ds) + a[0][2] * (b[1][1] * ds) + a[0][3] * (b[1][2] * ds)) +
          (a[1][0] * b[0][1] + a[1][1] * b[0][2] + a[1][2] * b[0][3]);
  std::memcpy(&r[0][0], &r0, sizeof r0);
  std::memcpy(&r[1][0], &r1, sizeof r1);
}
#else
// Without vector extensions: the shim's gp_mm itself (slower, the same bits).
inline void gpMotors(const Motor& a, const Motor& b, Motor& r, float bDualScale = 1.0f) {
  r = mk().gp_mm(a, Motor(b[0], b[1] * bDualScale));
}
#endif

inline Motor gpMotors(const Motor& a, const Motor& b) {
  Motor r;
  gpMotors(a, b, r);
  return r;
}

}  // namespace mb::motor
