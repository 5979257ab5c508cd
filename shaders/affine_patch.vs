#version 450 core
// affine_patch.vs: the affine pipelines' (`affine`, `qtangent`, `hybrid`) vertex stage for
// Bezier patch primitives. The same refinement pattern, control points and evaluation as
// matrix_patch.vs (patch_fetch.glsl); the frame is patch_transform.glsl's affinePatchVertex
// (matrixAffineVertex on P, dP/du x dP/dv and dP/du with the draw's mat4x3 model, mat3 normal
// matrix and mirror factor). A patch vertex stores no frame,
// so the qtangent format does not apply: all three pipelines draw patches with this shader.
#include "pga.glsl"
#include "matrix_transform.glsl"
#include "patch_fetch.glsl"
#include "patch_transform.glsl"

uniform mat4 u_ViewProjectionMatrix;
uniform mat4x3 u_ModelMatrix;
uniform mat3 u_NormalMatrix;
uniform float u_Mirror;

out vec3 v_worldPosition;
out vec3 v_worldNormal;
out vec4 v_worldTangent;
out vec2 v_uv0;
out vec2 v_uv1;
out vec4 v_color;

void main() {
  mat3 s = patchSurface();
  mat3x4 v = affinePatchVertex(u_ModelMatrix, u_NormalMatrix, u_Mirror, s);
  v_worldPosition = v[0].xyz;
  v_worldNormal = normalize(v[1].xyz);
  v_worldTangent = vec4(normalize(v[2].xyz), v[2].w);
  v_uv0 = a_patchUv;
  v_uv1 = a_patchUv;
  v_color = vec4(1.0);
  gl_Position = matrixWorldToClip(u_ViewProjectionMatrix, v[0]);
}
