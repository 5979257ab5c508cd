#version 450 core
// matrix_patch.vs: the matrix pipeline's vertex stage for Bezier patch primitives. One
// refinement-pattern mesh drawn instanced once per patch; the surface point and its
// derivatives come from bezier_patch.glsl, the frame from patch_transform.glsl's
// matrixPatchVertex (normal = dP/du x dP/dv through u_NormalMatrix, tangent = dP/du through
// u_ModelMatrix). Same uniforms and varyings as matrix.vs.
// pga.glsl only because patch_transform.glsl also holds the motor frames (unused here).
#include "pga.glsl"
#include "matrix_transform.glsl"
#include "patch_fetch.glsl"
#include "patch_transform.glsl"

uniform mat4 u_ViewProjectionMatrix;
uniform mat4 u_ModelMatrix;
uniform mat4 u_NormalMatrix;

out vec3 v_worldPosition;
out vec3 v_worldNormal;
out vec4 v_worldTangent;
out vec2 v_uv0;
out vec2 v_uv1;
out vec4 v_color;

void main() {
  mat3x4 v = matrixPatchVertex(u_ModelMatrix, u_NormalMatrix, patchSurface());
  v_worldPosition = v[0].xyz / v[0].w;
  v_worldNormal = normalize(v[1].xyz);
  v_worldTangent = vec4(normalize(v[2].xyz), v[2].w);
  v_uv0 = a_patchUv;
  v_uv1 = a_patchUv;
  v_color = vec4(1.0);
  gl_Position = matrixWorldToClip(u_ViewProjectionMatrix, v[0]);
}
