// Hierarchy update (simd_kernels.h) as ozz-animation's SoA local-to-model job does it: nodes in
// parents-first order, walked in groups of one full vector; each group's local transforms are
// computed together from the TRS planes (structure of arrays, every lane busy whatever the tree's
// shape) into a small stack block, then every node of the group takes its parent's world
// transform as 4-lane vectors (matrix columns / motor halves) and multiplies it by its local
// one, broadcast component by component: no gather, and when the parent is the node just done
// (a chain) its world is still in registers. The skin palette pair reads those worlds with the
// same per-node products (Palette, below). Compiled once per Highway target.
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

// gp_mm(a, b) on 4-lane halves: a = (a0, a1) (a's e0 half a1, its dual part scaled by `ps`:
// the parent's uniform scale in the hierarchy, 1 in the palette), b(c) = b's component c
// broadcast. The sum over b's 8 components of that component times a signed lane permutation of
// a's halves (derived from pga.glsl's gp_mm, lane by lane): 10 permutations, 7 fused + 6 mul +
// 3 add, as trees of depth 3 (on a chain every level is latency on the next node).
template <class B> HWY_INLINE void motorProduct4(V4 a0, V4 a1, const B& b, V4 ps, V4* o) {
  const V4 Mx = permSign<1, 0, 3, 2, 1, 0, 1, 0>(a0), My = permSign<2, 3, 0, 1, 1, 0, 0, 1>(a0),
           Mz = permSign<3, 2, 1, 0, 1, 1, 0, 0>(a0);
  const V4 Qx = permSign<3, 2, 1, 0, 1, 1, 0, 0>(a1), Qy = permSign<2, 3, 0, 1, 0, 1, 1, 0>(a1),
           Qz = permSign<1, 0, 3, 2, 1, 0, 1, 0>(a1);
  const V4 Nx = permSign<0, 3, 2, 1, 0, 1, 0, 0>(a0), Ny = permSign<3, 0, 1, 2, 0, 0, 1, 0>(a0),
           Nz = permSign<2, 1, 0, 3, 1, 0, 0, 0>(a0), Np = permSign<1, 2, 3, 0, 1, 1, 1, 0>(a0);
  o[0] = add4(mulAdd4(b(0), a0, mul4(b(1), Mx)), mulAdd4(b(2), My, mul4(b(3), Mz)));
  const V4 rotorPart = add4(mulAdd4(b(0), a1, mul4(b(1), Qx)), mulAdd4(b(2), Qy, mul4(b(3), Qz)));
  const V4 dualPart = add4(mulAdd4(b(4), Nx, mul4(b(5), Ny)), mulAdd4(b(6), Nz, mul4(b(7), Np)));
  o[1] = mulAdd4(dualPart, ps, rotorPart);
}

// matrixCompose(P, b) for an affine b on 4-lane columns: P = the 4 columns of a mat4 (the
// result's last row is P's), b(c) = component c of b as a mat4x3 (column c / 3, row c % 3)
// broadcast: 12 broadcasts, 5 fused + 7 mul + 4 add.
template <class B> HWY_INLINE void affineProduct4(const V4* P, const B& b, V4* o) {
  MB_UNROLL for (size_t j = 0; j < 3; ++j)
    o[j] = add4(mulAdd4(P[0], b(3 * j), mul4(P[1], b(3 * j + 1))), mul4(P[2], b(3 * j + 2)));
  o[3] = add4(mulAdd4(P[0], b(9), mul4(P[1], b(10))), mulAdd4(P[2], b(11), P[3]));
}

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
          motorProduct4(last[0], last[1], L, lane0(last[2]), o);
          o[2] = mul4(lane0(last[2]), L(8));  // lane 0: the world scale
        } else {
          affineProduct4(last, L, o);
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

// Pair palette: out[j] = world[node[j]] * inverseBind[j], both operands read as stored (the
// worlds AoS as Hierarchy writes them, the inverse binds AoS), one product per joint, no
// gather: the same per-joint walk on both sides (the world 4 joints ahead prefetched).
// Affine: inverse bind a column-major mat4 (glTF's inverseBindMatrices; affine, its last row
// 0 0 0 1 taken as such), out 16 floats (mat4). Motor: world 12 floats per node (its
// motor's 8; the scale not applied, as gp_mm), inverse bind and out 8 floats.
// On 256-bit targets (AVX2, AVX-512) one 8-lane vector holds two 4-lane columns (affine: out
// columns 0|1 and 2|3, each world column loaded into both blocks, the inverse bind's factors
// broadcast within the blocks: 7 broadcasts, 7 fused + 2 mul + 2 add per joint) or both halves
// of a motor (gp_mm: the 4 rotor components of the inverse bind times [a0|a1] and 3 signed lane
// permutations of it, its 4 e0 components times 4 signed permutations of a0 into the upper
// block: 8 broadcasts, 7 permutations, 7 fused + 2 mul + 2 add). Narrower targets: the
// hierarchy's 4-lane products, affineProduct4 and motorProduct4.
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX2
using D8 = hn::FixedTag<float, 8>;
using V8 = hn::Vec<D8>;
// Lanes idx[k] of v, the lanes whose sign[k] is -0.0f negated.
HWY_INLINE V8 permSign8(V8 v, const int32_t* idx, const float* sign) {
  const D8 d;
  return hn::Xor(hn::TableLookupLanes(v, hn::SetTableIndices(d, idx)), hn::Load(d, sign));
}
#endif

template <bool kMotor>
void Palette(const float* world, const int32_t* node, const float* inverseBind, float* out, size_t n) {
  constexpr size_t W = kMotor ? kHierarchyMotorFloats : kHierarchyAffineFloats, B = kMotor ? 8 : 16;
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX2
  const D8 d;
  constexpr float z = 0.0f, m = -0.0f;
  // gp_mm's permutations of A = [a0|a1] (X: rotor part, lanes as motorProduct4's M | Q) and of
  // a0 into the upper block (Y: its N), derived from motorProduct4's permSign lanes.
  alignas(32) static constexpr int32_t xi[3][8] = {{1, 0, 3, 2, 7, 6, 5, 4}, {2, 3, 0, 1, 6, 7, 4, 5}, {3, 2, 1, 0, 5, 4, 7, 6}};
  alignas(32) static constexpr float xs[3][8] = {{m, z, m, z, m, m, z, z}, {m, z, z, m, z, m, m, z}, {m, m, z, z, m, z, m, z}};
  alignas(32) static constexpr int32_t yi[4][8] = {
      {0, 3, 2, 1, 0, 3, 2, 1}, {3, 0, 1, 2, 3, 0, 1, 2}, {2, 1, 0, 3, 2, 1, 0, 3}, {1, 2, 3, 0, 1, 2, 3, 0}};
  alignas(32) static constexpr float ys[4][8] = {
      {z, z, z, z, z, m, z, z}, {z, z, z, z, z, z, m, z}, {z, z, z, z, m, z, z, z}, {z, z, z, z, m, m, m, z}};
  alignas(32) static constexpr float upper[8] = {z, z, z, z, 1.0f, 1.0f, 1.0f, 1.0f};
#endif
  for (size_t j = 0; j < n; ++j) {
    if (j + 4 < n) hwy::Prefetch(world + size_t(node[j + 4]) * W);
    const float* a = world + size_t(node[j]) * W;
    const float* ib = inverseBind + j * B;
    float* o = out + j * B;
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX2
    if constexpr (kMotor) {
      const V8 A = hn::LoadU(d, a);
      const V8 R = hn::Add(hn::MulAdd(hn::Set(d, ib[0]), A, hn::Mul(hn::Set(d, ib[1]), permSign8(A, xi[0], xs[0]))),
                           hn::MulAdd(hn::Set(d, ib[2]), permSign8(A, xi[1], xs[1]),
                                      hn::Mul(hn::Set(d, ib[3]), permSign8(A, xi[2], xs[2]))));
      const V8 D = hn::Add(hn::MulAdd(hn::Set(d, ib[4]), permSign8(A, yi[0], ys[0]), hn::Mul(hn::Set(d, ib[5]), permSign8(A, yi[1], ys[1]))),
                           hn::MulAdd(hn::Set(d, ib[6]), permSign8(A, yi[2], ys[2]), hn::Mul(hn::Set(d, ib[7]), permSign8(A, yi[3], ys[3]))));
      hn::StoreU(hn::MulAdd(D, hn::Load(d, upper), R), d, o);  // D's lower block (not N) times 0
    } else {
      const V8 P0 = hn::LoadDup128(d, a), P1 = hn::LoadDup128(d, a + 4), P2 = hn::LoadDup128(d, a + 8),
               P3 = hn::LoadDup128(d, a + 12);
      const V8 I01 = hn::LoadU(d, ib), I23 = hn::LoadU(d, ib + 8);
      const V8 o01 = hn::Add(hn::MulAdd(P0, hn::Broadcast<0>(I01), hn::Mul(P1, hn::Broadcast<1>(I01))),
                             hn::Mul(P2, hn::Broadcast<2>(I01)));
      const V8 o23 = hn::Add(hn::MulAdd(P0, hn::Broadcast<0>(I23), hn::Mul(P1, hn::Broadcast<1>(I23))),
                             hn::MulAdd(P2, hn::Broadcast<2>(I23), hn::Mul(P3, hn::Broadcast<3>(I23))));
      hn::StoreU(o01, d, o), hn::StoreU(o23, d, o + 8);
    }
#else
    V4 r[4];
    if constexpr (kMotor) {
      motorProduct4(load4(a), load4(a + 4), [ib](size_t c) { return set4(ib[c]); }, set4(1.0f), r);
      store4(r[0], o), store4(r[1], o + 4);
    } else {
      const V4 P[4] = {load4(a), load4(a + 4), load4(a + 8), load4(a + 12)};
      affineProduct4(P, [ib](size_t c) { return set4(ib[c + c / 3]); }, r);
      MB_UNROLL for (size_t h = 0; h < 4; ++h) store4(r[h], o + 4 * h);
    }
#endif
  }
}

void PaletteAffine(const float* world, const int32_t* node, const float* inverseBind, float* out, size_t n) {
  Palette<false>(world, node, inverseBind, out, n);
}
void PaletteMotor(const float* world, const int32_t* node, const float* inverseBind, float* out, size_t n) {
  Palette<true>(world, node, inverseBind, out, n);
}

}  // namespace mb::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace mb::simd {

HWY_EXPORT(HierarchyAffine);
HWY_EXPORT(HierarchyMotor);
HWY_EXPORT(PaletteAffine);
HWY_EXPORT(PaletteMotor);

void hierarchyAffine(ConstPlanes trs, const int32_t* parent, size_t n, float* world) {
  HWY_DYNAMIC_DISPATCH(HierarchyAffine)(trs, parent, n, world);
}
void hierarchyMotor(ConstPlanes trs, const int32_t* parent, size_t n, float* world) {
  HWY_DYNAMIC_DISPATCH(HierarchyMotor)(trs, parent, n, world);
}
void paletteAffine(const float* world, const int32_t* node, const float* inverseBind, float* out, size_t n) {
  HWY_DYNAMIC_DISPATCH(PaletteAffine)(world, node, inverseBind, out, n);
}
void paletteMotor(const float* world, const int32_t* node, const float* inverseBind, float* out, size_t n) {
  HWY_DYNAMIC_DISPATCH(PaletteMotor)(world, node, inverseBind, out, n);
}

}  // namespace mb::simd
#endif  // HWY_ONCE
