// paper_listings.glsl: the paper's printed GLSL listings for the kernels whose op-count rows
// differ from its table, transcribed expression for expression (names prefixed paper_) so
// that `motorbench claims` and tests/test_pga_paper_listings.cpp can count what the printed
// code does, beside the table's number and our own implementation. Counting only:
// nothing renders with these, and pga.glsl's own functions are derived from the algebra.
// Needs pga.glsl (motor, line) included before it. The swizzles are as printed (log_m's
// c * M[0].wzy and exp_b's t * B[0].zyx differ from pga.glsl's derivation; the counts do not
// depend on the order of a swizzle).
//
// Counts below are what mb::Counted measures (negation free, subtraction is an addition).

#ifndef MB_PAPER_LISTINGS_GLSL
#define MB_PAPER_LISTINGS_GLSL

// The printed normalize_m (table: 21 mul, 5 add).
// counted: 24 mul, 10 add, 1 div, 1 sqrt (length = dot + sqrt; 1 / length; d: 6 mul 3 add;
// a[0] * s, a[1] * s: 8 mul; a[0].yzw * (s * d): 4 mul; -a[0].x * s * d: 2 mul; vec4 sum: 4 add)
motor paper_normalize_m(motor a) {
  float s = 1. / length(a[0]);
  float d = (a[1].w * a[0].x - dot(a[1].xyz, a[0].yzw)) * s * s;
  return motor(a[0] * s, a[1] * s + vec4(a[0].yzw * (s * d), -a[0].x * s * d));
}

// The printed sqrt_m (table: 21 mul, 6 add): the printed normalize_m plus one addition.
// counted: 24 mul, 11 add, 1 div, 1 sqrt
motor paper_sqrt_m(motor R) {
  return paper_normalize_m(motor(R[0].x + 1., R[0].yzw, R[1]));
}

// The printed log_m (table: 14 mul, 5 add, 1 div, 1 acos, 1 sqrt); 1 - s^2 as printed.
// counted: 14 mul, 5 add, 1 div, 1 sqrt, 1 acos
line paper_log_m(motor M) {
  if (M[0].x == 1.) return line(vec3(0.), vec3(M[1].xyz));
  float a = 1. / (1. - M[0].x * M[0].x), b = acos(M[0].x) * sqrt(a),
        c = a * M[1].w * (1. - M[0].x * b);
  return line(b * M[0].yzw, b * M[1].xyz + c * M[0].wzy);
}

// The printed exp_b (table: 17 mul, 8 add, 2 div, 1 sqrt, 1 cos, 1 sin).
// counted: 17 mul, 8 add, 2 div, 1 sqrt, 1 cos, 1 sin
motor paper_exp_b(line B) {
  float l = dot(B[0], B[0]);
  if (l == 0.) return motor(vec4(1., 0., 0., 0.), vec4(B[1], 0.));
  float a = sqrt(l), m = dot(B[0].xyz, B[1]), c = cos(a), s = sin(a) / a, t = m / l * (c - s);
  return motor(c, s * B[0], s * B[1] + t * B[0].zyx, m * s);
}

// The printed skinning blend (no count in the paper's table): four joint motors, each after
// the first negated when its rotor half's dot with the running sum is <= 0, the printed
// normalize_m, then composed with the object-to-world motor, toWorld = gp(toWorld, blend).
// counted: 124 mul, 83 add, 1 div, 1 sqrt (4 x 8 mul weights, 3 dots 12 mul 9 add, 3 motor
// sums 24 add, paper_normalize_m 24/10, gp_mm 48/40)
motor paper_skin_blend(motor toWorld, motor b1, motor b2, motor b3, motor b4, vec4 weights) {
  motor r = weights.x * b1;
  if (dot(r[0], b2[0]) <= 0.0) b2 = -b2;
  r = r + weights.y * b2;
  if (dot(r[0], b3[0]) <= 0.0) b3 = -b3;
  r = r + weights.z * b3;
  if (dot(r[0], b4[0]) <= 0.0) b4 = -b4;
  r = r + weights.w * b4;
  return gp_mm(toWorld, paper_normalize_m(r));
}

// The printed tangent-frame handedness: sign(1 / x) (the paper's sum counts it as 1 mul).
// counted: 1 div, 1 sign
float paper_handedness(vec4 tangentRotor) { return sign(1.0 / tangentRotor.x); }

#endif  // MB_PAPER_LISTINGS_GLSL
