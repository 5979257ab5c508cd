// Points, directions, batched products and the skin palette (simd_kernels.h), compiled once per
// Highway target and dispatched at run time to the best one the CPU supports.
#include <cstring>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernels/simd/simd_transform.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "kernels/simd/simd_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace mb::simd::HWY_NAMESPACE {

// Pair point / direction: 3 planes in and out, uniforms broadcast before the loop, 3 input
// planes prefetched; matrix 9 multiply-adds per item (rows 0..2 of the affine mat4), motor
// sw_mp 18 / sw_md 18 fused ops.
void PointsMatrix(const float* model, ConstPlanes in, Planes out, size_t n) {
  const bool nt = streamOutput(out, 3, n);
  forEachBatch(n, nt, [&](auto d, size_t b, size_t e, bool main) {
    using V = hn::Vec<decltype(d)>;
    V m[16], p[3], o[3];
    broadcast(d, model, m);
    for (size_t i = b; i < e; i += hn::Lanes(d)) {
      if (main) prefetchPlanes(in, 3, i);
      loadPlanes(d, in, i, p);
      affinePoint(m, 4, p[0], p[1], p[2], o);
      storePlanes(d, out, i, o, main && nt);
    }
  });
}

void PointsMotor(const float* motor, ConstPlanes in, Planes out, size_t n) {
  const float c3[3] = {motor[7] * motor[1], motor[7] * motor[2], motor[7] * motor[3]};
  const bool nt = streamOutput(out, 3, n);
  forEachBatch(n, nt, [&](auto d, size_t b, size_t e, bool main) {
    using V = hn::Vec<decltype(d)>;
    V m[8], c[3], p[3], o[3];
    broadcast(d, motor, m);
    broadcast(d, c3, c);
    const V two = hn::Set(d, 2.0f);
    for (size_t i = b; i < e; i += hn::Lanes(d)) {
      if (main) prefetchPlanes(in, 3, i);
      loadPlanes(d, in, i, p);
      motorPoint(m, c, p[0], p[1], p[2], two, o);
      storePlanes(d, out, i, o, main && nt);
    }
  });
}

void DirectionsMatrix(const float* model, ConstPlanes in, Planes out, size_t n) {
  const bool nt = streamOutput(out, 3, n);
  forEachBatch(n, nt, [&](auto d, size_t b, size_t e, bool main) {
    using V = hn::Vec<decltype(d)>;
    V m[16], p[3], o[3];
    broadcast(d, model, m);
    for (size_t i = b; i < e; i += hn::Lanes(d)) {
      if (main) prefetchPlanes(in, 3, i);
      loadPlanes(d, in, i, p);
      linearDirection(m, 4, p[0], p[1], p[2], o);
      storePlanes(d, out, i, o, main && nt);
    }
  });
}

void DirectionsMotor(const float* motor, ConstPlanes in, Planes out, size_t n) {
  const bool nt = streamOutput(out, 3, n);
  forEachBatch(n, nt, [&](auto d, size_t b, size_t e, bool main) {
    using V = hn::Vec<decltype(d)>;
    V m[8], p[3], o[3];
    broadcast(d, motor, m);
    const V two = hn::Set(d, 2.0f);
    for (size_t i = b; i < e; i += hn::Lanes(d)) {
      if (main) prefetchPlanes(in, 3, i);
      loadPlanes(d, in, i, p);
      motorDirection(m, p[0], p[1], p[2], two, o);
      storePlanes(d, out, i, o, main && nt);
    }
  });
}

// Pair compose (mat4 / affine / motor): both operands and the result planar, every input plane
// prefetched, one product per lane: mat4 16 mul + 48 fused, affine 36 fused, gp_mm 48 fused.
void ComposeMat4(ConstPlanes a, ConstPlanes b, Planes out, size_t n) {
  const bool nt = streamOutput(out, 16, n);
  forEachBatch(n, nt, [&](auto d, size_t s, size_t e, bool main) {
    using V = hn::Vec<decltype(d)>;
    V x[16], y[16], o[16];
    for (size_t i = s; i < e; i += hn::Lanes(d)) {
      if (main) prefetchPlanes(a, 16, i), prefetchPlanes(b, 16, i);
      loadPlanes(d, a, i, x);
      loadPlanes(d, b, i, y);
      for (size_t j = 0; j < 4; ++j)
        for (size_t r = 0; r < 4; ++r)
          o[4 * j + r] = hn::MulAdd(x[r], y[4 * j], hn::MulAdd(x[4 + r], y[4 * j + 1],
                         hn::MulAdd(x[8 + r], y[4 * j + 2], hn::Mul(x[12 + r], y[4 * j + 3]))));
      storePlanes(d, out, i, o, main && nt);
    }
  });
}

void ComposeAffine(ConstPlanes a, ConstPlanes b, Planes out, size_t n) {
  const bool nt = streamOutput(out, 12, n);
  forEachBatch(n, nt, [&](auto d, size_t s, size_t e, bool main) {
    using V = hn::Vec<decltype(d)>;
    V x[12], y[12], o[12];
    for (size_t i = s; i < e; i += hn::Lanes(d)) {
      if (main) prefetchPlanes(a, 12, i), prefetchPlanes(b, 12, i);
      loadPlanes(d, a, i, x);
      loadPlanes(d, b, i, y);
      affineProduct(x, y, o);
      storePlanes(d, out, i, o, main && nt);
    }
  });
}

void ComposeMotor(ConstPlanes a, ConstPlanes b, Planes out, size_t n) {
  const bool nt = streamOutput(out, 8, n);
  forEachBatch(n, nt, [&](auto d, size_t s, size_t e, bool main) {
    using V = hn::Vec<decltype(d)>;
    V x[8], y[8], o[8];
    for (size_t i = s; i < e; i += hn::Lanes(d)) {
      if (main) prefetchPlanes(a, 8, i), prefetchPlanes(b, 8, i);
      loadPlanes(d, a, i, x);
      loadPlanes(d, b, i, y);
      motorProduct(x, y, o);
      storePlanes(d, out, i, o, main && nt);
    }
  });
}

// Pair palette (affine / motor): the joint's node world gathered per component (12 / 8
// GatherIndex), the inverse bind loaded and prefetched, then the product as in compose.
void PaletteAffine(ConstPlanes world, const int32_t* node, ConstPlanes inverseBind, Planes out, size_t n) {
  const bool nt = streamOutput(out, 12, n);
  forEachBatch(n, nt, [&](auto d, size_t s, size_t e, bool main) {
    using V = hn::Vec<decltype(d)>;
    const hn::RebindToSigned<decltype(d)> di;
    V x[12], y[12], o[12];
    for (size_t i = s; i < e; i += hn::Lanes(d)) {
      if (main) prefetchPlanes(inverseBind, 12, i);
      gatherPlanes(d, world, hn::LoadU(di, node + i), x);
      loadPlanes(d, inverseBind, i, y);
      affineProduct(x, y, o);
      storePlanes(d, out, i, o, main && nt);
    }
  });
}

void PaletteMotor(ConstPlanes world, const int32_t* node, ConstPlanes inverseBind, Planes out, size_t n) {
  const bool nt = streamOutput(out, 8, n);
  forEachBatch(n, nt, [&](auto d, size_t s, size_t e, bool main) {
    using V = hn::Vec<decltype(d)>;
    const hn::RebindToSigned<decltype(d)> di;
    V x[8], y[8], o[8];
    for (size_t i = s; i < e; i += hn::Lanes(d)) {
      if (main) prefetchPlanes(inverseBind, 8, i);
      gatherPlanes(d, world, hn::LoadU(di, node + i), x);
      loadPlanes(d, inverseBind, i, y);
      motorProduct(x, y, o);
      storePlanes(d, out, i, o, main && nt);
    }
  });
}

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
HWY_EXPORT(PaletteAffine);
HWY_EXPORT(PaletteMotor);

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
void paletteAffine(ConstPlanes world, const int32_t* node, ConstPlanes inverseBind, Planes out, size_t n) {
  HWY_DYNAMIC_DISPATCH(PaletteAffine)(world, node, inverseBind, out, n);
}
void paletteMotor(ConstPlanes world, const int32_t* node, ConstPlanes inverseBind, Planes out, size_t n) {
  HWY_DYNAMIC_DISPATCH(PaletteMotor)(world, node, inverseBind, out, n);
}

}  // namespace mb::simd
#endif  // HWY_ONCE
