// shaders/shim/glsl.h: a small GLSL shim so that the project's shader math (shaders/*.glsl)
// also compiles as C++ (DESIGN.md, core idea 4). One source then runs on the GPU, in unit
// tests, with the op-counting scalar (shaders/shim/counted.h) and as the CPU reference path.
//
// Types (namespace glsl, templated on the scalar type S):
//   vec<S,2|3|4>                vec2/vec3/vec4: component-wise + - * /, scalar*vec, vec*scalar
//   mat<S,C,R>                  C columns of vec<S,R> (GLSL matCxR): m[i] is column i,
//                               mat*vec, vec*mat (row vector), mat*mat, + - * scalar
//   GLSL-style constructors: vec4(s) splat, vec4(s, vec3), vec4(vec3, s), mat2x4(vec4, vec4),
//   mat2x4(s, vec3, vec3, s) ... (components are consumed in order, column-major for
//   matrices, and must add up exactly), mat(s) = s * identity, mat3(mat4) upper-left.
//
// How to compile a .glsl module as C++ (see shaders/shim/pga.h for the real use):
//
//   #include "shaders/shim/glsl.h"              // at file scope, before any namespace
//   namespace mb {
//   #define MB_GLSL_CLASS Pga                   // name of the class template to create
//   #include "shaders/shim/glsl_begin.h"        // template <class Scalar> struct Pga { ...
//   #include "shaders/pga.glsl"                 //   the GLSL functions become members
//   #include "shaders/shim/glsl_end.h"          // };  (undefines MB_GLSL_CLASS, float)
//   }
//   mb::Pga<float> P;  P.gp_mm(a, b);          // or Pga<double>, Pga<mb::Counted>
//
// glsl_begin.h opens `template <class Scalar> struct MB_GLSL_CLASS`, declares the GLSL type
// names (vec2..vec4, mat2..mat4, mat2x3, mat2x4, mat3x4, mat4x3 and the PGA vocabulary
// motor = mat2x4, line = mat2x3, point = direction = vec3) and the GLSL built-ins as static
// members, defines MB_GLSL_CPP, and `#define float Scalar`. Functions defined inside a class
// are implicitly inline, so such a header may be included by any number of translation units,
// and one class template serves every scalar type.
//
// The GLSL subset a module must stay within to compile both ways:
//  - No `out`/`inout` parameters: return a struct-free aggregate instead (mat2x3 for two
//    vec3s, mat2x4 for a motor...). `in`/`const` parameters are fine.
//  - Only the built-in types above; no arrays, no structs, no samplers, no uniforms/ins/outs,
//    no `precision`, no integer vectors. Global `const float NAME = value;` is allowed.
//  - Only the swizzles listed below (read-only: never assign to a swizzle; assigning to a
//    single component .x/.y/.z/.w is fine). Add a missing one with one MB_GLSL_SWZ line.
//  - Built-ins: those declared in shaders/shim/glsl_prelude.inl.
//  - Literals are written as in GLSL (1.0, 0.5, 2.). In C++ they are doubles and are converted
//    to the scalar type at the operator, so float code stays float.
//  - Macros: `#define NAME type` for type vocabulary goes under `#ifndef MB_GLSL_CPP` (the
//    C++ side gets type aliases instead); other object-like macros must be #undef'd at the
//    end of the module if they would break C++ code.
//  - Include guards are named MB_<STEM>_GLSL (e.g. MB_PGA_GLSL). A guard must act per C++
//    class, so glsl_end.h #undef's the guards of the shared modules; list a new module there.
//    Nested `#include "x.glsl"` work in both worlds (the GL loader expands each file once per
//    stage; the C++ preprocessor resolves the path relative to the including file).
//
// Swizzles are union members (proxy structs sharing the vector's storage) so that GLSL's
// `a[0].yzw` compiles unchanged. This relies on anonymous structs in unions and union type
// punning, both documented GCC/Clang extensions; -Wpedantic is silenced for those lines only.
#pragma once
#define MB_GLSL_SHIM_H 1

#include <cmath>
#include <type_traits>

namespace glsl {

template <class S, int N> struct vec;
template <class S, int C, int R> struct mat;

// Scalar hooks behind every built-in. The default calls <cmath>; counted.h specialises it for
// mb::Counted so that each call is counted.
template <class S> struct scalar_ops {
  static S sqrt(S x) { return std::sqrt(x); }
  static S inversesqrt(S x) { return S(1) / std::sqrt(x); }
  static S sin(S x) { return std::sin(x); }
  static S cos(S x) { return std::cos(x); }
  static S tan(S x) { return std::tan(x); }
  static S asin(S x) { return std::asin(x); }
  static S acos(S x) { return std::acos(x); }
  static S atan(S x) { return std::atan(x); }
  static S atan2(S y, S x) { return std::atan2(y, x); }
  static S exp(S x) { return std::exp(x); }
  static S log(S x) { return std::log(x); }
  static S exp2(S x) { return std::exp2(x); }
  static S log2(S x) { return std::log2(x); }
  static S pow(S x, S y) { return std::pow(x, y); }
  static S abs(S x) { return std::abs(x); }
  static S sign(S x) { return x > S(0) ? S(1) : (x < S(0) ? S(-1) : S(0)); }
  static S floor(S x) { return std::floor(x); }
  static S ceil(S x) { return std::ceil(x); }
  static S min(S x, S y) { return y < x ? y : x; }
  static S max(S x, S y) { return x < y ? y : x; }
};

namespace detail {

// Read-only swizzle view of components I... of an N-vector. R (= vec<S, sizeof...(I)>) is a
// template argument on purpose: it makes R's hidden-friend operators visible through
// argument-dependent lookup, so `s * v.yzw` or `v.yzw + w` resolve with an implicit conversion.
template <class S, int N, class R, int... I> struct Swz {
  S v[N];
  operator R() const { return R(v[I]...); }
};

template <class T> struct ncomp : std::integral_constant<int, 1> {};
template <class S, int N> struct ncomp<vec<S, N>> : std::integral_constant<int, N> {};
template <class S, int N, class R, int... I>
struct ncomp<Swz<S, N, R, I...>> : std::integral_constant<int, int(sizeof...(I))> {};

// Appends the components of one constructor argument (scalar, literal, vector, swizzle).
template <class S, class T> void put(S* out, int& k, const T& a) {
  if constexpr (ncomp<T>::value == 1) {
    out[k++] = S(a);
  } else {
    const vec<S, ncomp<T>::value> v = a;
    for (int i = 0; i < ncomp<T>::value; ++i) out[k++] = v[i];
  }
}

template <class S, class... A> constexpr bool total_is(int n) {
  return (0 + ... + ncomp<std::remove_cvref_t<A>>::value) == n;
}

// Operators shared by every vector size, as hidden friends (non-templates, so that swizzle
// proxies and literals convert implicitly). Each scalar operation is one S operation, which is
// what the op counter sees: vec3 + vec3 is 3 additions, s * vec3 is 3 multiplications.
template <class S, int N> struct vec_ops {
  using V = vec<S, N>;
  template <class F> static V map(F f) {
    V r;
    for (int i = 0; i < N; ++i) r[i] = f(i);
    return r;
  }
  friend V operator+(const V& a, const V& b) { return map([&](int i) { return a[i] + b[i]; }); }
  friend V operator-(const V& a, const V& b) { return map([&](int i) { return a[i] - b[i]; }); }
  friend V operator*(const V& a, const V& b) { return map([&](int i) { return a[i] * b[i]; }); }
  friend V operator/(const V& a, const V& b) { return map([&](int i) { return a[i] / b[i]; }); }
  friend V operator+(const V& a, const S& s) { return map([&](int i) { return a[i] + s; }); }
  friend V operator-(const V& a, const S& s) { return map([&](int i) { return a[i] - s; }); }
  friend V operator*(const V& a, const S& s) { return map([&](int i) { return a[i] * s; }); }
  friend V operator/(const V& a, const S& s) { return map([&](int i) { return a[i] / s; }); }
  friend V operator+(const S& s, const V& a) { return map([&](int i) { return s + a[i]; }); }
  friend V operator-(const S& s, const V& a) { return map([&](int i) { return s - a[i]; }); }
  friend V operator*(const S& s, const V& a) { return map([&](int i) { return s * a[i]; }); }
  friend V operator/(const S& s, const V& a) { return map([&](int i) { return s / a[i]; }); }
  friend V operator-(const V& a) { return map([&](int i) { return -a[i]; }); }
  friend V operator+(const V& a) { return a; }
  friend V& operator+=(V& a, const V& b) { return a = a + b; }
  friend V& operator-=(V& a, const V& b) { return a = a - b; }
  friend V& operator*=(V& a, const V& b) { return a = a * b; }
  friend V& operator/=(V& a, const V& b) { return a = a / b; }
  friend V& operator*=(V& a, const S& s) { return a = a * s; }
  friend V& operator/=(V& a, const S& s) { return a = a / s; }
  friend bool operator==(const V& a, const V& b) {
    for (int i = 0; i < N; ++i)
      if (!(a[i] == b[i])) return false;
    return true;
  }
};

}  // namespace detail

#define MB_GLSL_SWZ(N, M, name, ...) ::glsl::detail::Swz<S, N, ::glsl::vec<S, M>, __VA_ARGS__> name

// The common part of vec2/vec3/vec4: storage access, constructors.
#define MB_GLSL_VEC_COMMON(N)                                                                   \
  vec() { for (int i = 0; i < N; ++i) e[i] = S(0); }                                          \
  explicit vec(const S& s) { for (int i = 0; i < N; ++i) e[i] = s; }                          \
  template <class A0, class A1, class... A>                                                   \
    requires(detail::total_is<S, A0, A1, A...>(N))                                            \
  vec(const A0& a0, const A1& a1, const A&... a) {                                            \
    int k = 0;                                                                                \
    detail::put(e, k, a0);                                                                    \
    detail::put(e, k, a1);                                                                    \
    (detail::put(e, k, a), ...);                                                              \
  }                                                                                           \
  /* GLSL vec3(vec4) etc.: drop the trailing components. */                                  \
  template <int M>                                                                            \
    requires(M > N)                                                                           \
  explicit vec(const vec<S, M>& o) { for (int i = 0; i < N; ++i) e[i] = o[i]; }               \
  /* Scalar-type conversion (float <-> double <-> Counted), C++ only. */                      \
  template <class T>                                                                          \
    requires(!std::is_same_v<T, S>)                                                           \
  explicit vec(const vec<T, N>& o) { for (int i = 0; i < N; ++i) e[i] = static_cast<S>(o[i]); } \
  S& operator[](int i) { return e[i]; }                                                       \
  const S& operator[](int i) const { return e[i]; }                                           \
  static constexpr int length() { return N; }

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
#endif

template <class S> struct vec<S, 2> : detail::vec_ops<S, 2> {
  union {
    S e[2];
    struct { S x, y; };
    MB_GLSL_SWZ(2, 2, yx, 1, 0);
  };
  MB_GLSL_VEC_COMMON(2)
};

template <class S> struct vec<S, 3> : detail::vec_ops<S, 3> {
  union {
    S e[3];
    struct { S x, y, z; };
    MB_GLSL_SWZ(3, 2, xy, 0, 1);
    MB_GLSL_SWZ(3, 2, yz, 1, 2);
    MB_GLSL_SWZ(3, 3, xyz, 0, 1, 2);  // the paper's printed exp_b (shaders/paper_listings.glsl)
    MB_GLSL_SWZ(3, 3, zyx, 2, 1, 0);
  };
  MB_GLSL_VEC_COMMON(3)
};

template <class S> struct vec<S, 4> : detail::vec_ops<S, 4> {
  union {
    S e[4];
    struct { S x, y, z, w; };
    MB_GLSL_SWZ(4, 2, xy, 0, 1);
    MB_GLSL_SWZ(4, 2, zw, 2, 3);
    MB_GLSL_SWZ(4, 3, xyz, 0, 1, 2);
    MB_GLSL_SWZ(4, 3, yzw, 1, 2, 3);
    MB_GLSL_SWZ(4, 3, wzy, 3, 2, 1);  // the paper's printed log_m (shaders/paper_listings.glsl)
  };
  MB_GLSL_VEC_COMMON(4)
};

#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
#undef MB_GLSL_VEC_COMMON

// matCxR: C columns, R rows, column-major like GLSL (m[i] is column i).
template <class S, int C, int R> struct mat {
  using Col = vec<S, R>;
  using Row = vec<S, C>;
  Col c[C];

  mat() = default;  // zero (columns default to zero)
  explicit mat(const S& d) {  // d * identity
    for (int i = 0; i < C && i < R; ++i) c[i][i] = d;
  }
  template <class A0, class A1, class... A>
    requires(detail::total_is<S, A0, A1, A...>(C * R))
  mat(const A0& a0, const A1& a1, const A&... a) {
    S f[C * R];
    int k = 0;
    detail::put(f, k, a0);
    detail::put(f, k, a1);
    (detail::put(f, k, a), ...);
    for (int i = 0; i < C; ++i)
      for (int j = 0; j < R; ++j) c[i][j] = f[i * R + j];
  }
  // GLSL matrix-from-matrix: copy the overlap, identity elsewhere (mat3(mat4), mat4(mat3)).
  template <int C2, int R2>
    requires(C2 != C || R2 != R)
  explicit mat(const mat<S, C2, R2>& o) : mat(S(1)) {
    for (int i = 0; i < C && i < C2; ++i)
      for (int j = 0; j < R && j < R2; ++j) c[i][j] = o[i][j];
  }
  template <class T>
    requires(!std::is_same_v<T, S>)
  explicit mat(const mat<T, C, R>& o) {
    for (int i = 0; i < C; ++i) c[i] = Col(o[i]);
  }

  Col& operator[](int i) { return c[i]; }
  const Col& operator[](int i) const { return c[i]; }
  static constexpr int length() { return C; }

  template <class F> static mat map(F f) {
    mat r;
    for (int i = 0; i < C; ++i) r.c[i] = f(i);
    return r;
  }
  friend mat operator+(const mat& a, const mat& b) { return map([&](int i) { return a[i] + b[i]; }); }
  friend mat operator-(const mat& a, const mat& b) { return map([&](int i) { return a[i] - b[i]; }); }
  friend mat operator-(const mat& a) { return map([&](int i) { return -a[i]; }); }
  friend mat operator*(const mat& a, const S& s) { return map([&](int i) { return a[i] * s; }); }
  friend mat operator*(const S& s, const mat& a) { return map([&](int i) { return s * a[i]; }); }
  friend mat operator/(const mat& a, const S& s) { return map([&](int i) { return a[i] / s; }); }
  friend mat& operator+=(mat& a, const mat& b) { return a = a + b; }
  friend mat& operator-=(mat& a, const mat& b) { return a = a - b; }
  friend mat& operator*=(mat& a, const S& s) { return a = a * s; }
  friend bool operator==(const mat& a, const mat& b) {
    for (int i = 0; i < C; ++i)
      if (!(a[i] == b[i])) return false;
    return true;
  }
  // Column vector: sum of columns weighted by v (C*R mul, (C-1)*R add).
  friend Col operator*(const mat& m, const Row& v) {
    Col r = m[0] * v[0];
    for (int i = 1; i < C; ++i) r = r + m[i] * v[i];
    return r;
  }
  // Row vector: one dot product per column (C*R mul, C*(R-1) add).
  friend Row operator*(const Col& v, const mat& m) {
    Row r;
    for (int i = 0; i < C; ++i) {
      S d = v[0] * m[i][0];
      for (int j = 1; j < R; ++j) d = d + v[j] * m[i][j];
      r[i] = d;
    }
    return r;
  }
  // matCxR * matKxC = matKxR: one mat*vec per column of b.
  template <int K> friend mat<S, K, R> operator*(const mat& a, const mat<S, K, C>& b) {
    mat<S, K, R> r;
    for (int i = 0; i < K; ++i) r[i] = a * b[i];
    return r;
  }
};

template <class S, int C, int R> mat<S, R, C> transpose(const mat<S, C, R>& m) {
  mat<S, R, C> t;
  for (int i = 0; i < C; ++i)
    for (int j = 0; j < R; ++j) t[j][i] = m[i][j];
  return t;
}

// GLSL built-ins over exact types. glsl_prelude.inl wraps them as non-template static
// members of a shader class so that proxies and literals convert at the call.
namespace builtin {

template <class S> using ops = scalar_ops<S>;

template <class S, int N, class F> vec<S, N> each(const vec<S, N>& a, F f) {
  vec<S, N> r;
  for (int i = 0; i < N; ++i) r[i] = f(a[i]);
  return r;
}
template <class S, int N, class F> vec<S, N> each(const vec<S, N>& a, const vec<S, N>& b, F f) {
  vec<S, N> r;
  for (int i = 0; i < N; ++i) r[i] = f(a[i], b[i]);
  return r;
}

template <class S, int N> S dot(const vec<S, N>& a, const vec<S, N>& b) {
  S d = a[0] * b[0];
  for (int i = 1; i < N; ++i) d = d + a[i] * b[i];
  return d;
}
template <class S> vec<S, 3> cross(const vec<S, 3>& a, const vec<S, 3>& b) {
  return vec<S, 3>(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
template <class S, int N> S length(const vec<S, N>& a) { return ops<S>::sqrt(dot(a, a)); }
template <class S, int N> S distance(const vec<S, N>& a, const vec<S, N>& b) { return length(a - b); }
template <class S, int N> vec<S, N> normalize(const vec<S, N>& a) {
  return a * ops<S>::inversesqrt(dot(a, a));
}
template <class S, int N> vec<S, N> reflect(const vec<S, N>& i, const vec<S, N>& n) {
  return i - S(2) * dot(n, i) * n;
}

}  // namespace builtin
}  // namespace glsl
