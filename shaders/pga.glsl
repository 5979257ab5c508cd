// pga.glsl: the PGA toolbox of "Look, Ma, No Matrices!" (De Keninck, SIGGRAPH 2024), written
// once in the GLSL subset of shaders/shim/glsl.h: it is included by vertex shaders on the GPU
// and compiled as C++ (mb::Pga<S>, shaders/shim/pga.h) for tests, op counting and CPU paths.
// Derived from the algebra of 3D PGA R(3,0,1) (e0^2 = 0, e1^2 = e2^2 = e3^2 = 1).
//
// Layout (the paper's, also the reference implementation's):
//   motor     = mat2x4 [[s, e23, e31, e12], [e01, e02, e03, e0123]]
//   line      = mat2x3 [[e23, e31, e12], [e01, e02, e03]]      (bivector)
//   point     = vec3   (e032, e013, e021), implied e123 = 1
//   direction = vec3   (e032, e013, e021), implied e123 = 0
// Suffixes: _m general motor, _r rotor about the origin (second column zero), _t translator
// (first column (1,0,0,0), e0123 = 0), _p point, _d direction, _v vector (plane through origin).
// gp_ab(a, b) is the geometric product a b: as transformations, b is applied first (like the
// matrix product A B). A normalised motor has M ~M = 1.
//
// glTF conventions (checked against GLM in tests/pga/test_pga_products.cpp):
//   rotation quaternion (x, y, z, w)  -> rotor      [w, -x, -y, -z | 0, 0, 0, 0]
//   translation t                     -> translator [1, 0, 0, 0 | -t.x/2, -t.y/2, -t.z/2, 0]
//   node TRS (uniform scale aside)    -> gp_tr(translator, rotor) = T R
// Sandwiching a point or direction with such a motor equals applying the node's 4x4 matrix.
//
// Every "measured:" line is what `motorbench ops` counts by executing this file with
// mb::Counted (shaders/shim/counted.h): subtraction counts as addition, negation is free,
// "other" = any other built-in call. The paper's claim follows where it makes one.
#ifndef MB_PGA_GLSL
#define MB_PGA_GLSL

#ifndef MB_GLSL_CPP
#define motor     mat2x4
#define line      mat2x3
#define point     vec3
#define direction vec3
#endif

// ---- composition --------------------------------------------------------------------------

// General motor product a b.
// measured: 48 mul, 40 add (paper: 48, 40)
motor gp_mm(motor a, motor b) {
  vec3 A = a[0].yzw, B = b[0].yzw, Ad = a[1].xyz, Bd = b[1].xyz;
  float s = a[0].x * b[0].x - dot(A, B);
  vec3 e = a[0].x * B + b[0].x * A + cross(B, A);
  vec3 d = a[0].x * Bd + b[0].x * Ad + cross(B, Ad) + cross(Bd, A) - b[1].w * A - a[1].w * B;
  float p = a[0].x * b[1].w + b[0].x * a[1].w + dot(A, Bd) + dot(Ad, B);
  return motor(s, e, d, p);
}

// Rotor times rotor (both about the origin); the result is a rotor.
// measured: 16 mul, 12 add (paper: 16, 12)
motor gp_rr(motor a, motor b) {
  vec3 A = a[0].yzw, B = b[0].yzw;
  return motor(vec4(a[0].x * b[0].x - dot(A, B), a[0].x * B + b[0].x * A + cross(B, A)), vec4(0.));
}

// Translator times translator; the result is a translator.
// measured: 0 mul, 3 add (paper: 0, 3)
motor gp_tt(motor a, motor b) {
  return motor(vec4(1., 0., 0., 0.), vec4(a[1].xyz + b[1].xyz, 0.));
}

// Rotor a times translator b.
// measured: 12 mul, 8 add (paper: 12, 8)
motor gp_rt(motor a, motor b) {
  vec3 A = a[0].yzw, Bd = b[1].xyz;
  return motor(a[0], vec4(a[0].x * Bd + cross(Bd, A), dot(A, Bd)));
}

// Translator a times rotor b (T R: rotate, then translate).
// measured: 12 mul, 8 add (paper: 12, 8)
motor gp_tr(motor a, motor b) {
  vec3 B = b[0].yzw, Ad = a[1].xyz;
  return motor(b[0], vec4(b[0].x * Ad + cross(B, Ad), dot(Ad, B)));
}

// Rotor a times general motor b.
// measured: 32 mul, 24 add (paper: 32, 24)
motor gp_rm(motor a, motor b) {
  vec3 A = a[0].yzw, B = b[0].yzw, Bd = b[1].xyz;
  return motor(a[0].x * b[0].x - dot(A, B),
               a[0].x * B + b[0].x * A + cross(B, A),
               a[0].x * Bd + cross(Bd, A) - b[1].w * A,
               a[0].x * b[1].w + dot(A, Bd));
}

// General motor a times rotor b.
// measured: 32 mul, 24 add (paper: 32, 24)
motor gp_mr(motor a, motor b) {
  vec3 A = a[0].yzw, B = b[0].yzw, Ad = a[1].xyz;
  return motor(a[0].x * b[0].x - dot(A, B),
               a[0].x * B + b[0].x * A + cross(B, A),
               b[0].x * Ad + cross(B, Ad) - a[1].w * B,
               b[0].x * a[1].w + dot(Ad, B));
}

// Translator a times general motor b.
// measured: 12 mul, 12 add (paper: 12, 12)
motor gp_tm(motor a, motor b) {
  vec3 B = b[0].yzw, Ad = a[1].xyz;
  return motor(b[0], vec4(b[1].xyz + b[0].x * Ad + cross(B, Ad), b[1].w + dot(Ad, B)));
}

// General motor a times translator b.
// measured: 12 mul, 12 add (paper: 12, 12)
motor gp_mt(motor a, motor b) {
  vec3 A = a[0].yzw, Bd = b[1].xyz;
  return motor(a[0], vec4(a[1].xyz + a[0].x * Bd + cross(Bd, A), a[1].w + dot(A, Bd)));
}

// Product of two vectors (planes through the origin) a b = a.b + a^b: a rotor that rotates
// by twice the angle from a to b (sqrt_m halves it).
// measured: 9 mul, 5 add (no claim)
motor gp_vv(vec3 a, vec3 b) {
  return motor(vec4(dot(a, b), cross(a, b)), vec4(0.));
}

// ---- sandwiches (a must be normalised) ----------------------------------------------------

// a b ~a for a point, evaluated as the two full products (trivector part of (a b) ~a), without
// using a ~a = 1. For a normalised motor the e123 part is 1, so this is the transformed point.
// measured: 36 mul, 33 add (paper: 33, 29)
point sw_mp_naive(motor a, point b) {
  vec3 A = a[0].yzw, Ad = a[1].xyz;
  // a b = (e0: x0, e1..e3: -A) + (e032..e021: T, e123: a[0].x)
  float x0 = dot(A, b) - a[1].w;
  vec3 T = a[0].x * b + cross(b, A) - Ad;
  return a[0].x * T + cross(T, A) + x0 * A - a[0].x * Ad + cross(A, Ad) - a[1].w * A;
}

// a b ~a for a point, using a ~a = 1 (p' = a p ~a + p (1 - a ~a)).
// measured: 21 mul, 18 add (paper: 21, 18)
point sw_mp(motor a, point b) {
  vec3 A = a[0].yzw;
  vec3 t = cross(b, A) - a[1].xyz;
  return (a[0].x * t + cross(t, A) - a[1].w * A) * 2. + b;
}

// a b ~a for a direction (translation drops out).
// measured: 18 mul, 12 add (paper: 18, 12)
direction sw_md(motor a, direction b) {
  vec3 A = a[0].yzw;
  vec3 t = cross(b, A);
  return (a[0].x * t + cross(t, A)) * 2. + b;
}

// Image of the basis directions e032 (x), e013 (y), e021 (z), SCALED BY 0.5 (the paper's
// trick: the 0.5 avoids the doubling; normalise or double the result where length matters).
// measured: 6 mul, 4 add each (paper: 6, 4 for "e.g. the x axis")
direction sw_mx(motor a) {
  return direction(0.5 - a[0].z * a[0].z - a[0].w * a[0].w,
                   a[0].y * a[0].z - a[0].x * a[0].w,
                   a[0].y * a[0].w + a[0].x * a[0].z);
}
direction sw_my(motor a) {
  return direction(a[0].x * a[0].w + a[0].y * a[0].z,
                   0.5 - a[0].y * a[0].y - a[0].w * a[0].w,
                   a[0].z * a[0].w - a[0].x * a[0].y);
}
direction sw_mz(motor a) {
  return direction(a[0].y * a[0].w - a[0].x * a[0].z,
                   a[0].x * a[0].y + a[0].z * a[0].w,
                   0.5 - a[0].z * a[0].z - a[0].y * a[0].y);
}

// Image of the origin e123 (the translation column of the motor's matrix).
// measured: 15 mul, 9 add (no paper claim; the reference source says 15, 9)
point sw_mo(motor a) {
  vec3 A = a[0].yzw, Ad = a[1].xyz;
  return -2. * (a[0].x * Ad + cross(Ad, A) + a[1].w * A);
}

// World normal (column 0) and tangent (column 1) from a tangent-frame rotor that maps x to the
// tangent and z to the normal: sw_mz and sw_mx sharing products; both SCALED BY 0.5.
// The handedness is not in here: it is the sign of the vertex rotor's scalar part
// (shaders/motor_transform.glsl, motorHandedness).
// measured: 9 mul, 8 add (paper: 9, 8)
mat2x3 extractNormalTangent(motor a) {
  float yw = a[0].y * a[0].w;
  float xz = a[0].x * a[0].z;
  float zz = a[0].z * a[0].z;
  return mat2x3(yw - xz, a[0].z * a[0].w + a[0].y * a[0].x, 0.5 - zz - a[0].y * a[0].y,
                0.5 - zz - a[0].w * a[0].w, a[0].z * a[0].y - a[0].x * a[0].w, yw + xz);
}

// ---- reverse, normalisation, square root --------------------------------------------------

// ~a: flips the bivector part. The inverse of a normalised motor.
// measured: 0 mul, 0 add (negations are free)
motor reverse_m(motor a) {
  return motor(a[0].x, -a[0].yzw, -a[1].xyz, a[1].w);
}

// a / |a| with the Study-number inverse square root: |a|^2 = a ~a = n + m e0123 and
// 1/sqrt(n + m e0123) = 1/sqrt(n) - m/(2 n sqrt(n)) e0123. Result: M ~M = 1 exactly in
// the algebra, the same rigid motion as a (a Gram-Schmidt of the motor manifold).
// measured: 22 mul, 10 add, 1 inversesqrt (paper: 21 mul, 5 add with 1 div, 1 sqrt)
motor normalize_m(motor a) {
  float s = inversesqrt(dot(a[0], a[0]));
  float d = (a[1].w * a[0].x - dot(a[1].xyz, a[0].yzw)) * (s * s);
  return motor(a[0] * s, (a[1] + d * vec4(a[0].yzw, -a[0].x)) * s);
}

// Square root of a normalised motor: normalize_m(1 + R). Not defined for R = -1.
// measured: 22 mul, 11 add, 1 inversesqrt (paper: 21, 6)
motor sqrt_m(motor R) {
  return normalize_m(motor(R[0].x + 1., R[0].yzw, R[1]));
}

// ---- exponential and logarithm ------------------------------------------------------------

// exp(B) of a bivector B = (u on e23,e31,e12; v on e01,e02,e03): a screw motion by twice |u|
// about the line, when u.v = 0. For u = 0 a translator.
// measured: 17 mul, 8 add, 2 div, 1 sqrt, 1 cos, 1 sin (paper: 17, 8, 2 div, 1 sqrt, cos, sin)
motor exp_b(line B) {
  float l = dot(B[0], B[0]);
  if (l == 0.) return motor(vec4(1., 0., 0., 0.), vec4(B[1], 0.));
  float a = sqrt(l), m = dot(B[0], B[1]), c = cos(a), s = sin(a) / a, t = m / l * (c - s);
  return motor(c, s * B[0], s * B[1] + t * B[0], m * s);
}

// log(M) of a normalised motor, the inverse of exp_b for |u| < pi (scalar part > -1).
// 1 - s^2 is evaluated as (1 - s)(1 + s): accurate near s = 1 (small rotations) in float.
// measured: 14 mul, 6 add, 1 div, 1 sqrt, 1 acos (paper: 14, 5, 1 div, 1 acos, 1 sqrt)
line log_m(motor M) {
  if (M[0].x >= 1.) return line(vec3(0.), M[1].xyz);
  float a = 1. / ((1. - M[0].x) * (1. + M[0].x));
  float b = acos(M[0].x) * sqrt(a);
  float c = a * M[1].w * (1. - M[0].x * b);
  return line(b * M[0].yzw, b * M[1].xyz + c * M[0].yzw);
}

// exp(angle * B) for a line B through the origin (only B[0] is used): the rotor
// [cos(angle), sin(angle) B[0]]. As the reference's exp_r, the angle is NOT halved: with
// B = e23 the rotor turns by -2 angle about +x (right-handed), i.e. quaternion angle -2 angle.
// measured: 3 mul, 0 add, 1 sin, 1 cos (reference source: 3 mul, cos, sin)
motor exp_r(float angle, line B) {
  return motor(cos(angle), sin(angle) * B[0], vec4(0.));
}

// exp(dist * B) for an ideal line B (only B[1] is used): the translator [1, dist B[1]].
// As the reference's exp_t: with B = e01 it translates by -2 dist along x.
// measured: 3 mul, 0 add (reference source: 3 mul)
motor exp_t(float dist, line B) {
  return motor(vec4(1., 0., 0., 0.), vec4(dist * B[1], 0.));
}

// ---- projection ---------------------------------------------------------------------------

// The reference's perspective projection of a view-space point (camera looks down +z, x is
// mirrored): equals glm::perspective(minfov, aspect, n, f) * vec4(-p.x, p.y, -p.z, 1) when the
// vertical fov is the minimal one. The first three lines are per-draw constants on a GPU.
// measured: 9 mul, 4 add, 4 div, 1 sin, 1 cos (no claim)
vec4 project(const float n, const float f, const float minfov, float aspect, vec3 inpos) {
  float cthf = cos(0.5 * minfov) / sin(0.5 * minfov);
  float fa = 2. * f * n / (n - f), fb = (n + f) / (n - f);
  vec2 fit = cthf * vec2(-1. / aspect, 1.);
  return vec4(inpos.xy * fit, fa - fb * inpos.z, inpos.z);
}

#endif  // MB_PGA_GLSL
