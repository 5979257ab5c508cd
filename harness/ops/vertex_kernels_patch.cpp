// The counted Bezier patch kernels: the evaluation both patch shaders share, then each
// pipeline's frame.
#include "harness/ops/vertex_inputs.h"
#include "harness/ops/vertex_kernels.h"

namespace mb::opsv::detail {

std::vector<VertexKernel> patchKernels() {
  static const VertexInputs& in = inputs();  // static: the lambdas outlive this call
  static TC T;
  const std::string store = kStore3;
  return {
      {"matrix, motor", "patch: bicubic evaluation (P, dP/du, dP/dv)", "bezierPatch",
       [&] { T.bezierPatch(in.rows[0], in.rows[1], in.rows[2], in.rows[3], in.uv); },
       patchEvalProbe(), patchEvalDecls(),
       "shared by matrix_patch.vs and motor_patch.vs (the 16 control points come from texelFetch, "
       "no arithmetic)"},
      {"matrix", "patch frame (normal = dP/du x dP/dv)", "matrixPatchVertex",
       [&] { T.matrixPatchVertex(in.model, in.normal, in.surface); },
       "mat3x4 v = matrixPatchVertex(u_model, u_normal, mat3(a_s0, a_s1, a_s2));" + store,
       patchFrameDecls() + "uniform mat4 u_model; uniform mat4 u_normal;\n",
       "cross 6/3 + the Sample Viewer's three mat4 * vec4 48/36 + handedness 1/0"},
      {"affine, qtangent, hybrid", "patch frame (mat4x3 + mat3)", "affinePatchVertex",
       [&] { T.affinePatchVertex(in.affine, in.affineNormal, 1.0, in.surface); },
       "mat3x4 v = affinePatchVertex(u_model, u_normal, u_mirror, mat3(a_s0, a_s1, a_s2));" + store,
       patchFrameDecls() + "uniform mat4x3 u_model; uniform mat3 u_normal; uniform float u_mirror;\n",
       "cross 6/3 + matrixAffineVertex 28/21 (affine_patch.vs)"},
      {"motor", "patch frame (a): derivatives sandwiched, crossed", "motorPatchVertex",
       [&] { T.motorPatchVertex(in.toWorld, 1.25, in.surface); },
       "mat3x4 v = motorPatchVertex(motor(u_world[0], u_world[1]), u_scale, mat3(a_s0, a_s1, a_s2));" + store,
       patchFrameDecls() + "uniform vec4 u_world[2]; uniform float u_scale;\n",
       "drawn: sw_mp 21/18 + scale 3/0, two sw_md 36/24, cross 6/3"},
      {"motor (b)", "patch frame (b): tangent rotor + gp_rr (not drawn)", "motorPatchVertexRotor",
       [&] { T.motorPatchVertexRotor(in.toWorld, 1.25, in.surface); },
       "mat3x4 v = motorPatchVertexRotor(motor(u_world[0], u_world[1]), u_scale, mat3(a_s0, a_s1, a_s2));" + store,
       patchFrameDecls() + "uniform vec4 u_world[2]; uniform float u_scale;\n",
       "the alternative, counted and not drawn: two normalisations, the rotor of the frame "
       "(branches: Shepperd), gp_rr, extractNormalTangent"},
      {"motor", "patch frame (a), scaled fallback", "motorScaledPatchVertex",
       [&] { T.motorScaledPatchVertex(in.toWorld, TC::vec3(1.0, -2.0, 0.5), in.surface); },
       "mat3x4 v = motorScaledPatchVertex(motor(u_world[0], u_world[1]), u_scale3, mat3(a_s0, a_s1, a_s2));" + store,
       patchFrameDecls() + "uniform vec4 u_world[2]; uniform vec3 u_scale3;\n", ""},
  };
}

}  // namespace mb::opsv::detail
