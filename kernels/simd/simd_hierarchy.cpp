// Hierarchy update (simd_kernels.h), compiled once per Highway target and dispatched at run
// time to the best one the CPU supports.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernels/simd/simd_hierarchy.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "kernels/simd/simd_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace mb::simd::HWY_NAMESPACE {

// Pair hierarchy: the same level-by-level loop, TRS planes loaded (and prefetched) per batch,
// the parent's world gathered per component (affine 12, motor 9 with its scale), one product
// per lane (affine 36 fused, gp_mm 48 fused) after the local transform (affine: quaternion
// to matrix 12 mul + 12 fused and 9 scale mul; motor: gp_tr 12 fused and 4 scale mul).
template <bool kMotor>
void Hierarchy(ConstPlanes trs, const int32_t* parent, const uint32_t* levelEnd, size_t levels, Planes world) {
  constexpr size_t C = kMotor ? 9 : 12;
  size_t begin = 0;
  for (size_t level = 0; level < levels; ++level) {
    const size_t end = levelEnd[level], n = end - begin;
    forEachBatch(n, false, [&](auto d, size_t b, size_t e, bool main) {
      using V = hn::Vec<decltype(d)>;
      const hn::RebindToSigned<decltype(d)> di;
      const V one = hn::Set(d, 1.0f), half = hn::Set(d, 0.5f);
      V t[8], l[C], pw[C], o[C];
      for (size_t k = begin + b; k < begin + e; k += hn::Lanes(d)) {
        if (main) prefetchPlanes(trs, 8, k);
        loadPlanes(d, trs, k, t);
        const V x = t[0], y = t[1], z = t[2], w = t[3], s = t[7];
        if constexpr (kMotor) {
          // gp_tr(T, R): R = [w, -x, -y, -z], T's e0 half = -t / 2.
          const V ax = hn::Mul(hn::Neg(half), t[4]), ay = hn::Mul(hn::Neg(half), t[5]), az = hn::Mul(hn::Neg(half), t[6]);
          const V Bx = hn::Neg(x), By = hn::Neg(y), Bz = hn::Neg(z);
          l[0] = w, l[1] = Bx, l[2] = By, l[3] = Bz;
          l[4] = hn::MulAdd(w, ax, hn::MulSub(By, az, hn::Mul(Bz, ay)));
          l[5] = hn::MulAdd(w, ay, hn::MulSub(Bz, ax, hn::Mul(Bx, az)));
          l[6] = hn::MulAdd(w, az, hn::MulSub(Bx, ay, hn::Mul(By, ax)));
          l[7] = hn::MulAdd(ax, Bx, hn::MulAdd(ay, By, hn::Mul(az, Bz)));
          l[8] = s;
        } else {
          const V x2 = hn::Add(x, x), y2 = hn::Add(y, y), z2 = hn::Add(z, z);
          const V xx = hn::Mul(x, x2), yy = hn::Mul(y, y2), zz = hn::Mul(z, z2), xy = hn::Mul(x, y2),
                  xz = hn::Mul(x, z2), yz = hn::Mul(y, z2), wx = hn::Mul(w, x2), wy = hn::Mul(w, y2),
                  wz = hn::Mul(w, z2);
          l[0] = hn::Mul(hn::Sub(one, hn::Add(yy, zz)), s), l[1] = hn::Mul(hn::Add(xy, wz), s), l[2] = hn::Mul(hn::Sub(xz, wy), s);
          l[3] = hn::Mul(hn::Sub(xy, wz), s), l[4] = hn::Mul(hn::Sub(one, hn::Add(xx, zz)), s), l[5] = hn::Mul(hn::Add(yz, wx), s);
          l[6] = hn::Mul(hn::Add(xz, wy), s), l[7] = hn::Mul(hn::Sub(yz, wx), s), l[8] = hn::Mul(hn::Sub(one, hn::Add(xx, yy)), s);
          l[9] = t[4], l[10] = t[5], l[11] = t[6];
        }
        if (level == 0) {  // roots: world = local
          storePlanes(d, world, k, l, false);
          continue;
        }
        gatherPlanes(d, ConstPlanes(world), hn::LoadU(di, parent + k), pw);
        if constexpr (kMotor) {
          // The parent's scale applies to the local translation (the motor's e0 half).
          MB_UNROLL for (size_t c = 4; c < 8; ++c) l[c] = hn::Mul(l[c], pw[8]);
          motorProduct(pw, l, o);
          o[8] = hn::Mul(pw[8], s);
        } else {
          affineProduct(pw, l, o);
        }
        storePlanes(d, world, k, o, false);
      }
    });
    begin = end;
  }
}

void HierarchyAffine(ConstPlanes trs, const int32_t* parent, const uint32_t* levelEnd, size_t levels, Planes world) {
  Hierarchy<false>(trs, parent, levelEnd, levels, world);
}
void HierarchyMotor(ConstPlanes trs, const int32_t* parent, const uint32_t* levelEnd, size_t levels, Planes world) {
  Hierarchy<true>(trs, parent, levelEnd, levels, world);
}

}  // namespace mb::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace mb::simd {

HWY_EXPORT(HierarchyAffine);
HWY_EXPORT(HierarchyMotor);

void hierarchyAffine(ConstPlanes trs, const int32_t* parent, const uint32_t* levelEnd, size_t levels, Planes world) {
  HWY_DYNAMIC_DISPATCH(HierarchyAffine)(trs, parent, levelEnd, levels, world);
}
void hierarchyMotor(ConstPlanes trs, const int32_t* parent, const uint32_t* levelEnd, size_t levels, Planes world) {
  HWY_DYNAMIC_DISPATCH(HierarchyMotor)(trs, parent, levelEnd, levels, world);
}

}  // namespace mb::simd
#endif  // HWY_ONCE
