// The counted per-vertex kernels of the motor forms: motor.vs (motor + uniform scale, tangent
// rotor, motor skinning, world to clip).
#include "harness/ops/vertex_inputs.h"
#include "harness/ops/vertex_kernels.h"

namespace mb::opsv::detail {

namespace {

// The counting shader every kernel below runs (one instance; static: the kernels' lambdas
// outlive the calls that list them).
PC& motorShader() {
  static PC P;
  return P;
}

// motor.vs: the rigid and skinned vertex (and the paper's reference form), the joint blend,
// world to clip (per vertex and with per-frame constants), the scaled fallback.
std::vector<VertexKernel> motorFormKernels() {
  static const VertexInputs& in = inputs();  // static: the lambdas outlive this call
  static PC& P = motorShader();
  const std::string motorIncl = kMotorIncl, store = kStore3;
  return {
      {"motor", "rigid vertex with frame", "motorRigidVertex",
       [&] { P.motorRigidVertex(in.toWorld, 1.25, in.position, in.rotor); },
       "mat3x4 v = motorRigidVertex(motor(u_world[0], u_world[1]), u_scale, a_position, "
       "a_tangentRotor);" + store,
       motorIncl + kMotorAttribs + "uniform vec4 u_world[2]; uniform float u_scale;\n",
       "paper 47/38 = sw_mp 21/18 + gp_rr 16/12 + extractNormalTangent 9/8 + 1 mul handedness; "
       "here +3 mul: the uniform scale of the position, and the handedness is sign(1/x) "
       "(1 div, 1 other: IEEE signed zero) instead of 1 mul"},
      {"motor", "skinned vertex (4 joints)", "motorSkinnedVertex",
       [&] {
         P.motorSkinnedVertex(in.joints[0], in.joints[1], in.joints[2], in.joints[3],
                              PC::vec4(0.4, 0.3, 0.2, 0.1), 1.25, in.position, in.rotor);
       },
       "mat3x4 v = motorSkinnedVertex(motor(u_j[0], u_j[1]), motor(u_j[2], u_j[3]), "
       "motor(u_j[4], u_j[5]), motor(u_j[6], u_j[7]), a_weights, u_scale, a_position, "
       "a_tangentRotor);" + store,
       motorIncl + kMotorAttribs + "uniform vec4 u_j[8]; uniform float u_scale;\n", ""},
      {"motor", "skinned vertex, reference", "motorSkinnedVertexReference",
       [&] {
         P.motorSkinnedVertexReference(in.toWorld, in.joints[0], in.joints[1], in.joints[2],
                                       in.joints[3], PC::vec4(0.4, 0.3, 0.2, 0.1), 1.25,
                                       in.position, in.rotor);
       },
       "mat3x4 v = motorSkinnedVertexReference(motor(u_world[0], u_world[1]), "
       "motor(u_j[0], u_j[1]), motor(u_j[2], u_j[3]), motor(u_j[4], u_j[5]), "
       "motor(u_j[6], u_j[7]), a_weights, u_scale, a_position, a_tangentRotor);" + store,
       motorIncl + kMotorAttribs + "uniform vec4 u_world[2]; uniform vec4 u_j[8]; uniform float u_scale;\n",
       "the paper's form: palette relative to the mesh node, toWorld = gp(toWorld, blend) per vertex"},
      {"motor", "joint blend (4 joints)", "motorBlendJoints",
       [&] {
         P.motorBlendJoints(in.joints[0], in.joints[1], in.joints[2], in.joints[3],
                            PC::vec4(0.4, 0.3, 0.2, 0.1));
       },
       "motor m = motorBlendJoints(motor(u_j[0], u_j[1]), motor(u_j[2], u_j[3]), "
       "motor(u_j[4], u_j[5]), motor(u_j[6], u_j[7]), a_weights); o_0 = m[0]; o_1 = m[1];",
       motorIncl + kMotorAttribs + "uniform vec4 u_j[8];\n",
       "part of the skinned vertex: shortest-arc blend + normalize_m"},
      {"motor", "world to clip", "motorWorldToClip",
       [&] {
         P.motorWorldToClip(in.camera, PC::vec3(1.5, 0.25, -3.0), 0.05, 100.0, 0.8, 1.5);
       },
       "gl_Position = motorWorldToClip(motor(u_camera[0], u_camera[1]), a_world, "
       "u_projection.x, u_projection.y, u_projection.z, u_projection.w);",
       motorIncl + "uniform vec4 u_camera[2]; uniform vec4 u_projection;\n"
                   "layout(location = 0) in vec3 a_world;\n",
       "the paper listing's form, counted, not drawn (the pipelines take the constants once per frame): project() recomputes its per-draw "
       "constants (cot of half the fov, depth terms: 6 mul, 3 add, 4 div, 1 sin, 1 cos) per vertex; "
       "per vertex proper: sw_mp + 3 mul, 1 add"},
      {"motor, motor_q", "world to clip (per-frame constants)", "motorWorldToClipConstants",
       [&] {
         P.motorWorldToClipConstants(in.camera, PC::vec3(1.5, 0.25, -3.0),
                                     PC::vec4(-1.2, 1.8, -0.1, -1.001));
       },
       "gl_Position = motorWorldToClipConstants(motor(u_camera[0], u_camera[1]), a_world, u_k);",
       motorIncl + "uniform vec4 u_camera[2]; uniform vec4 u_k;\n"
                   "layout(location = 0) in vec3 a_world;\n",
       "drawn by motor.vs and motor_patch.vs: project() with its constants computed once per frame "
       "(motorProjectionConstants), as the matrix side builds its projection matrix once per frame"},
      {"motor", "scaled vertex (fallback)", "motorScaledVertex",
       [&] { P.motorScaledVertex(in.toWorld, PC::vec3(1.0, -2.0, 0.5), in.position, in.rotor); },
       "mat3x4 v = motorScaledVertex(motor(u_world[0], u_world[1]), u_scale3, a_position, "
       "a_tangentRotor);" + store,
       motorIncl + kMotorAttribs + "uniform vec4 u_world[2]; uniform vec3 u_scale3;\n", ""},
  };
}

// motor_c: the 4-byte rotor decode and the vertices that read it.
std::vector<VertexKernel> compactMotorKernels() {
  static const VertexInputs& in = inputs();  // static: the lambdas outlive this call
  static PC& P = motorShader();
  const std::string motorIncl = kMotorIncl, store = kStore3;
  return {
      {"motor_c", "rotor decode (4 bytes)", "compactRotor", [&] { P.compactRotor(in.compactRotor); },
       "mat2x4 r = compactRotor(a_compactFrame); o_0 = r[0]; o_1 = r[1];", motorIncl + kCompactAttribs,
       "smallest three (10, 10, 9 bits) and the reflection bit: no sign of a zero"},
      {"motor_c", "rigid vertex with frame", "motorCompactVertex",
       [&] { P.motorCompactVertex(in.toWorld, 1.25, in.position, in.compactRotor); },
       "mat3x4 v = motorCompactVertex(motor(u_world[0], u_world[1]), u_scale, a_position, "
       "a_compactFrame);" + store,
       motorIncl + kCompactAttribs + "uniform vec4 u_world[2]; uniform float u_scale;\n",
       "compactRotor + motorRigidVertex's sandwich, gp_rr and extraction; the handedness is the bit"},
      {"motor_c", "skinned vertex (4 joints)", "motorCompactSkinnedVertex",
       [&] {
         P.motorCompactSkinnedVertex(in.joints[0], in.joints[1], in.joints[2], in.joints[3],
                                     PC::vec4(0.4, 0.3, 0.2, 0.1), 1.25, in.position, in.dequant,
                                     in.compactRotor);
       },
       "mat3x4 v = motorCompactSkinnedVertex(motor(u_j[0], u_j[1]), motor(u_j[2], u_j[3]), "
       "motor(u_j[4], u_j[5]), motor(u_j[6], u_j[7]), a_weights, u_scale, a_position, u_dequant, "
       "a_compactFrame);" + store,
       motorIncl + kCompactAttribs + "uniform vec4 u_j[8]; uniform float u_scale;\n",
       "motorBlendJoints + compactPosition + motorCompactVertex"},
      {"motor_c", "skinned vertex, reference", "motorCompactSkinnedVertexReference",
       [&] {
         P.motorCompactSkinnedVertexReference(in.toWorld, in.joints[0], in.joints[1], in.joints[2],
                                              in.joints[3], PC::vec4(0.4, 0.3, 0.2, 0.1), 1.25,
                                              in.position, in.dequant, in.compactRotor);
       },
       "mat3x4 v = motorCompactSkinnedVertexReference(motor(u_world[0], u_world[1]), "
       "motor(u_j[0], u_j[1]), motor(u_j[2], u_j[3]), motor(u_j[4], u_j[5]), "
       "motor(u_j[6], u_j[7]), a_weights, u_scale, a_position, u_dequant, a_compactFrame);" + store,
       motorIncl + kCompactAttribs + "uniform vec4 u_world[2]; uniform vec4 u_j[8]; uniform float u_scale;\n",
       "the paper's form with the compact vertex"},
      {"motor_c", "scaled vertex (fallback)", "motorCompactScaledVertex",
       [&] { P.motorCompactScaledVertex(in.toWorld, PC::vec3(1.0, -2.0, 0.5), in.position, in.compactRotor); },
       "mat3x4 v = motorCompactScaledVertex(motor(u_world[0], u_world[1]), u_scale3, a_position, "
       "a_compactFrame);" + store,
       motorIncl + kCompactAttribs + "uniform vec4 u_world[2]; uniform vec3 u_scale3;\n", ""},
  };
}

// motor_cf: the signed rotor decode and the vertices that hand the rotor to the fragment.
std::vector<VertexKernel> compactRotorKernels() {
  static const VertexInputs& in = inputs();  // static: the lambdas outlive this call
  static PC& P = motorShader();
  const std::string motorIncl = kMotorIncl, store = kStore3;
  return {
      {"motor_cf", "signed rotor decode (4 bytes)", "compactSignedRotor",
       [&] { P.compactSignedRotor(in.compactRotor); }, "o_0 = compactSignedRotor(a_compactFrame);",
       motorIncl + kCompactAttribs, "compactRotor, then its bit negates the rotor (the sign chosen for interpolation)"},
      {"motor_cf", "rigid vertex, rotor out", "motorCompactRotorVertex",
       [&] { P.motorCompactRotorVertex(in.toWorld, 1.25, in.position, in.compactRotor); },
       "mat2x4 v = motorCompactRotorVertex(motor(u_world[0], u_world[1]), u_scale, a_position, "
       "a_compactFrame); o_0 = v[0]; o_1 = v[1];",
       motorIncl + kCompactAttribs + "uniform vec4 u_world[2]; uniform float u_scale;\n",
       "compactSignedRotor + sw_mp + gp_rr; the frame is unpacked per fragment (rotorShadingNormal)"},
      {"motor_cf", "skinned vertex, rotor out", "motorCompactRotorSkinnedVertex",
       [&] {
         P.motorCompactRotorSkinnedVertex(in.joints[0], in.joints[1], in.joints[2], in.joints[3],
                                          PC::vec4(0.4, 0.3, 0.2, 0.1), 1.25, in.position, in.dequant,
                                          in.compactRotor);
       },
       "mat2x4 v = motorCompactRotorSkinnedVertex(motor(u_j[0], u_j[1]), motor(u_j[2], u_j[3]), "
       "motor(u_j[4], u_j[5]), motor(u_j[6], u_j[7]), a_weights, u_scale, a_position, u_dequant, "
       "a_compactFrame); o_0 = v[0]; o_1 = v[1];",
       motorIncl + kCompactAttribs + "uniform vec4 u_j[8]; uniform float u_scale;\n",
       "motorBlendJoints + compactPosition + motorCompactRotorVertex"},
      {"motor_cf", "skinned vertex, reference, rotor out", "motorCompactRotorSkinnedVertexReference",
       [&] {
         P.motorCompactRotorSkinnedVertexReference(in.toWorld, in.joints[0], in.joints[1], in.joints[2],
                                                   in.joints[3], PC::vec4(0.4, 0.3, 0.2, 0.1), 1.25,
                                                   in.position, in.dequant, in.compactRotor);
       },
       "mat2x4 v = motorCompactRotorSkinnedVertexReference(motor(u_world[0], u_world[1]), "
       "motor(u_j[0], u_j[1]), motor(u_j[2], u_j[3]), motor(u_j[4], u_j[5]), "
       "motor(u_j[6], u_j[7]), a_weights, u_scale, a_position, u_dequant, a_compactFrame); o_0 = v[0]; o_1 = v[1];",
       motorIncl + kCompactAttribs + "uniform vec4 u_world[2]; uniform vec4 u_j[8]; uniform float u_scale;\n",
       "the paper's form"},
      {"motor_cf", "scaled vertex (fallback)", "motorScaledRotorVertex",
       [&] { P.motorScaledRotorVertex(in.toWorld, PC::vec3(1.0, -2.0, 0.5), in.position, in.rotor, -1.0); },
       "mat3x4 v = motorScaledRotorVertex(motor(u_world[0], u_world[1]), u_scale3, a_position, "
       "a_tangentRotor, a_weights.x);" + store,
       motorIncl + kMotorAttribs + "uniform vec4 u_world[2]; uniform vec3 u_scale3;\n",
       "motorScaledVertex with the handedness given (motor_cf: the position's w)"},
  };
}

// The exact fallback (pipelines/motor/linear_fallback.h): draws and skins whose transforms are
// not similarities; every motor-family pipeline (MB_LINEAR_FALLBACK).
std::vector<VertexKernel> linearFallbackKernels() {
  static const VertexInputs& in = inputs();  // static: the lambdas outlive this call
  static PC& P = motorShader();
  const std::string motorIncl = kMotorIncl, store = kStore3;
  return {
      {"motor, motor_q, motor_c, motor_cf", "linear vertex (exact fallback)", "motorLinearRotorVertex",
       [&] {
         P.motorLinearRotorVertex(in.toWorld, in.affineNormals[0], in.affineNormals[1], in.position, in.rotor, -1.0);
       },
       "mat3x4 v = motorLinearRotorVertex(motor(u_world[0], u_world[1]), u_linear, u_linearNormal, "
       "a_position, a_tangentRotor, a_weights.x);" + store,
       motorIncl + kMotorAttribs + "uniform vec4 u_world[2]; uniform mat3 u_linear; uniform mat3 u_linearNormal;\n",
       "per draw: the polar factors of a world that is not a similarity (motor, linear part and its "
       "inverse-transpose); the frame decode of the pipeline's vertex format comes on top"},
      {"motor, motor_q, motor_c, motor_cf", "linear parts of 4 joints (exact skin fallback)", "motorBlendLinear",
       [&] {
         P.motorBlendLinear(in.affineNormals[0], in.affineNormals[1], in.affineNormals[2], in.affineNormals[3],
                            PC::vec4(0.4, 0.3, 0.2, 0.1));
       },
       "mat3 l = motorBlendLinear(u_l[0], u_l[1], u_l[2], u_l[3], a_weights); "
       "o_0 = vec4(l[0], l[1].x); o_1 = vec4(l[1].yz, l[2].xy); o_2 = vec4(l[2].z);",
       motorIncl + kMotorAttribs + "uniform mat3 u_l[4];\n",
       "per skinned vertex on the fallback, twice (linear part and normal matrix) beside motorBlendJoints"},
  };
}

// Morph targets: the rotor's own part of each method, per morphing vertex; the delta sums come
// on top (morph.glsl: per target with a non-zero weight, 1 mul + 1 add per float: 9 per target
// for the frame method's position + normal + tangent, 7 for the rotor method's position +
// rotor). shaders/motor_transform.glsl explains both.
std::vector<VertexKernel> morphRotorKernels() {
  static const VertexInputs& in = inputs();  // static: the lambdas outlive this call
  static PC& P = motorShader();
  const std::string motorIncl = kMotorIncl;
  return {
      {"motor, motor_q", "morph rotor, frame method (a)", "morphRotorFrame",
       [&] { P.morphRotorFrame(in.rotor, PC::vec3(0.1, -0.2, 0.05), PC::vec3(0.0, 0.15, -0.1)); },
       "vec4 r = morphRotorFrame(a_tangentRotor, a_weights.xyz, a_position); o_0 = r; o_1 = r; o_2 = r;",
       motorIncl + kMotorAttribs,
       "rotorFrame (extractNormalTangent, doubled) + deltas + rotorFromFrame (Gram-Schmidt, one branch "
       "of the trace/diagonal rule, renormalise with the base rotor's handedness)"},
      {"motor, motor_q", "morph rotor, rotor method (b)", "morphRotorBlend",
       [&] { P.morphRotorBlend(in.rotor, PC::vec4(0.05, -0.1, 0.02, 0.1)); },
       "vec4 r = morphRotorBlend(a_tangentRotor, a_weights); o_0 = r; o_1 = r; o_2 = r;",
       motorIncl + kMotorAttribs,
       "rotor + summed rotor deltas, renormalised with the base rotor's handedness"},
  };
}

}  // namespace

std::vector<VertexKernel> motorKernels() {
  std::vector<VertexKernel> all;
  for (auto group :
       {motorFormKernels, compactMotorKernels, compactRotorKernels, linearFallbackKernels, morphRotorKernels})
    for (VertexKernel& k : group()) all.push_back(std::move(k));
  return all;
}

}  // namespace mb::opsv::detail
