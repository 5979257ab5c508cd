// Points, directions and batched products (simd_kernels.h), compiled once per
// Highway target and dispatched at run time to the best one the CPU supports.
#include <cstring>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernels/simd/simd_transform.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "kernels/simd/simd_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace mb::simd::HWY_NAMESPACE {

// Pair point / direction: one loop for both sides and both kinds, 3 planes in and out, the
// uniform (mat4 16 or motor 8 floats, motor points also e0123 * A) broadcast before the loop,
// 3 input planes prefetched; matrix 9 multiply-adds per item (rows 0..2 of the affine mat4),
// motor sw_mp 18 / sw_md 18 fused ops.
template <bool kMotor, bool kPoint> void vec3Batch(const float* u, ConstPlanes in, Planes out, size_t n) {
  constexpr size_t U = kMotor ? 8 : 16;
  const float c3[3] = {kMotor ? u[7] * u[1] : 0.0f, kMotor ? u[7] * u[2] : 0.0f, kMotor ? u[7] * u[3] : 0.0f};
  const bool nt = streamOutput(out, 3, n);
  forEachBatch(n, nt, [&](auto d, size_t b, size_t e, bool main) {
    using V = hn::Vec<decltype(d)>;
    V m[U], c[3], p[3], o[3];
    broadcast(d, u, m);
    broadcast(d, c3, c);
    const V two = hn::Set(d, 2.0f);
    for (size_t i = b; i < e; i += hn::Lanes(d)) {
      if (main) prefetchPlanes(in, 3, i);
      loadPlanes(d, in, i, p);
      if constexpr (kMotor && kPoint) motorPoint(m, c, p[0], p[1], p[2], two, o);
      else if constexpr (kMotor) motorDirection(m, p[0], p[1], p[2], two, o);
      else if constexpr (kPoint) affinePoint(m, 4, p[0], p[1], p[2], o);
      else linearDirection(m, 4, p[0], p[1], p[2], o);
      storePlanes(d, out, i, o, main && nt);
    }
  });
}

void PointsMatrix(const float* model, ConstPlanes in, Planes out, size_t n) { vec3Batch<false, true>(model, in, out, n); }
void PointsMotor(const float* motor, ConstPlanes in, Planes out, size_t n) { vec3Batch<true, true>(motor, in, out, n); }
void DirectionsMatrix(const float* model, ConstPlanes in, Planes out, size_t n) {
  vec3Batch<false, false>(model, in, out, n);
}
void DirectionsMotor(const float* motor, ConstPlanes in, Planes out, size_t n) {
  vec3Batch<true, false>(motor, in, out, n);
}

// a * b for mat4 operands (matrixCompose: 16 mul + 48 fused).
template <class V> HWY_INLINE void mat4Product(const V* x, const V* y, V* o) {
  MB_UNROLL for (size_t j = 0; j < 4; ++j)
    MB_UNROLL for (size_t r = 0; r < 4; ++r)
      o[4 * j + r] = hn::MulAdd(x[r], y[4 * j], hn::MulAdd(x[4 + r], y[4 * j + 1],
                     hn::MulAdd(x[8 + r], y[4 * j + 2], hn::Mul(x[12 + r], y[4 * j + 3]))));
}

// The products of the compose pair, as functors over C-plane operands.
struct Mat4Product {
  static constexpr size_t C = 16;
  template <class V> void operator()(const V* x, const V* y, V* o) const { mat4Product(x, y, o); }
};
struct AffineProduct {
  static constexpr size_t C = 12;
  template <class V> void operator()(const V* x, const V* y, V* o) const { affineProduct(x, y, o); }
};
struct MotorProduct {
  static constexpr size_t C = 8;
  template <class V> void operator()(const V* x, const V* y, V* o) const { motorProduct(x, y, o); }
};

// Pair compose (mat4 / affine / motor): one loop for every product, both operands and the
// result planar, every input plane prefetched, one product per lane: mat4 16 mul + 48 fused,
// affine 36 fused, gp_mm 48 fused.
template <class Product> void composeBatch(ConstPlanes a, ConstPlanes b, Planes out, size_t n, Product product) {
  constexpr size_t C = Product::C;
  const bool nt = streamOutput(out, C, n);
  forEachBatch(n, nt, [&](auto d, size_t s, size_t e, bool main) {
    using V = hn::Vec<decltype(d)>;
    V x[C], y[C], o[C];
    for (size_t i = s; i < e; i += hn::Lanes(d)) {
      if (main) prefetchPlanes(a, C, i), prefetchPlanes(b, C, i);
      loadPlanes(d, a, i, x);
      loadPlanes(d, b, i, y);
      product(x, y, o);
      storePlanes(d, out, i, o, main && nt);
    }
  });
}

void ComposeMat4(ConstPlanes a, ConstPlanes b, Planes out, size_t n) { composeBatch(a, b, out, n, Mat4Product()); }
void ComposeAffine(ConstPlanes a, ConstPlanes b, Planes out, size_t n) {
  composeBatch(a, b, out, n, AffineProduct());
}
void ComposeMotor(ConstPlanes a, ConstPlanes b, Planes out, size_t n) { composeBatch(a, b, out, n, MotorProduct()); }
}  // namespace mb::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace mb::simd {

HWY_EXPORT(PointsMatrix);
HWY_EXPORT(PointsMotor);
HWY_EXPORT(DirectionsMatrix);
HWY_EXPORT(DirectionsMotor);
HWY_EXPORT(ComposeMat4);
HWY_EXPORT(ComposeAffine);
HWY_EXPORT(ComposeMotor);

void pointsMatrix(const float model[16], ConstPlanes in, Planes out, size_t n) {
  HWY_DYNAMIC_DISPATCH(PointsMatrix)(model, in, out, n);
}
void pointsMotor(const float motor[8], ConstPlanes in, Planes out, size_t n) {
  HWY_DYNAMIC_DISPATCH(PointsMotor)(motor, in, out, n);
}
void directionsMatrix(const float model[16], ConstPlanes in, Planes out, size_t n) {
  HWY_DYNAMIC_DISPATCH(DirectionsMatrix)(model, in, out, n);
}
void directionsMotor(const float motor[8], ConstPlanes in, Planes out, size_t n) {
  HWY_DYNAMIC_DISPATCH(DirectionsMotor)(motor, in, out, n);
}
void composeMat4(ConstPlanes a, ConstPlanes b, Planes out, size_t n) { HWY_DYNAMIC_DISPATCH(ComposeMat4)(a, b, out, n); }
void composeAffine(ConstPlanes a, ConstPlanes b, Planes out, size_t n) {
  HWY_DYNAMIC_DISPATCH(ComposeAffine)(a, b, out, n);
}
void composeMotor(ConstPlanes a, ConstPlanes b, Planes out, size_t n) { HWY_DYNAMIC_DISPATCH(ComposeMotor)(a, b, out, n); }

}  // namespace mb::simd
#endif  // HWY_ONCE
