// Hierarchy update (simd_kernels.h) as ozz-animation's SoA local-to-model job does it: nodes in
// parents-first order, walked in groups of one full vector; each group's local transforms are
// computed together from the TRS planes (structure of arrays, every lane busy whatever the tree's
// shape) into a small stack block, then every node of the group takes its parent's world
// transform as 4-lane vectors (matrix columns / motor halves) and multiplies it by its local
// one, broadcast component by component: no gather, and when the parent is the node just done
// (a chain) its world is still in registers. Compiled once per Highway target.
#include <algorithm>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernels/simd/simd_hierarchy.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "kernels/simd/simd_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace mb::simd::HWY_NAMESPACE {

// 4-lane vectors for the per-node products: 128-bit Highway vectors, or four floats on the
// one-lane HWY_SCALAR fallback (which has no 4-lane type).
#if HWY_TARGET == HWY_SCALAR
struct V4 {
  float l[4];
};
HWY_INLINE V4 load4(const float* p) { return {{p[0], p[1], p[2], p[3]}}; }
HWY_INLINE void store4(V4 v, float* p) { p[0] = v.l[0], p[1] = v.l[1], p[2] = v.l[2], p[3] = v.l[3]; }
HWY_INLINE V4 set4(float x) { return {{x, x, x, x}}; }
HWY_INLINE V4 lane0(V4 v) { return set4(v.l[0]); }
HWY_INLINE V4 mul4(V4 a, V4 b) { return {{a.l[0] * b.l[0], a.l[1] * b.l[1], a.l[2] * b.l[2], a.l[3] * b.l[3]}}; }
HWY_INLINE V4 add4(V4 a, V4 b) { return {{a.l[0] + b.l[0], a.l[1] + b.l[1], a.l[2] + b.l[2], a.l[3] + b.l[3]}}; }
HWY_INLINE V4 mulAdd4(V4 a, V4 b, V4 c) {
  V4 r;
  for (int i = 0; i < 4; ++i) r.l[i] = a.l[i] * b.l[i] + c.l[i];
  return r;
}
template <int i0, int i1, int i2, int i3, int n0, int n1, int n2, int n3> HWY_INLINE V4 permSign(V4 v) {
  return {{n0 ? -v.l[i0] : v.l[i0], n1 ? -v.l[i1] : v.l[i1], n2 ? -v.l[i2] : v.l[i2], n3 ? -v.l[i3] : v.l[i3]}};
}
#else
using D4 = hn::FixedTag<float, 4>;
using V4 = hn::Vec<D4>;
HWY_INLINE V4 load4(const float* p) { return hn::LoadU(D4(), p); }
HWY_INLINE void store4(V4 v, float* p) { hn::StoreU(v, D4(), p); }
HWY_INLINE V4 set4(float x) { return hn::Set(D4(), x); }
HWY_INLINE V4 lane0(V4 v) { return hn::Broadcast<0>(v); }
HWY_INLINE V4 mul4(V4 a, V4 b) { return hn::Mul(a, b); }
HWY_INLINE V4 add4(V4 a, V4 b) { return hn::Add(a, b); }
HWY_INLINE V4 mulAdd4(V4 a, V4 b, V4 c) { return hn::MulAdd(a, b, c); }
// Lanes (i0, i1, i2, i3) of v, the lanes whose n is 1 negated.
template <int i0, int i1, int i2, int i3, int n0, int n1, int n2, int n3> HWY_INLINE V4 permSign(V4 v) {
  const D4 d;
  alignas(16) static constexpr int32_t idx[4] = {i0, i1, i2, i3};
  alignas(16) static constexpr float sign[4] = {n0 ? -0.0f : 0.0f, n1 ? -0.0f : 0.0f, n2 ? -0.0f : 0.0f, n3 ? -0.0f : 0.0f};
  return hn::Xor(hn::TableLookupLanes(v, hn::SetTableIndices(d, idx)), hn::Load(d, sign));
}
#endif

// The local transforms of the nodes at item i (lanes of d) into block[c * G + lane0 + lane].
// Affine: T R S as a mat4x3 (quaternion to matrix 12 mul + 12 add, 9 scale mul), 12 planes.
// Motor: gp_tr(T, R) (12 fused ops) and the scale, 9 planes.
template <bool kMotor, class D>
HWY_INLINE void localBlock(D d, ConstPlanes trs, size_t i, float* block, size_t lane0, size_t G) {
  using V = hn::Vec<D>;
  V t[8], l[12];
  loadPlanes(d, trs, i, t);
  const V x = t[0], y = t[1], z = t[2], w = t[3], s = t[7];
  constexpr size_t C = kMotor ? 9 : 12;
  if constexpr (kMotor) {
    // R = [w, -x, -y, -z]; T's e0 half = -t / 2.
    const V nh = hn::Set(d, -0.5f);
    const V ax = hn::Mul(nh, t[4]), ay = hn::Mul(nh, t[5]), az = hn::Mul(nh, t[6]);
    const V Bx = hn::Neg(x), By = hn::Neg(y), Bz = hn::Neg(z);
    l[0] = w, l[1] = Bx, l[2] = By, l[3] = Bz;
    l[4] = hn::MulAdd(w, ax, hn::MulSub(By, az, hn::Mul(Bz, ay)));
    l[5] = hn::MulAdd(w, ay, hn::MulSub(Bz, ax, hn::Mul(Bx, az)));
    l[6] = hn::MulAdd(w, az, hn::MulSub(Bx, ay, hn::Mul(By, ax)));
    l[7] = hn::MulAdd(ax, Bx, hn::MulAdd(ay, By, hn::Mul(az, Bz)));
    l[8] = s;
  } else {
    const V one = hn::Set(d, 1.0f);
    const V x2 = hn::Add(x, x), y2 = hn::Add(y, y), z2 = hn::Add(z, z);
    const V xx = hn::Mul(x, x2), yy = hn::Mul(y, y2), zz = hn::Mul(z, z2), xy = hn::Mul(x, y2), xz = hn::Mul(x, z2),
            yz = hn::Mul(y, z2), wx = hn::Mul(w, x2), wy = hn::Mul(w, y2), wz = hn::Mul(w, z2);
    l[0] = hn::Mul(hn::Sub(one, hn::Add(yy, zz)), s), l[1] = hn::Mul(hn::Add(xy, wz), s), l[2] = hn::Mul(hn::Sub(xz, wy), s);
    l[3] = hn::Mul(hn::Sub(xy, wz), s), l[4] = hn::Mul(hn::Sub(one, hn::Add(xx, zz)), s), l[5] = hn::Mul(hn::Add(yz, wx), s);
    l[6] = hn::Mul(hn::Add(xz, wy), s), l[7] = hn::Mul(hn::Sub(yz, wx), s), l[8] = hn::Mul(hn::Sub(one, hn::Add(xx, yy)), s);
    l[9] = t[4], l[10] = t[5], l[11] = t[6];
  }
  MB_UNROLL for (size_t c = 0; c < C; ++c) hn::StoreU(l[c], d, block + c * G + lane0);
}

// Pair hierarchy: the same group walk, local block and parent reuse on both sides; per node the
// affine product as 4-lane columns (12 broadcasts, 5 fused + 7 mul + 4 add), the motor
// product gp_mm as 4-lane halves (8 broadcasts, 10 lane permutations of the parent, 7 fused +
// 6 mul + 3 add, the scale 1 mul), both summed as trees of depth 3; the parent's uniform scale
// applied to the local translation (the motor's e0 half).
// World layout per node: affine 16 floats (4 columns xyzw, w = 0 0 0 1), motor 12 floats
// (the motor's 8, its scale, 3 unused).
template <bool kMotor> void Hierarchy(ConstPlanes trs, const int32_t* parent, size_t n, float* world) {
  constexpr size_t C = kMotor ? 9 : 12, W = kMotor ? 12 : 16;
  const hn::ScalableTag<float> d;
  constexpr size_t G = HWY_LANES(float);
  HWY_ALIGN float block[C * G];
  V4 last[4] = {set4(0.0f), set4(0.0f), set4(0.0f), set4(0.0f)};  // the previous node's world
  for (size_t g = 0; g < n; g += G) {
    const size_t count = std::min(G, n - g);
    if (count == G && hn::Lanes(d) == G) localBlock<kMotor>(d, trs, g, block, 0, G);
    else
      for (size_t i = 0; i < count; ++i) localBlock<kMotor>(hn::CappedTag<float, 1>(), trs, g + i, block, i, G);
    for (size_t i = 0; i < count; ++i) {
      const size_t k = g + i;
      const int32_t p = parent[k];
      auto L = [&](size_t c) { return set4(block[c * G + i]); };
      float* out = world + k * W;
      if (p < 0) {  // a root: world = local
        HWY_ALIGN float v[16] = {};
        for (size_t c = 0; c < C; ++c) v[kMotor ? c : c + c / 3] = block[c * G + i];
        if (!kMotor) v[3] = v[7] = v[11] = 0.0f, v[15] = 1.0f;
        MB_UNROLL for (size_t h = 0; h < W / 4; ++h) last[h] = load4(v + 4 * h);
      } else if (size_t(p) + 1 != k) {  // not the node just done: its world from memory
        MB_UNROLL for (size_t h = 0; h < W / 4; ++h) last[h] = load4(world + size_t(p) * W + 4 * h);
      }
      if (p >= 0) {
        V4 o[4];
        if constexpr (kMotor) {
          const V4 a0 = last[0], a1 = last[1];
          const V4 ps = lane0(last[2]);
          // gp_mm(a, b) = sum over b's components of the component times a signed lane
          // permutation of a's halves (derived from pga.glsl's gp_mm, lane by lane).
          const V4 Mx = permSign<1, 0, 3, 2, 1, 0, 1, 0>(a0), My = permSign<2, 3, 0, 1, 1, 0, 0, 1>(a0),
                   Mz = permSign<3, 2, 1, 0, 1, 1, 0, 0>(a0);
          const V4 Qx = permSign<3, 2, 1, 0, 1, 1, 0, 0>(a1), Qy = permSign<2, 3, 0, 1, 0, 1, 1, 0>(a1),
                   Qz = permSign<1, 0, 3, 2, 1, 0, 1, 0>(a1);
          const V4 Nx = permSign<0, 3, 2, 1, 0, 1, 0, 0>(a0), Ny = permSign<3, 0, 1, 2, 0, 0, 1, 0>(a0),
                   Nz = permSign<2, 1, 0, 3, 1, 0, 0, 0>(a0), Np = permSign<1, 2, 3, 0, 1, 1, 1, 0>(a0);
          // Sums as trees of depth 3: on a chain every level is latency on the next node.
          o[0] = add4(mulAdd4(L(0), a0, mul4(L(1), Mx)), mulAdd4(L(2), My, mul4(L(3), Mz)));
          const V4 rotorPart = add4(mulAdd4(L(0), a1, mul4(L(1), Qx)), mulAdd4(L(2), Qy, mul4(L(3), Qz)));
          const V4 dualPart = add4(mulAdd4(L(4), Nx, mul4(L(5), Ny)), mulAdd4(L(6), Nz, mul4(L(7), Np)));
          o[1] = mulAdd4(dualPart, ps, rotorPart);
          o[2] = mul4(ps, L(8));  // lane 0: the world scale
        } else {
          const V4 P0 = last[0], P1 = last[1], P2 = last[2], P3 = last[3];
          MB_UNROLL for (size_t j = 0; j < 3; ++j)
            o[j] = add4(mulAdd4(P0, L(3 * j), mul4(P1, L(3 * j + 1))), mul4(P2, L(3 * j + 2)));
          o[3] = add4(mulAdd4(P0, L(9), mul4(P1, L(10))), mulAdd4(P2, L(11), P3));
        }
        MB_UNROLL for (size_t h = 0; h < W / 4; ++h) last[h] = o[h];
      }
      MB_UNROLL for (size_t h = 0; h < W / 4; ++h) store4(last[h], out + 4 * h);
    }
  }
}

void HierarchyAffine(ConstPlanes trs, const int32_t* parent, size_t n, float* world) {
  Hierarchy<false>(trs, parent, n, world);
}
void HierarchyMotor(ConstPlanes trs, const int32_t* parent, size_t n, float* world) {
  Hierarchy<true>(trs, parent, n, world);
}

}  // namespace mb::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace mb::simd {

HWY_EXPORT(HierarchyAffine);
HWY_EXPORT(HierarchyMotor);

void hierarchyAffine(ConstPlanes trs, const int32_t* parent, size_t n, float* world) {
  HWY_DYNAMIC_DISPATCH(HierarchyAffine)(trs, parent, n, world);
}
void hierarchyMotor(ConstPlanes trs, const int32_t* parent, size_t n, float* world) {
  HWY_DYNAMIC_DISPATCH(HierarchyMotor)(trs, parent, n, world);
}

}  // namespace mb::simd
#endif  // HWY_ONCE
