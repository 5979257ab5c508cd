// patch_fetch.glsl: GPU-only part of the patch vertex shaders (matrix_patch.vs,
// motor_patch.vs): the refinement-pattern vertex (its uv on the patch, attribute 0) and the
// instance's 16 control points from a buffer texture (GL_RGB32F, 16 texels per patch,
// gl_InstanceID = patch), evaluated by bezier_patch.glsl. Not part of the C++ shim.
#include "bezier_patch.glsl"

layout(location = 0) in vec2 a_patchUv;
layout(binding = 5) uniform samplerBuffer u_ControlPoints;

mat4x3 patchRow(int row) {
  int k = 16 * gl_InstanceID + 4 * row;
  return mat4x3(texelFetch(u_ControlPoints, k).xyz, texelFetch(u_ControlPoints, k + 1).xyz,
                texelFetch(u_ControlPoints, k + 2).xyz, texelFetch(u_ControlPoints, k + 3).xyz);
}

// P, dP/du, dP/dv of this vertex (object space).
mat3 patchSurface() {
  return bezierPatch(patchRow(0), patchRow(1), patchRow(2), patchRow(3), a_patchUv);
}
