// Vertex frame and skinned vertex (simd_kernels.h), compiled once per Highway target and
// dispatched at run time to the best one the CPU supports.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernels/simd/simd_vertex.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "kernels/simd/simd_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace mb::simd::HWY_NAMESPACE {

// Pair vertex frame: planar in (matrix 10 planes: position, normal, tangent; motor 7:
// position, tangent rotor) and the same 10 output planes, uniforms broadcast before the loop,
// every input plane prefetched. Matrix 27 fused + 1 mul per vertex (matrixAffineVertex); motor
// 3 mul + 18 (sw_mp) + 16 (gp_rr) + 13 (frame) + 1 sign = 51 (motorRigidVertex).
void VertexFrameMatrix(const float* model, const float* normal, float mirror, ConstPlanes in, Planes out,
                       size_t n) {
  const bool nt = streamOutput(out, 10, n);
  forEachBatch(n, nt, [&](auto d, size_t b, size_t e, bool main) {
    using V = hn::Vec<decltype(d)>;
    V m[12], nm[9], v[10], o[10];
    broadcast(d, model, m);
    broadcast(d, normal, nm);
    const V mir = hn::Set(d, mirror);
    for (size_t i = b; i < e; i += hn::Lanes(d)) {
      if (main) prefetchPlanes(in, 10, i);
      loadPlanes(d, in, i, v);
      affineVertex(m, nm, mir, v, v + 3, v + 6, o);
      storePlanes(d, out, i, o, main && nt);
    }
  });
}

void VertexFrameMotor(const float* motor, float scale, ConstPlanes in, Planes out, size_t n) {
  const float c3[3] = {motor[7] * motor[1], motor[7] * motor[2], motor[7] * motor[3]};
  const bool nt = streamOutput(out, 10, n);
  forEachBatch(n, nt, [&](auto d, size_t b, size_t e, bool main) {
    using V = hn::Vec<decltype(d)>;
    V m[8], c[3], v[7], o[10];
    broadcast(d, motor, m);
    broadcast(d, c3, c);
    const V s = hn::Set(d, scale), two = hn::Set(d, 2.0f), half = hn::Set(d, 0.5f), one = hn::Set(d, 1.0f);
    for (size_t i = b; i < e; i += hn::Lanes(d)) {
      if (main) prefetchPlanes(in, 7, i);
      loadPlanes(d, in, i, v);
      motorVertex(m, c, s, v, v + 3, two, half, one, o);
      storePlanes(d, out, i, o, main && nt);
    }
  });
}

// Pair skinned vertex: the same planar vertex streams as the vertex frame pair plus 4 uint16
// joint planes and 4 weight planes (all prefetched); each joint's palette entry is read by
// PaletteFetch (lane permutations of a palette held in registers, or GatherIndex component by
// component: matrix 4 x 12 = 48 gathers, motor 4 x 8 = 32, with PaletteFetchMode::Gathered or
// a palette too large for the registers). Matrix: blend
// 12 mul + 36 fused, cofactor 18, matrixAffineVertex 28 (affineSkinnedVertex). Motor: blend
// with the hemisphere rule 8 mul + 3 x (4 fused, 1 select, 8 fused), normalize_m ~22 with an
// estimate + Newton step for inversesqrt, then motorRigidVertex 51 (motorSkinnedVertex).
// Prefetches (main loop) and loads item i's vertex planes and weights; the joint planes are
// prefetched too (their indices are loaded at the gathers).
template <class D, size_t C>
HWY_INLINE void loadSkinned(D d, bool main, ConstPlanes in, ConstPlanes weights, JointPlanes joints, size_t i,
                            hn::Vec<D> (&v)[C], hn::Vec<D> (&w)[4]) {
  if (main) {
    prefetchPlanes(in, C, i), prefetchPlanes(weights, 4, i);
    MB_UNROLL for (size_t k = 0; k < 4; ++k) hwy::Prefetch(joints[k] + i + kPrefetchAhead);
  }
  loadPlanes(d, in, i, v);
  loadPlanes(d, weights, i, w);
}

void SkinnedVertexMatrix(ConstPlanes palette, float mirror, ConstPlanes in, JointPlanes joints, ConstPlanes weights,
                         Planes out, size_t n, PaletteFetchMode mode) {
  const bool nt = streamOutput(out, 10, n);
  forEachBatch(n, nt, [&](auto d, size_t b, size_t e, bool main) {
    using V = hn::Vec<decltype(d)>;
    const V mir = hn::Set(d, mirror);
    const PaletteFetch<decltype(d), 12> fetch(d, palette, main && mode == PaletteFetchMode::InRegisters);
    V v[10], w[4], skin[12], j[12], cof[9], o[10];
    for (size_t i = b; i < e; i += hn::Lanes(d)) {
      loadSkinned(d, main, in, weights, joints, i, v, w);
      fetch(d, jointIndices(d, joints, 0, i), j);
      MB_UNROLL for (size_t c = 0; c < 12; ++c) skin[c] = hn::Mul(w[0], j[c]);
      MB_UNROLL for (size_t k = 1; k < 4; ++k) {
        fetch(d, jointIndices(d, joints, k, i), j);
        MB_UNROLL for (size_t c = 0; c < 12; ++c) skin[c] = hn::MulAdd(w[k], j[c], skin[c]);
      }
      cofactor(skin, cof);
      affineVertex(skin, cof, mir, v, v + 3, v + 6, o);
      storePlanes(d, out, i, o, main && nt);
    }
  });
}

void SkinnedVertexMotor(ConstPlanes palette, float scale, ConstPlanes in, JointPlanes joints, ConstPlanes weights,
                        Planes out, size_t n, PaletteFetchMode mode) {
  const bool nt = streamOutput(out, 10, n);
  forEachBatch(n, nt, [&](auto d, size_t b, size_t e, bool main) {
    using V = hn::Vec<decltype(d)>;
    const V s = hn::Set(d, scale), two = hn::Set(d, 2.0f), half = hn::Set(d, 0.5f), one = hn::Set(d, 1.0f);
    const V zero = hn::Zero(d);
    const PaletteFetch<decltype(d), 8> fetch(d, palette, main && mode == PaletteFetchMode::InRegisters);
    V v[7], w[4], r[8], j[8], c[3], o[10];
    for (size_t i = b; i < e; i += hn::Lanes(d)) {
      loadSkinned(d, main, in, weights, joints, i, v, w);
      fetch(d, jointIndices(d, joints, 0, i), j);
      MB_UNROLL for (size_t k = 0; k < 8; ++k) r[k] = hn::Mul(j[k], w[0]);
      MB_UNROLL for (size_t k = 1; k < 4; ++k) {
        fetch(d, jointIndices(d, joints, k, i), j);
        // Hemisphere rule: the weight is negated when dot(r rotor half, joint rotor half) <= 0.
        const V dot = hn::MulAdd(r[0], j[0], hn::MulAdd(r[1], j[1], hn::MulAdd(r[2], j[2], hn::Mul(r[3], j[3]))));
        const V wk = hn::IfThenElse(hn::Le(dot, zero), hn::Neg(w[k]), w[k]);
        MB_UNROLL for (size_t q = 0; q < 8; ++q) r[q] = hn::MulAdd(j[q], wk, r[q]);
      }
      motorNormalize(d, r);
      c[0] = hn::Mul(r[7], r[1]), c[1] = hn::Mul(r[7], r[2]), c[2] = hn::Mul(r[7], r[3]);
      motorVertex(r, c, s, v, v + 3, two, half, one, o);
      storePlanes(d, out, i, o, main && nt);
    }
  });
}

}  // namespace mb::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace mb::simd {

HWY_EXPORT(VertexFrameMatrix);
HWY_EXPORT(VertexFrameMotor);
HWY_EXPORT(SkinnedVertexMatrix);
HWY_EXPORT(SkinnedVertexMotor);

void vertexFrameMatrix(const float model[12], const float normal[9], float mirror, ConstPlanes in, Planes out,
                       size_t n) {
  HWY_DYNAMIC_DISPATCH(VertexFrameMatrix)(model, normal, mirror, in, out, n);
}
void vertexFrameMotor(const float motor[8], float scale, ConstPlanes in, Planes out, size_t n) {
  HWY_DYNAMIC_DISPATCH(VertexFrameMotor)(motor, scale, in, out, n);
}
void skinnedVertexMatrix(ConstPlanes palette, float mirror, ConstPlanes in, JointPlanes joints, ConstPlanes weights,
                         Planes out, size_t n, PaletteFetchMode fetch) {
  HWY_DYNAMIC_DISPATCH(SkinnedVertexMatrix)(palette, mirror, in, joints, weights, out, n, fetch);
}
void skinnedVertexMotor(ConstPlanes palette, float scale, ConstPlanes in, JointPlanes joints, ConstPlanes weights,
                        Planes out, size_t n, PaletteFetchMode fetch) {
  HWY_DYNAMIC_DISPATCH(SkinnedVertexMotor)(palette, scale, in, joints, weights, out, n, fetch);
}

void mat4ToAffine(const float model[16], const float normal[16], float model12[12], float normal9[9], float* mirror) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 3; ++r) model12[c * 3 + r] = model[c * 4 + r];
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) normal9[c * 3 + r] = normal[c * 4 + r];
  *mirror = normal[15];
}

}  // namespace mb::simd
#endif  // HWY_ONCE
