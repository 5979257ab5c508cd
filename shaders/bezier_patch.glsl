// bezier_patch.glsl: evaluation of a bicubic Bezier patch (position and both first
// derivatives) from its 16 control points, written once in the GLSL subset of
// shaders/shim/glsl.h: the patch vertex shaders (matrix_patch.vs, motor_patch.vs) call it on
// the GPU, shaders/shim/patch.h compiles it as C++ for the CPU reference, tests and the op
// counter. Both pipelines run exactly this code; only the frame transform after it differs.
//
// Control points: four rows (v = 0, 1/3, 2/3, 1), each a mat4x3 whose columns are the row's
// points (u = 0, 1/3, 2/3, 1) -- Primitive::patchPoints' order, point 4 * row + column.
//
// Crack-free edges: along a patch edge every weight of the other rows/columns is exactly 0
// and the edge's own weights are computed symmetrically in t and 1 - t, and sums pair the
// ends and the middles, so two patches sharing an edge (either direction, row or column)
// compute bit-identical positions on the CPU (tests/pipelines/test_patch_eval.cpp checks the teapot).

#ifndef MB_BEZIER_PATCH_GLSL
#define MB_BEZIER_PATCH_GLSL

// GLSL's `precise` forbids the GPU compiler to fuse a * b + c into one rounding (fma) in the
// position sums: fusing one term of the symmetric pair but not its mirror breaks the
// bit-identical edges (measured on llvmpipe: 2.4e-7 gaps without it). C++ evaluates as written.
#ifdef MB_GLSL_CPP
#define precise
#endif

// Cubic Bernstein weights at t, written so that swapping t and 1 - t swaps them exactly.
// counted: 8 mul, 1 add
vec4 bernstein3(float t) {
  float s = 1.0 - t;
  float ss = s * s, tt = t * t;
  return vec4(ss * s, (3.0 * t) * ss, (3.0 * s) * tt, tt * t);
}

// Weights of the control-point differences in a cubic's derivative: 3 x the quadratic basis.
// counted: 6 mul, 1 add
vec3 bernstein2d(float t) {
  float s = 1.0 - t;
  return vec3(3.0 * (s * s), 6.0 * (s * t), 3.0 * (t * t));
}

// A cubic along one row: the point (weights b) and the derivative from the differences of
// consecutive points (weights d). Differences of coincident points are exactly 0, which is
// what makes a collapsed row's derivative exactly 0 (bezierPatch's degenerate test).
// counted: 21 mul, 24 add
mat2x3 bezierRow(mat4x3 row, vec4 b, vec3 d) {
  precise vec3 p = (row[0] * b.x + row[3] * b.w) + (row[1] * b.y + row[2] * b.z);
  vec3 dp = d.x * (row[1] - row[0]) + d.y * (row[2] - row[1]) + d.z * (row[3] - row[2]);
  return mat2x3(p, dp);
}

// Position, dP/du and dP/dv of the patch at uv (columns 0, 1, 2).
//
// Degenerate edges: where a whole row of control points coincides (the teapot's lid apex and
// bottom centre), dP/du is exactly 0 along that edge and the normal dP/du x dP/dv would be
// NaN. There dP/du is replaced by its limiting direction towards the edge, the mixed
// derivative d2P/du dv (dP/du(u, v) ~ v d2P/dudv(u, 0) near v = 0, ~ -(1 - v) d2P/dudv near
// v = 1), and the same for a collapsed column and dP/dv. The test is relative (|dP/du|^2 <=
// 1e-12 |dP/dv|^2) so scale does not matter; interior vertices never take it.
// counted: 153 mul, 137 add at an ordinary vertex; +9 mul, +15 add on a degenerate edge
// (tests/pipelines/test_patch_eval.cpp)
mat3 bezierPatch(mat4x3 r0, mat4x3 r1, mat4x3 r2, mat4x3 r3, vec2 uv) {
  vec4 bu = bernstein3(uv.x), bv = bernstein3(uv.y);
  vec3 du = bernstein2d(uv.x), dv = bernstein2d(uv.y);
  mat2x3 a = bezierRow(r0, bu, du), b = bezierRow(r1, bu, du);
  mat2x3 c = bezierRow(r2, bu, du), d = bezierRow(r3, bu, du);
  precise vec3 p = (a[0] * bv.x + d[0] * bv.w) + (b[0] * bv.y + c[0] * bv.z);
  vec3 pu = (a[1] * bv.x + d[1] * bv.w) + (b[1] * bv.y + c[1] * bv.z);
  vec3 pv = dv.x * (b[0] - a[0]) + dv.y * (c[0] - b[0]) + dv.z * (d[0] - c[0]);
  float uu = dot(pu, pu), vv = dot(pv, pv);
  if (uu <= 1e-12 * vv || vv <= 1e-12 * uu) {
    vec3 twist = dv.x * (b[1] - a[1]) + dv.y * (c[1] - b[1]) + dv.z * (d[1] - c[1]);
    if (uu <= 1e-12 * vv) pu = uv.y < 0.5 ? twist : -twist;
    else pv = uv.x < 0.5 ? twist : -twist;
  }
  return mat3(p, pu, pv);
}

#ifdef MB_GLSL_CPP
#undef precise
#endif

#endif  // MB_BEZIER_PATCH_GLSL
