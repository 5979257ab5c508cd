// harness/bench/affine_compose.h: composition of two affine transforms stored as GLSL mat4x3
// (4 columns of 3 rows: the linear part and the translation, the implied last row 0 0 0 1),
// the form production engines compose their scene graphs in. On the shim's types, so the same
// source is counted (mb::Counted) and timed (float).
//   counted: mat3 * mat3 27 mul 18 add, mat3 * vec3 9 mul 6 add, + translation 3 add = 36/27.
#pragma once
#include "harness/bench/bench_shaders.h"

namespace mb::bench {

// a * b as 4x4 matrices (b applied first), without the constant last row.
template <class S>
typename MatrixShader<S>::mat4x3 affineCompose(const typename MatrixShader<S>::mat4x3& a,
                                               const typename MatrixShader<S>::mat4x3& b) {
  using M = MatrixShader<S>;
  const typename M::mat3 A(a), B(b);
  const typename M::mat3 L = A * B;
  return typename M::mat4x3(L[0], L[1], L[2], A * b[3] + a[3]);
}

}  // namespace mb::bench
