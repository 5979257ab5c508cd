// shaders/shim/glsl_prelude.inl: the GLSL vocabulary inside a shader class (see glsl.h).
// Included by glsl_begin.h inside `template <class Scalar> struct MB_GLSL_CLASS { ... };`.
// No include guard on purpose. Built-ins are non-template static members taking the exact
// GLSL types, so swizzle proxies (v.yzw) and double literals convert at the call.

using vec2 = ::glsl::vec<Scalar, 2>;
using vec3 = ::glsl::vec<Scalar, 3>;
using vec4 = ::glsl::vec<Scalar, 4>;
using mat2 = ::glsl::mat<Scalar, 2, 2>;
using mat3 = ::glsl::mat<Scalar, 3, 3>;
using mat4 = ::glsl::mat<Scalar, 4, 4>;
using mat2x3 = ::glsl::mat<Scalar, 2, 3>;
using mat2x4 = ::glsl::mat<Scalar, 2, 4>;
using mat3x4 = ::glsl::mat<Scalar, 3, 4>;
using mat4x3 = ::glsl::mat<Scalar, 4, 3>;
// The PGA vocabulary of shaders/pga.glsl (there: #define motor mat2x4 ... for GLSL only).
using motor = mat2x4;      // [[s, e23, e31, e12], [e01, e02, e03, e0123]]
using line = mat2x3;       // [[e23, e31, e12], [e01, e02, e03]]
using point = vec3;        // (e032, e013, e021), implied e123 = 1
using direction = vec3;    // (e032, e013, e021), implied e123 = 0
// Instantiate the vector classes now: their hidden-friend operators must be visible to
// argument-dependent lookup when only a swizzle proxy names them.
static_assert(sizeof(vec2) + sizeof(vec3) + sizeof(vec4) > 0);

#define MB_GLSL_GEN1(fn, expr)                                                            \
  static Scalar fn(const Scalar& x) { return expr; }                                      \
  static vec2 fn(const vec2& v) { return ::glsl::builtin::each(v, [](const Scalar& x) { return expr; }); } \
  static vec3 fn(const vec3& v) { return ::glsl::builtin::each(v, [](const Scalar& x) { return expr; }); } \
  static vec4 fn(const vec4& v) { return ::glsl::builtin::each(v, [](const Scalar& x) { return expr; }); }
#define MB_GLSL_GEN2(fn, expr)                                                            \
  static Scalar fn(const Scalar& x, const Scalar& y) { return expr; }                     \
  static vec2 fn(const vec2& a, const vec2& b) {                                          \
    return ::glsl::builtin::each(a, b, [](const Scalar& x, const Scalar& y) { return expr; }); } \
  static vec3 fn(const vec3& a, const vec3& b) {                                          \
    return ::glsl::builtin::each(a, b, [](const Scalar& x, const Scalar& y) { return expr; }); } \
  static vec4 fn(const vec4& a, const vec4& b) {                                          \
    return ::glsl::builtin::each(a, b, [](const Scalar& x, const Scalar& y) { return expr; }); }

MB_GLSL_GEN1(sqrt, ::glsl::scalar_ops<Scalar>::sqrt(x))
MB_GLSL_GEN1(inversesqrt, ::glsl::scalar_ops<Scalar>::inversesqrt(x))
MB_GLSL_GEN1(sin, ::glsl::scalar_ops<Scalar>::sin(x))
MB_GLSL_GEN1(cos, ::glsl::scalar_ops<Scalar>::cos(x))
MB_GLSL_GEN1(tan, ::glsl::scalar_ops<Scalar>::tan(x))
MB_GLSL_GEN1(asin, ::glsl::scalar_ops<Scalar>::asin(x))
MB_GLSL_GEN1(acos, ::glsl::scalar_ops<Scalar>::acos(x))
MB_GLSL_GEN1(atan, ::glsl::scalar_ops<Scalar>::atan(x))
MB_GLSL_GEN1(exp, ::glsl::scalar_ops<Scalar>::exp(x))
MB_GLSL_GEN1(log, ::glsl::scalar_ops<Scalar>::log(x))
MB_GLSL_GEN1(exp2, ::glsl::scalar_ops<Scalar>::exp2(x))
MB_GLSL_GEN1(log2, ::glsl::scalar_ops<Scalar>::log2(x))
MB_GLSL_GEN1(abs, ::glsl::scalar_ops<Scalar>::abs(x))
MB_GLSL_GEN1(sign, ::glsl::scalar_ops<Scalar>::sign(x))
MB_GLSL_GEN1(floor, ::glsl::scalar_ops<Scalar>::floor(x))
MB_GLSL_GEN1(ceil, ::glsl::scalar_ops<Scalar>::ceil(x))
MB_GLSL_GEN1(fract, x - ::glsl::scalar_ops<Scalar>::floor(x))
MB_GLSL_GEN2(atan, ::glsl::scalar_ops<Scalar>::atan2(x, y))
MB_GLSL_GEN2(pow, ::glsl::scalar_ops<Scalar>::pow(x, y))
MB_GLSL_GEN2(min, ::glsl::scalar_ops<Scalar>::min(x, y))
MB_GLSL_GEN2(max, ::glsl::scalar_ops<Scalar>::max(x, y))
MB_GLSL_GEN2(mod, x - y * ::glsl::scalar_ops<Scalar>::floor(x / y))
MB_GLSL_GEN2(step, x <= y ? Scalar(1) : Scalar(0))  // step(edge, x): 0 below the edge
#undef MB_GLSL_GEN1
#undef MB_GLSL_GEN2

static vec2 min(const vec2& a, const Scalar& b) { return min(a, vec2(b)); }
static vec3 min(const vec3& a, const Scalar& b) { return min(a, vec3(b)); }
static vec4 min(const vec4& a, const Scalar& b) { return min(a, vec4(b)); }
static vec2 max(const vec2& a, const Scalar& b) { return max(a, vec2(b)); }
static vec3 max(const vec3& a, const Scalar& b) { return max(a, vec3(b)); }
static vec4 max(const vec4& a, const Scalar& b) { return max(a, vec4(b)); }
static Scalar clamp(const Scalar& x, const Scalar& lo, const Scalar& hi) { return min(max(x, lo), hi); }
static vec2 clamp(const vec2& x, const vec2& lo, const vec2& hi) { return min(max(x, lo), hi); }
static vec3 clamp(const vec3& x, const vec3& lo, const vec3& hi) { return min(max(x, lo), hi); }
static vec4 clamp(const vec4& x, const vec4& lo, const vec4& hi) { return min(max(x, lo), hi); }
static vec2 clamp(const vec2& x, const Scalar& lo, const Scalar& hi) { return min(max(x, lo), hi); }
static vec3 clamp(const vec3& x, const Scalar& lo, const Scalar& hi) { return min(max(x, lo), hi); }
static vec4 clamp(const vec4& x, const Scalar& lo, const Scalar& hi) { return min(max(x, lo), hi); }
// mix(x, y, a) = x + (y - x) * a: per component 1 mul, 2 add.
static Scalar mix(const Scalar& x, const Scalar& y, const Scalar& a) { return x + (y - x) * a; }
static vec2 mix(const vec2& x, const vec2& y, const Scalar& a) { return x + (y - x) * a; }
static vec3 mix(const vec3& x, const vec3& y, const Scalar& a) { return x + (y - x) * a; }
static vec4 mix(const vec4& x, const vec4& y, const Scalar& a) { return x + (y - x) * a; }
static vec2 mix(const vec2& x, const vec2& y, const vec2& a) { return x + (y - x) * a; }
static vec3 mix(const vec3& x, const vec3& y, const vec3& a) { return x + (y - x) * a; }
static vec4 mix(const vec4& x, const vec4& y, const vec4& a) { return x + (y - x) * a; }

static Scalar dot(const vec2& a, const vec2& b) { return ::glsl::builtin::dot(a, b); }
static Scalar dot(const vec3& a, const vec3& b) { return ::glsl::builtin::dot(a, b); }
static Scalar dot(const vec4& a, const vec4& b) { return ::glsl::builtin::dot(a, b); }
static vec3 cross(const vec3& a, const vec3& b) { return ::glsl::builtin::cross(a, b); }
static Scalar length(const Scalar& a) { return abs(a); }
static Scalar length(const vec2& a) { return ::glsl::builtin::length(a); }
static Scalar length(const vec3& a) { return ::glsl::builtin::length(a); }
static Scalar length(const vec4& a) { return ::glsl::builtin::length(a); }
static Scalar distance(const vec2& a, const vec2& b) { return ::glsl::builtin::distance(a, b); }
static Scalar distance(const vec3& a, const vec3& b) { return ::glsl::builtin::distance(a, b); }
static Scalar distance(const vec4& a, const vec4& b) { return ::glsl::builtin::distance(a, b); }
static vec2 normalize(const vec2& a) { return ::glsl::builtin::normalize(a); }
static vec3 normalize(const vec3& a) { return ::glsl::builtin::normalize(a); }
static vec4 normalize(const vec4& a) { return ::glsl::builtin::normalize(a); }
static vec3 reflect(const vec3& i, const vec3& n) { return ::glsl::builtin::reflect(i, n); }
static mat2 transpose(const mat2& m) { return ::glsl::transpose(m); }
static mat3 transpose(const mat3& m) { return ::glsl::transpose(m); }
static mat4 transpose(const mat4& m) { return ::glsl::transpose(m); }
