// curved_transform.glsl: the per-vertex transforms of the curved-space pipelines,
// shared by shaders/curved_matrix.vs, shaders/curved_motor.vs and the CPU op counter
// (shaders/shim/pga_kappa.h). MB_KAPPA = +1 (S3) or -1 (H3). Each side in its cheapest
// arrangement for two vectors (position and normal) per vertex.
#ifndef MB_CURVED_TRANSFORM_GLSL
#define MB_CURVED_TRANSFORM_GLSL

#include "pga_kappa.glsl"

#if MB_KAPPA != 0
// view * (instance * v) for the position and the normal (two mat4 * vec4 each; composing
// view * instance first would cost 64 mul more per vertex).
// measured: 64 mul, 48 add
mat2x4 curvedMatrixVertex(mat4 view, mat4 instance, vec4 pos, vec4 normal) {
  return mat2x4(view * (instance * pos), view * (instance * normal));
}

#if MB_KAPPA > 0
// S3: camera and instance as quaternion pairs: one pair product, two pair sandwiches.
// measured: 96 mul, 72 add
mat2x4 curvedMotorVertex(mat2x4 camera, mat2x4 instance, vec4 pos, vec4 normal) {
  mat2x4 m = gp_pair(camera, instance);
  return mat2x4(sw_pair(m, pos), sw_pair(m, normal));
}
#else
// H3: camera and instance as motors: one motor product, two sandwiches.
// measured: 192 mul, 152 add
mat2x4 curvedMotorVertex(motor camera, motor instance, vec4 pos, vec4 normal) {
  motor m = gp_mm_k(camera, instance);
  return mat2x4(sw_mp_k(m, pos), sw_mp_k(m, normal));
}
#endif
#endif

#endif  // MB_CURVED_TRANSFORM_GLSL
