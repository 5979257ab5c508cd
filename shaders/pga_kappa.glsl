// pga_kappa.glsl: the curvature-generic PGA products. The algebra of pga.glsl with
// e0^2 = MB_KAPPA instead of 0: MB_KAPPA = 0 Euclidean (these functions ARE pga.glsl's, same
// counts), +1 elliptic (spherical space S3, motors = Spin(4)), -1 hyperbolic (H3, Spin(3,1)).
// MB_KAPPA must be #defined to 0, 1 or -1 before inclusion: it is a compile-time constant per
// variant (a shader #define on the GPU; one C++ class per value through shaders/shim/pga_kappa.h),
// so kappa = +-1 costs sign flips (free), never multiplications.
//
// Layout as pga.glsl: motor [[s, e23, e31, e12], [e01, e02, e03, e0123]]. A point of curved
// space is a vec4 (x, y, z, w) = x e032 + y e013 + z e021 + w e123 with
//   S3: x^2 + y^2 + z^2 + w^2 = 1        H3: x^2 + y^2 + z^2 - w^2 = -1 (w > 0)
// and the origin (0, 0, 0, 1); the same formula moves tangent vectors (dot(p, v) = 0 in the
// space's metric), so one function serves positions and normals.
// Derivation (why the kappa terms look like this): write a motor M = R + e0 Q with R in the
// even algebra of e1..e3 (s, A) and Q odd (d on e1..e3, p on e123). e0 commutes with R and
// anticommutes with Q, so (R1 + e0 Q1)(R2 + e0 Q2) = R1 R2 - kappa Q1 Q2 + e0 (R1 Q2 + Q1 R2):
// the only new term of the product is -kappa Q1 Q2 in the rotor part. The point sandwich was
// expanded symbolically (e0^2 = kappa) and factored around pga.glsl's t = x x A - w d.
// Unit motor: M ~M = s^2 + |A|^2 + kappa (|d|^2 + p^2) = 1 and s p - A.d = 0.
//
// "measured:" lines are counts of the kappa = +-1 variants by execution with mb::Counted
// (tests/test_pga_kappa.cpp checks them; kappa = 0 equals pga.glsl's).
#ifndef MB_PGA_KAPPA_GLSL
#define MB_PGA_KAPPA_GLSL

#ifndef MB_KAPPA
#error "pga_kappa.glsl: #define MB_KAPPA 0, 1 or -1 before including it"
#endif

#include "pga.glsl"

// kappa * x for the compile-time kappa: x, -x (free) or 0 (the caller drops the term).
#if MB_KAPPA > 0
#define MB_KAPPA_TIMES(x) (x)
#else
#define MB_KAPPA_TIMES(x) (-(x))
#endif

// ---- composition --------------------------------------------------------------------------

// General motor product a b (b applied first).
// measured: 64 mul, 56 add (kappa = 0: gp_mm, 48 mul, 40 add)
motor gp_mm_k(motor a, motor b) {
#if MB_KAPPA == 0
  return gp_mm(a, b);
#else
  vec3 Ad = a[1].xyz, Bd = b[1].xyz;
  motor e = gp_mm(a, b);
  // -kappa Q_a Q_b with Q = (p - d) as a quaternion: scalar p_a p_b - Ad.Bd, bivector below.
  float s = a[1].w * b[1].w - dot(Ad, Bd);
  vec3 v = cross(Ad, Bd) + b[1].w * Ad + a[1].w * Bd;
  return motor(e[0] + MB_KAPPA_TIMES(vec4(s, -v)), e[1]);
#endif
}

// ---- sandwiches (a must be normalised) ----------------------------------------------------

#if MB_KAPPA == 0
// kappa = 0: a point is vec3 with implied w = 1; this is pga.glsl's sw_mp.
// measured: 21 mul, 18 add
point sw_mp_k(motor a, point b) { return sw_mp(a, b); }
#else
// a b ~a for a point or tangent vector b = (x, y, z, w) of curved space.
// measured: 64 mul, 48 add
vec4 sw_mp_k(motor a, vec4 b) {
  vec3 A = a[0].yzw, d = a[1].xyz, x = b.xyz;
  float s = a[0].x, p = a[1].w, w = b.w;
  vec3 t = cross(x, A) - w * d;
  vec3 u = d * dot(d, x) + p * (p * x + cross(d, x));
  vec3 e = x + (s * t + cross(t, A) - (w * p) * A - MB_KAPPA_TIMES(u)) * 2.;
  float c = w * (dot(d, d) + p * p) - dot(s * d + p * A + cross(A, d), x);
  return vec4(e, w - MB_KAPPA_TIMES(c) * 2.);
}
#endif

// ---- normalisation, exponential -----------------------------------------------------------

// a / |a|: |a|^2 = a ~a = n + 2 m e0123 (n = |a0|^2 + kappa |a1|^2, m = s p - A.d) and
// 1/sqrt(n + 2 m I) ~ (1 - (m/n) I) / sqrt(n). Exact for kappa = 0 (pga.glsl's normalize_m);
// for kappa = +-1 the remaining error of M ~M is 3 (m/n)^2: the first-order fix for drift.
// measured: 30 mul, 18 add, 1 inversesqrt (kappa = 0: normalize_m, 22 mul, 10 add)
motor normalize_m_k(motor a) {
#if MB_KAPPA == 0
  return normalize_m(a);
#else
  float n = dot(a[0], a[0]) + MB_KAPPA_TIMES(dot(a[1], a[1]));
  float s = inversesqrt(n);
  float d = (a[1].w * a[0].x - dot(a[1].xyz, a[0].yzw)) * (s * s);
  // a (1 - d I): I = e0123 maps [s, A | D, p] to [kappa p, -kappa D | -A, s].
  return motor(a[0] - MB_KAPPA_TIMES(d * vec4(a[1].w, -a[1].xyz)),
               a[1] + d * vec4(a[0].yzw, -a[0].x)) * s;
#endif
}

// The motor that moves the origin by `dist` along the unit direction u (a translation in
// R3, a rotation of the (u, w) plane by dist in S3, a boost in H3): [c, 0 | -s u, 0] with
// (c, s) = (1, dist/2), (cos, sin)(dist/2), (cosh, sinh)(dist/2).
// measured: 5 mul, 0 add, 1 sin, 1 cos (kappa = -1: 6 mul, 2 add, 1 div, 1 exp; 0: 4 mul)
motor translator_k(float dist, vec3 u) {
#if MB_KAPPA == 0
  return motor(vec4(1., 0., 0., 0.), vec4(-0.5 * dist * u, 0.));
#elif MB_KAPPA > 0
  return motor(vec4(cos(0.5 * dist), 0., 0., 0.), vec4(-sin(0.5 * dist) * u, 0.));
#else
  float e = exp(0.5 * dist), ie = 1. / e;
  return motor(vec4(0.5 * (e + ie), 0., 0., 0.), vec4((0.5 * (ie - e)) * u, 0.));
#endif
}

// ---- S3 only: the motor as its quaternion pair --------------------------------------------
#if MB_KAPPA > 0
// In S3 the pseudoscalar I = e0123 squares to +1 and is central in the even algebra, so
// (1 +- I)/2 split a motor into two quaternions: L = (s + p, A - d), R = (s - p, -A - d),
// stored as vec4 (real, i, j, k). A point (x, y, z, w) as the quaternion X = w + x i + y j + z k
// moves as X -> R X L: the reference's x -> q1 x q2 (non-euclidean-rendering.txt), up to the
// order of its coordinates. pair = mat2x4 [L, R].

// Hamilton product of quaternions stored (real, i, j, k).
// measured: 16 mul, 12 add
vec4 qmul(vec4 a, vec4 b) {
  return vec4(a.x * b.x - dot(a.yzw, b.yzw), a.x * b.yzw + b.x * a.yzw + cross(a.yzw, b.yzw));
}

// measured: 0 mul, 8 add
mat2x4 pair_from_motor(motor a) {
  return mat2x4(a[0].x + a[1].w, a[0].yzw - a[1].xyz, a[0].x - a[1].w, -a[0].yzw - a[1].xyz);
}

// measured: 8 mul, 8 add
motor motor_from_pair(mat2x4 q) {
  return motor(q[0].x + q[1].x, q[0].yzw - q[1].yzw, -(q[0].yzw + q[1].yzw), q[0].x - q[1].x) * 0.5;
}

// Product of two motors in pair form (a b: b applied first): (L_a L_b ... ) per factor.
// X -> R_a (R_b X L_b) L_a, so the pair of a b is (L_b L_a, R_a R_b).
// measured: 32 mul, 24 add
mat2x4 gp_pair(mat2x4 a, mat2x4 b) { return mat2x4(qmul(b[0], a[0]), qmul(a[1], b[1])); }

// Renormalisation of a pair: each quaternion to unit length (exact: the pair of a unit motor
// is two unit quaternions).
// measured: 16 mul, 6 add, 2 inversesqrt
mat2x4 normalize_pair(mat2x4 q) {
  return mat2x4(q[0] * inversesqrt(dot(q[0], q[0])), q[1] * inversesqrt(dot(q[1], q[1])));
}

// Sandwich of a point or tangent vector (x, y, z, w) with a unit pair.
// measured: 32 mul, 24 add
vec4 sw_pair(mat2x4 a, vec4 b) {
  vec4 X = qmul(qmul(a[1], vec4(b.w, b.xyz)), a[0]);
  return vec4(X.yzw, X.x);
}
#endif

#undef MB_KAPPA_TIMES
#endif  // MB_PGA_KAPPA_GLSL
