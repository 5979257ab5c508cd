#version 450 core
// motor_patch.vs: the motor pipeline's vertex stage for Bezier patch primitives. The same
// refinement pattern, control points and evaluation as matrix_patch.vs (patch_fetch.glsl);
// the frame by patch_transform.glsl's motorPatchVertex: both derivatives moved by the world
// motor's direction sandwich and crossed (method (a); method (b), a tangent rotor built per
// vertex and composed with gp_rr, counts more and is reported by the tests, not drawn).
// Same uniforms and varyings as motor.vs; MB_SCALE_FALLBACK and MB_ORTHOGRAPHIC as there.
#include "pga.glsl"
#include "matrix_transform.glsl"
#include "motor_transform.glsl"
#include "patch_fetch.glsl"
#include "patch_transform.glsl"

uniform vec4 u_World[2];
#ifdef MB_SCALE_FALLBACK
uniform vec3 u_Scale;
#else
uniform float u_Scale;
#endif
uniform vec4 u_Camera[2];
uniform vec4 u_ProjectionK;  // motorProjectionConstants(near, far, vertical fov, aspect), per frame

out vec3 v_worldPosition;
out vec3 v_worldNormal;
out vec4 v_worldTangent;
out vec2 v_uv0;
out vec2 v_uv1;
out vec4 v_color;

void main() {
  motor toWorld = motor(u_World[0], u_World[1]);
#ifdef MB_SCALE_FALLBACK
  mat3x4 v = motorScaledPatchVertex(toWorld, u_Scale, patchSurface());
#else
  mat3x4 v = motorPatchVertex(toWorld, u_Scale, patchSurface());
#endif
  v_worldPosition = v[0].xyz;
  v_worldNormal = v[1].xyz;
  v_worldTangent = v[2];
  v_uv0 = a_patchUv;
  v_uv1 = a_patchUv;
  v_color = vec4(1.0);
#ifdef MB_ORTHOGRAPHIC
  gl_Position = motorWorldToClipOrthographic(motor(u_Camera[0], u_Camera[1]), v[0].xyz, u_ProjectionK);
#else
  gl_Position = motorWorldToClipConstants(motor(u_Camera[0], u_Camera[1]), v[0].xyz, u_ProjectionK);
#endif
}
