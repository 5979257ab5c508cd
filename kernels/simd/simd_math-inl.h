// Per-target building blocks of the SIMD kernels (kernels/simd/simd_*.cpp): the loop driver and
// the lane-wise forms of the shader functions. Included once per Highway target (the usual
// toggle guard), inside the kernels' HWY_NAMESPACE.
#if defined(MB_SIMD_MATH_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef MB_SIMD_MATH_INL_H_
#undef MB_SIMD_MATH_INL_H_
#else
#define MB_SIMD_MATH_INL_H_
#endif

#include <cstdint>

#include "hwy/cache_control.h"
#include "hwy/highway.h"
#include "kernels/simd/simd_kernels.h"

HWY_BEFORE_NAMESPACE();
namespace mb::simd::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// MB_UNROLL before a loop over planes, rows or components: the count is a small constant and
// the loop must vanish, so its arrays (uniforms, vertex planes, results) live in registers.
// GCC at -O2 peels such loops only when that does not grow the code: the matrix vertex kept
// three 3-trip row loops over stack arrays, reloading every uniform and input from the stack
// and storing every result to it (kernels/simd/README.md has the measurement).
#define MB_UNROLL _Pragma("GCC unroll 16")

// Input planes are prefetched this many floats ahead (1 KiB per plane: enough to cover the
// memory latency at one core's bandwidth; 20 planes x 1 KiB stay well inside L1).
constexpr size_t kPrefetchAhead = 256;

// Output bytes from which a kernel writes with non-temporal (streaming) stores: far beyond the
// L2 and most last-level caches, where a normal store first reads the line it overwrites
// (write-allocate) and so moves twice the bytes it writes. The same rule for every kernel.
constexpr size_t kStreamBytes = size_t(64) << 20;

// Whether a call writing `count` planes of n floats streams: large, and every plane aligned to
// the widest vector (64 bytes; then the full-vector stores of the main loop are aligned).
HWY_INLINE bool streamOutput(Planes out, size_t count, size_t n) {
  if (n * count * sizeof(float) < kStreamBytes) return false;
  for (size_t c = 0; c < count; ++c)
    if (reinterpret_cast<uintptr_t>(out[c]) % 64) return false;
  return true;
}

// Runs range(d, begin, end, main) over [0, n): full vectors of the target's width (main =
// true: prefetch, streaming stores allowed), then the tail one lane at a time, so every kernel
// handles any n with one body. `stream`: the kernel streamed its stores (fenced at the end).
template <class Range> HWY_INLINE void forEachBatch(size_t n, bool stream, const Range& range) {
  const hn::ScalableTag<float> d;
  const size_t full = n / hn::Lanes(d) * hn::Lanes(d);
  range(d, size_t(0), full, true);
  range(hn::CappedTag<float, 1>(), full, n, false);
  if (stream) hwy::FlushStream();
}

// Prefetches `count` planes of `p` at item i + kPrefetchAhead.
HWY_INLINE void prefetchPlanes(ConstPlanes p, size_t count, size_t i) {
  MB_UNROLL for (size_t c = 0; c < count; ++c) hwy::Prefetch(p[c] + i + kPrefetchAhead);
}

template <class D, size_t C> HWY_INLINE void loadPlanes(D d, ConstPlanes p, size_t i, hn::Vec<D> (&v)[C]) {
  MB_UNROLL for (size_t c = 0; c < C; ++c) v[c] = hn::LoadU(d, p[c] + i);
}
template <class D, size_t C>
HWY_INLINE void storePlanes(D d, Planes p, size_t i, const hn::Vec<D> (&v)[C], bool stream) {
  if (stream) {
    MB_UNROLL for (size_t c = 0; c < C; ++c) hn::Stream(v[c], d, p[c] + i);
  } else {
    MB_UNROLL for (size_t c = 0; c < C; ++c) hn::StoreU(v[c], d, p[c] + i);
  }
}
// Per-draw uniforms broadcast to every lane.
template <class D, size_t C> HWY_INLINE void broadcast(D d, const float* u, hn::Vec<D> (&v)[C]) {
  MB_UNROLL for (size_t c = 0; c < C; ++c) v[c] = hn::Set(d, u[c]);
}

// ---- matrix side -----------------------------------------------------------------------------

// Affine point: rows 0..2 of m * (p, 1), m a mat4x3 (or the first 12... of a column-major mat4
// read with column stride `cs`: 3 for mat4x3, 4 for mat4).
template <class V> HWY_INLINE void affinePoint(const V* m, size_t cs, V x, V y, V z, V* o) {
  MB_UNROLL for (size_t r = 0; r < 3; ++r)
    o[r] = hn::MulAdd(m[r], x, hn::MulAdd(m[cs + r], y, hn::MulAdd(m[2 * cs + r], z, m[3 * cs + r])));
}
// Linear part only: rows 0..2 of m * (v, 0).
template <class V> HWY_INLINE void linearDirection(const V* m, size_t cs, V x, V y, V z, V* o) {
  MB_UNROLL for (size_t r = 0; r < 3; ++r)
    o[r] = hn::MulAdd(m[r], x, hn::MulAdd(m[cs + r], y, hn::Mul(m[2 * cs + r], z)));
}

// matrixAffineVertex: model mat4x3 m[12], normal mat3 nm[9]; in p[3], n[3], t[4]; out[10].
template <class V> HWY_INLINE void affineVertex(const V* m, const V* nm, V mirror, const V* p, const V* n,
                                                const V* t, V* out) {
  affinePoint(m, 3, p[0], p[1], p[2], out);
  linearDirection(nm, 3, n[0], n[1], n[2], out + 3);
  linearDirection(m, 3, t[0], t[1], t[2], out + 6);
  out[9] = hn::Mul(t[3], mirror);
}

template <class V> HWY_INLINE void cross(V ax, V ay, V az, V bx, V by, V bz, V* o) {
  o[0] = hn::MulSub(ay, bz, hn::Mul(az, by));
  o[1] = hn::MulSub(az, bx, hn::Mul(ax, bz));
  o[2] = hn::MulSub(ax, by, hn::Mul(ay, bx));
}

// affineCofactor of the linear part of m (mat4x3): the columns' cross products.
template <class V> HWY_INLINE void cofactor(const V* m, V* c) {
  cross(m[3], m[4], m[5], m[6], m[7], m[8], c);
  cross(m[6], m[7], m[8], m[0], m[1], m[2], c + 3);
  cross(m[0], m[1], m[2], m[3], m[4], m[5], c + 6);
}

// a * b for mat4x3 operands (an affine product; 36 mul, 27 add).
template <class V> HWY_INLINE void affineProduct(const V* a, const V* b, V* o) {
  MB_UNROLL for (size_t j = 0; j < 3; ++j) linearDirection(a, 3, b[3 * j], b[3 * j + 1], b[3 * j + 2], o + 3 * j);
  affinePoint(a, 3, b[9], b[10], b[11], o + 9);
}

// ---- motor side ------------------------------------------------------------------------------
// Motors as 8 lanes-vectors m[0..7] = [s, e23, e31, e12, e01, e02, e03, e0123].

// sw_mp(m, b) with c = m[7] * m[1..3] given (a per-draw constant for a uniform motor).
template <class V> HWY_INLINE void motorPoint(const V* m, const V* c, V bx, V by, V bz, V two, V* o) {
  const V Ax = m[1], Ay = m[2], Az = m[3];
  // t = cross(b, A) - Ad
  const V tx = hn::MulSub(by, Az, hn::MulAdd(bz, Ay, m[4]));
  const V ty = hn::MulSub(bz, Ax, hn::MulAdd(bx, Az, m[5]));
  const V tz = hn::MulSub(bx, Ay, hn::MulAdd(by, Ax, m[6]));
  // (s t + cross(t, A) - e0123 A) * 2 + b
  o[0] = hn::MulAdd(hn::MulAdd(m[0], tx, hn::MulSub(ty, Az, hn::MulAdd(tz, Ay, c[0]))), two, bx);
  o[1] = hn::MulAdd(hn::MulAdd(m[0], ty, hn::MulSub(tz, Ax, hn::MulAdd(tx, Az, c[1]))), two, by);
  o[2] = hn::MulAdd(hn::MulAdd(m[0], tz, hn::MulSub(tx, Ay, hn::MulAdd(ty, Ax, c[2]))), two, bz);
}

// sw_md(m, b).
template <class V> HWY_INLINE void motorDirection(const V* m, V bx, V by, V bz, V two, V* o) {
  const V Ax = m[1], Ay = m[2], Az = m[3];
  V t[3];
  cross(bx, by, bz, Ax, Ay, Az, t);
  o[0] = hn::MulAdd(hn::MulAdd(m[0], t[0], hn::MulSub(t[1], Az, hn::Mul(t[2], Ay))), two, bx);
  o[1] = hn::MulAdd(hn::MulAdd(m[0], t[1], hn::MulSub(t[2], Ax, hn::Mul(t[0], Az))), two, by);
  o[2] = hn::MulAdd(hn::MulAdd(m[0], t[2], hn::MulSub(t[0], Ay, hn::Mul(t[1], Ax))), two, bz);
}

// extractNormalTangent(gp_rr(m, rotor r)) into o[0..5] (normal, tangent; both half length).
template <class V> HWY_INLINE void motorFrame(const V* m, const V* r, V half, V* o) {
  const V as = m[0], Ax = m[1], Ay = m[2], Az = m[3];
  const V bs = r[0], Bx = r[1], By = r[2], Bz = r[3];
  // gp_rr: s = as bs - A.B; e = as B + bs A + cross(B, A)
  const V x = hn::MulSub(as, bs, hn::MulAdd(Ax, Bx, hn::MulAdd(Ay, By, hn::Mul(Az, Bz))));
  const V y = hn::MulAdd(as, Bx, hn::MulAdd(bs, Ax, hn::MulSub(By, Az, hn::Mul(Bz, Ay))));
  const V z = hn::MulAdd(as, By, hn::MulAdd(bs, Ay, hn::MulSub(Bz, Ax, hn::Mul(Bx, Az))));
  const V w = hn::MulAdd(as, Bz, hn::MulAdd(bs, Az, hn::MulSub(Bx, Ay, hn::Mul(By, Ax))));
  // extractNormalTangent
  const V yw = hn::Mul(y, w), h = hn::NegMulAdd(z, z, half);
  o[0] = hn::NegMulAdd(x, z, yw);
  o[1] = hn::MulAdd(z, w, hn::Mul(y, x));
  o[2] = hn::NegMulAdd(y, y, h);
  o[3] = hn::NegMulAdd(w, w, h);
  o[4] = hn::MulSub(z, y, hn::Mul(x, w));
  o[5] = hn::MulAdd(x, z, yw);
}

// motorRigidVertex(m, scale, p, rotor) into out[10]; c = m[7] * m[1..3].
template <class V> HWY_INLINE void motorVertex(const V* m, const V* c, V scale, const V* p, const V* rotor,
                                               V two, V half, V one, V* out) {
  motorPoint(m, c, hn::Mul(p[0], scale), hn::Mul(p[1], scale), hn::Mul(p[2], scale), two, out);
  V nt[6];
  motorFrame(m, rotor, half, nt);
  out[3] = nt[0], out[4] = nt[1], out[5] = nt[2];
  out[6] = nt[3], out[7] = nt[4], out[8] = nt[5];
  out[9] = hn::CopySign(one, rotor[0]);  // sign(1 / s): the sign bit, signed zero included
}

// gp_mm(a, b) (48 mul, 40 add as the shader; fused here).
template <class V> HWY_INLINE void motorProduct(const V* a, const V* b, V* o) {
  const V as = a[0], Ax = a[1], Ay = a[2], Az = a[3], Adx = a[4], Ady = a[5], Adz = a[6], ap = a[7];
  const V bs = b[0], Bx = b[1], By = b[2], Bz = b[3], Bdx = b[4], Bdy = b[5], Bdz = b[6], bp = b[7];
  o[0] = hn::MulSub(as, bs, hn::MulAdd(Ax, Bx, hn::MulAdd(Ay, By, hn::Mul(Az, Bz))));
  o[1] = hn::MulAdd(as, Bx, hn::MulAdd(bs, Ax, hn::MulSub(By, Az, hn::Mul(Bz, Ay))));
  o[2] = hn::MulAdd(as, By, hn::MulAdd(bs, Ay, hn::MulSub(Bz, Ax, hn::Mul(Bx, Az))));
  o[3] = hn::MulAdd(as, Bz, hn::MulAdd(bs, Az, hn::MulSub(Bx, Ay, hn::Mul(By, Ax))));
  // d = as Bd + bs Ad + cross(B, Ad) + cross(Bd, A) - bp A - ap B
  o[4] = hn::NegMulAdd(ap, Bx, hn::NegMulAdd(bp, Ax, hn::NegMulAdd(Bdz, Ay, hn::MulAdd(Bdy, Az,
         hn::NegMulAdd(Bz, Ady, hn::MulAdd(By, Adz, hn::MulAdd(bs, Adx, hn::Mul(as, Bdx))))))));
  o[5] = hn::NegMulAdd(ap, By, hn::NegMulAdd(bp, Ay, hn::NegMulAdd(Bdx, Az, hn::MulAdd(Bdz, Ax,
         hn::NegMulAdd(Bx, Adz, hn::MulAdd(Bz, Adx, hn::MulAdd(bs, Ady, hn::Mul(as, Bdy))))))));
  o[6] = hn::NegMulAdd(ap, Bz, hn::NegMulAdd(bp, Az, hn::NegMulAdd(Bdy, Ax, hn::MulAdd(Bdx, Ay,
         hn::NegMulAdd(By, Adx, hn::MulAdd(Bx, Ady, hn::MulAdd(bs, Adz, hn::Mul(as, Bdz))))))));
  // p = as bp + bs ap + A.Bd + Ad.B
  o[7] = hn::MulAdd(as, bp, hn::MulAdd(bs, ap, hn::MulAdd(Ax, Bdx, hn::MulAdd(Ay, Bdy,
         hn::MulAdd(Az, Bdz, hn::MulAdd(Adx, Bx, hn::MulAdd(Ady, By, hn::Mul(Adz, Bz))))))));
}

// normalize_m(m) in place: inversesqrt as the hardware estimate refined by one Newton step
// (x86 targets) or an exact divide (portable fallbacks).
template <class D, class V> HWY_INLINE void motorNormalize(D d, V* m) {
  const V n = hn::MulAdd(m[0], m[0], hn::MulAdd(m[1], m[1], hn::MulAdd(m[2], m[2], hn::Mul(m[3], m[3]))));
#if HWY_TARGET == HWY_SCALAR || HWY_TARGET == HWY_EMU128
  // The portable targets' estimate is a bit trick (~1e-3): divide instead.
  const V s = hn::Div(hn::Set(d, 1.0f), hn::Sqrt(n));
#else
  // x86 estimates have >= 12 bits; one Newton step gives ~23.
  V s = hn::ApproximateReciprocalSqrt(n);
  s = hn::Mul(s, hn::NegMulAdd(hn::Mul(hn::Set(d, 0.5f), n), hn::Mul(s, s), hn::Set(d, 1.5f)));
#endif
  const V q = hn::MulSub(m[7], m[0], hn::MulAdd(m[4], m[1], hn::MulAdd(m[5], m[2], hn::Mul(m[6], m[3]))));
  const V dd = hn::Mul(q, hn::Mul(s, s));
  m[4] = hn::Mul(hn::MulAdd(dd, m[1], m[4]), s);
  m[5] = hn::Mul(hn::MulAdd(dd, m[2], m[5]), s);
  m[6] = hn::Mul(hn::MulAdd(dd, m[3], m[6]), s);
  m[7] = hn::Mul(hn::NegMulAdd(dd, m[0], m[7]), s);
  MB_UNROLL for (int c = 0; c < 4; ++c) m[c] = hn::Mul(m[c], s);
}

// Gathers component planes [0, C) of a palette at the lanes' indices.
template <class D, class VI, size_t C>
HWY_INLINE void gatherPlanes(D d, ConstPlanes palette, VI idx, hn::Vec<D> (&v)[C]) {
  MB_UNROLL for (size_t c = 0; c < C; ++c) v[c] = hn::GatherIndex(d, palette[c], idx);
}

// The palette fetch of the skinned pair: where the whole palette fits in at most
// kMaxBlocks vectors per component (AVX-512: 64 joints, AVX2: 32, SSE4: 16), it is held in
// registers (one vector of joints per block) and each lane's entry is a lane permutation per
// block, the blocks chosen by the index's high bits; else, and for the one-lane tail, one
// GatherIndex per component (a gather costs many micro-ops per lane: the skinned kernels'
// limit, kernels/simd/README.md).
template <class D, size_t C> struct PaletteFetch {
  using V = hn::Vec<D>;
  static constexpr size_t kMaxBlocks = 4;
  V table[C][kMaxBlocks];
  size_t blocks = 0;  // 0: gathered
  ConstPlanes palette;
  PaletteFetch(D d, ConstPlanes p, bool inRegisters) : palette(p) {
    const size_t L = hn::Lanes(d), J = p.stride, n = (J + L - 1) / L;
    if (!inRegisters || L == 1 || n > kMaxBlocks) return;
    blocks = n;
    HWY_ALIGN float lanes[HWY_LANES(float)];
    for (size_t c = 0; c < C; ++c)
      for (size_t b = 0; b < n; ++b) {
        for (size_t i = 0; i < L; ++i) lanes[i] = b * L + i < J ? p[c][b * L + i] : 0.0f;
        table[c][b] = hn::Load(d, lanes);
      }
  }
  template <class VI> HWY_INLINE void operator()(D d, VI idx, V (&v)[C]) const {
    if (!blocks) {
      MB_UNROLL for (size_t c = 0; c < C; ++c) v[c] = hn::GatherIndex(d, palette[c], idx);
      return;
    }
    const hn::RebindToSigned<D> di;
    const int32_t L = int32_t(hn::Lanes(d));
    const auto lane = hn::IndicesFromVec(d, hn::And(idx, hn::Set(di, L - 1)));
    MB_UNROLL for (size_t c = 0; c < C; ++c) v[c] = hn::TableLookupLanes(table[c][0], lane);
    for (size_t b = 1; b < blocks; ++b) {
      const auto inBlock = hn::RebindMask(d, hn::Gt(idx, hn::Set(di, int32_t(b) * L - 1)));
      MB_UNROLL for (size_t c = 0; c < C; ++c) v[c] = hn::IfThenElse(inBlock, hn::TableLookupLanes(table[c][b], lane), v[c]);
    }
  }
};

// Joint indices of plane k at item i as int32 lanes.
template <class D> HWY_INLINE hn::Vec<hn::RebindToSigned<D>> jointIndices(D /*d*/, JointPlanes j, size_t k, size_t i) {
  const hn::Rebind<uint16_t, D> d16;
  const hn::RebindToUnsigned<D> du;
  return hn::BitCast(hn::RebindToSigned<D>(), hn::PromoteTo(du, hn::LoadU(d16, j[k] + i)));
}

}  // namespace mb::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // MB_SIMD_MATH_INL_H_
