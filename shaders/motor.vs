#version 450 core
// motor.vs: the vertex stage of the PGA motor pipeline (pipelines/motor/). No matrices: the
// world transform is a motor plus a uniform scale, the tangent frame a rotor, the camera a
// motor followed by pga.glsl's projection with its constants computed once per frame
// (motorProjectionConstants, as the paper's renderer precomputes them and the matrix side
// builds its projection matrix once per frame). The transform itself lives in
// motor_transform.glsl (shared with the CPU tests and the op counter).
//
// Variants (#define):
//   MB_SKINNED        motor skinning: 4 joints per vertex, one motor (8 floats) per joint
//   MB_SCALE_FALLBACK the draw's scale is non-uniform or negative (motorScaledVertex)
//   MB_SKIN_REFERENCE with MB_SKINNED: the paper's form, joint motors relative to the mesh
//                     node and toWorld = gp(u_World, blend) per vertex (the default
//                     palette is in world space and u_World is not used)
//   MB_COMPACT        motor_c: position int16x4 SNORM, the tangent rotor in one
//                     2_10_10_10 word read as integers (compactRotor: smallest three and an
//                     explicit reflection bit), uv half2: 16-byte vertices. Rigid draws get
//                     the mesh's dequantisation folded into u_World and u_Scale; skinned and
//                     instanced draws apply u_Dequant per vertex (compactPosition)
//   MB_SIGNED_ROTOR   with MB_COMPACT, motor_cf's vertex: the frame word's extra bit
//                     negates the rotor (compactSignedRotor: the sign the mesh pass chose,
//                     pipelines/motor/rotor_signs.h) and the handedness is the position's w
//   MB_FRAGMENT_ROTOR with MB_SIGNED_ROTOR: the world tangent rotor is the varying, unpacked
//                     per fragment by forward.fs (frame_shading.glsl) instead of extracted
//                     here; the scale fallback cannot (a non-uniform scale is no rotation)
//                     and is built without it
//   MB_LINEAR_FALLBACK the exact fallback (pipelines/motor/linear_fallback.h) for a world
//                     transform or joint palette that is not a similarity: per draw a motor and
//                     u_Linear / u_LinearNormal (mat3), per joint a motor and 24 floats
//                     (MotorJointLinear, binding 1) blended with the weights; world-space
//                     palette only; compact positions dequantised per vertex (u_Dequant)
//   MB_INSTANCED      motor and scale per instance (vertex attributes, divisor 1) instead of
//                     per draw: EXT_mesh_gpu_instancing / --instances
//   MB_MORPH          morph targets (morph.glsl): the position and the tangent rotor morphed
//                     in object space before the skin and the motor. The frame by method (a) of
//                     motor_transform.glsl (deltas: position, normal, tangent); with
//                     MB_MORPH_ROTOR by method (b) (deltas: position, rotor). With MB_COMPACT
//                     (motor_c, motor_cf) method (a) only: the position dequantised per vertex
//                     (u_Dequant, never folded) before the float deltas are added, the 4-byte
//                     rotor decoded, morphed as a frame and re-formed (morphRotorFrameHanded;
//                     motor_cf: morphSignedRotorFrame keeps the stored sign's hemisphere)
//   MB_ORTHOGRAPHIC   an orthographic View: u_ProjectionK holds motorOrthographicConstants and
//                     clip space is motorWorldToClipOrthographic's (no division by depth)
#include "pga.glsl"
#include "motor_transform.glsl"
#ifdef MB_MORPH
#if defined(MB_COMPACT) && defined(MB_MORPH_ROTOR)
#error "MB_MORPH_ROTOR is not built for the compact vertex (method (a) only)"
#endif
#include "morph.glsl"
#endif

// motor_cf's programs: MB_COMPACT + MB_SIGNED_ROTOR, with MB_FRAGMENT_ROTOR or MB_SCALE_FALLBACK.
#if defined(MB_FRAGMENT_ROTOR) && (!defined(MB_SIGNED_ROTOR) || defined(MB_SCALE_FALLBACK))
#error "MB_FRAGMENT_ROTOR needs MB_SIGNED_ROTOR and no MB_SCALE_FALLBACK"
#endif
#if defined(MB_SIGNED_ROTOR) && !(defined(MB_COMPACT) && (defined(MB_FRAGMENT_ROTOR) || defined(MB_SCALE_FALLBACK) || defined(MB_LINEAR_FALLBACK)))
#error "MB_SIGNED_ROTOR needs MB_COMPACT and MB_FRAGMENT_ROTOR or MB_SCALE_FALLBACK"
#endif
#ifdef MB_SIGNED_ROTOR
layout(location = 0) in vec4 a_position;  // w: handedness (SNORM16 +-1)
#else
layout(location = 0) in vec3 a_position;
#endif
#ifdef MB_COMPACT
layout(location = 1) in vec4 a_compactFrame;  // integer fields as floats, not normalised
#if defined(MB_SKINNED) || defined(MB_INSTANCED) || defined(MB_LINEAR_FALLBACK) || defined(MB_MORPH)
uniform vec4 u_Dequant;  // the mesh's cube: center xyz, half extent w
#endif
#else
layout(location = 1) in vec4 a_tangentRotor;  // handedness in the sign of .x (signed zero)
#endif
layout(location = 2) in vec2 a_uv0;
layout(location = 4) in vec2 a_uv1;    // locations 4..7: pipelines/gl/scene_textures.h
layout(location = 5) in vec4 a_color;

// Per draw: object -> world motor (two vec4: [s,e23,e31,e12], [e01,e02,e03,e0123]) and the
// scale applied to positions before it: one float, or per axis for MB_SCALE_FALLBACK.
#ifdef MB_INSTANCED
// Per instance (divisor 1, pipelines/gl/instance_stream.h): the same motor and scale, node
// world * instance TRS composed on the CPU; never with MB_SKINNED.
layout(location = 8) in vec4 a_instanceWorld0;
layout(location = 9) in vec4 a_instanceWorld1;
#ifdef MB_SCALE_FALLBACK
layout(location = 10) in vec3 a_instanceScale;
#else
layout(location = 10) in float a_instanceScale;
#endif
#define u_Scale a_instanceScale
#else
uniform vec4 u_World[2];
#if defined(MB_LINEAR_FALLBACK) && !defined(MB_SKINNED)
uniform mat3 u_Linear;
uniform mat3 u_LinearNormal;
#endif
#ifdef MB_SCALE_FALLBACK
uniform vec3 u_Scale;
#else
uniform float u_Scale;
#endif
#endif
// Per frame: world -> view motor and the projection constants.
uniform vec4 u_Camera[2];
uniform vec4 u_ProjectionK;  // motorProjectionConstants(near, far, vertical fov, aspect)

#ifdef MB_SKINNED
layout(location = 6) in uvec4 a_joints;
layout(location = 7) in vec4 a_weights;
// The joint palette: one motor per joint (joint world motor * inverse-bind motor).
layout(std430, binding = 0) readonly buffer MotorJoints { vec4 u_Joints[]; };
motor jointMotor(uint j) { return motor(u_Joints[2u * j], u_Joints[2u * j + 1u]); }
#ifdef MB_LINEAR_FALLBACK
// Per joint: its linear part's three columns, then its normal matrix's (vec4-padded).
layout(std430, binding = 1) readonly buffer MotorJointLinear { vec4 u_JointLinear[]; };
mat3 jointLinear(uint j, uint k) {
  return mat3(u_JointLinear[6u * j + k].xyz, u_JointLinear[6u * j + k + 1u].xyz,
              u_JointLinear[6u * j + k + 2u].xyz);
}
#endif
#endif

#ifdef MB_FRAGMENT_ROTOR
out vec4 v_worldPositionHandedness;  // forward.fs's v_worldPosition and v_handedness in one slot
out vec4 v_worldRotor;
#else
out vec3 v_worldPosition;
out vec3 v_worldNormal;
out vec4 v_worldTangent;
#endif
out vec2 v_uv0;
out vec2 v_uv1;
out vec4 v_color;

void main() {
#if defined(MB_MORPH) && defined(MB_COMPACT)
  // The morphed compact vertex as floats: object-space position, rotor, handedness.
  vec3 m_position = morphPosition(compactPosition(a_position.xyz, u_Dequant));
#ifdef MB_SIGNED_ROTOR
  float m_handedness = a_position.w;
  vec4 m_rotor = compactSignedRotor(a_compactFrame);
  if (u_MorphNormal > 0 || u_MorphTangent > 0)
    m_rotor = morphSignedRotorFrame(m_rotor, m_handedness, morphNormal(vec3(0.0)), morphTangent(vec3(0.0)));
#else
  mat2x4 decoded = compactRotor(a_compactFrame);
  float m_handedness = decoded[1].x;
  vec4 m_rotor = decoded[0];
  if (u_MorphNormal > 0 || u_MorphTangent > 0)
    m_rotor = morphRotorFrameHanded(m_rotor, m_handedness, morphNormal(vec3(0.0)), morphTangent(vec3(0.0)));
#endif
#elif defined(MB_MORPH)  // the transform below reads the morphed attributes under the inputs' names
  vec3 m_position = morphPosition(a_position);
  vec4 m_tangentRotor = a_tangentRotor;
#ifdef MB_MORPH_ROTOR
  if (u_MorphNormal > 0) m_tangentRotor = morphRotorBlend(a_tangentRotor, morphVec4(vec4(0.0), u_MorphNormal));
#else
  if (u_MorphNormal > 0 || u_MorphTangent > 0)
    m_tangentRotor = morphRotorFrame(a_tangentRotor, morphNormal(vec3(0.0)), morphTangent(vec3(0.0)));
#endif
#define a_position m_position
#define a_tangentRotor m_tangentRotor
#endif
#ifdef MB_INSTANCED
  motor toWorld = motor(a_instanceWorld0, a_instanceWorld1);
#else
  motor toWorld = motor(u_World[0], u_World[1]);
#endif
#ifdef MB_SKINNED
  // glTF: skinned meshes ignore their node's transform; the skin motors reach world space.
  motor blended = motorBlendJoints(jointMotor(a_joints.x), jointMotor(a_joints.y),
                                   jointMotor(a_joints.z), jointMotor(a_joints.w), a_weights);
#ifdef MB_SKIN_REFERENCE
  toWorld = gp_mm(toWorld, blended);
#else
  toWorld = blended;
#endif
#endif
#ifdef MB_LINEAR_FALLBACK
#ifdef MB_SKINNED
  mat3 linear = motorBlendLinear(jointLinear(a_joints.x, 0u), jointLinear(a_joints.y, 0u),
                                 jointLinear(a_joints.z, 0u), jointLinear(a_joints.w, 0u), a_weights);
  mat3 normalLinear = motorBlendLinear(jointLinear(a_joints.x, 3u), jointLinear(a_joints.y, 3u),
                                       jointLinear(a_joints.z, 3u), jointLinear(a_joints.w, 3u), a_weights);
#else
  mat3 linear = u_Linear;
  mat3 normalLinear = u_LinearNormal;
#endif
#if defined(MB_COMPACT) && defined(MB_MORPH)
  mat3x4 v = motorLinearRotorVertex(toWorld, linear, normalLinear, m_position, m_rotor, m_handedness);
#elif defined(MB_COMPACT)
  vec3 position = compactPosition(a_position.xyz, u_Dequant);
#ifdef MB_SIGNED_ROTOR
  mat3x4 v = motorLinearRotorVertex(toWorld, linear, normalLinear, position,
                                    compactSignedRotor(a_compactFrame), a_position.w);
#else
  mat2x4 r = compactRotor(a_compactFrame);
  mat3x4 v = motorLinearRotorVertex(toWorld, linear, normalLinear, position, r[0], r[1].x);
#endif
#else
  mat3x4 v = motorLinearRotorVertex(toWorld, linear, normalLinear, a_position, a_tangentRotor,
                                    motorHandedness(a_tangentRotor));
#endif
#elif defined(MB_COMPACT) && defined(MB_MORPH)
#ifdef MB_FRAGMENT_ROTOR
  mat2x4 v = motorRotorVertex(toWorld, u_Scale, m_position, m_rotor);
  v_worldPositionHandedness = vec4(v[0].xyz, m_handedness);
  v_worldRotor = v[1];
#elif defined(MB_SCALE_FALLBACK)
  mat3x4 v = motorScaledRotorVertex(toWorld, u_Scale, m_position, m_rotor, m_handedness);
#else
  mat3x4 v = motorRigidRotorVertex(toWorld, u_Scale, m_position, m_rotor, m_handedness);
#endif
#elif defined(MB_COMPACT)
#if defined(MB_SKINNED) || defined(MB_INSTANCED)
  vec3 position = compactPosition(a_position.xyz, u_Dequant);
#else
  vec3 position = a_position.xyz;  // the mesh's cube is folded into u_World and u_Scale
#endif
#ifdef MB_FRAGMENT_ROTOR
  mat2x4 v = motorCompactRotorVertex(toWorld, u_Scale, position, a_compactFrame);
  v_worldPositionHandedness = vec4(v[0].xyz, a_position.w);
  v_worldRotor = v[1];
#elif defined(MB_SIGNED_ROTOR)  // with MB_SCALE_FALLBACK
  mat3x4 v = motorScaledRotorVertex(toWorld, u_Scale, position, compactSignedRotor(a_compactFrame),
                                    a_position.w);
#elif defined(MB_SCALE_FALLBACK)
  mat3x4 v = motorCompactScaledVertex(toWorld, u_Scale, position, a_compactFrame);
#else
  mat3x4 v = motorCompactVertex(toWorld, u_Scale, position, a_compactFrame);
#endif
#elif defined(MB_SCALE_FALLBACK)
  mat3x4 v = motorScaledVertex(toWorld, u_Scale, a_position, a_tangentRotor);
#else
  mat3x4 v = motorRigidVertex(toWorld, u_Scale, a_position, a_tangentRotor);
#endif
#ifndef MB_FRAGMENT_ROTOR
  v_worldPosition = v[0].xyz;
  v_worldNormal = v[1].xyz;
  v_worldTangent = v[2];
#endif
  v_uv0 = a_uv0;
  v_uv1 = a_uv1;
  v_color = a_color;
#ifdef MB_ORTHOGRAPHIC
  gl_Position = motorWorldToClipOrthographic(motor(u_Camera[0], u_Camera[1]), v[0].xyz, u_ProjectionK);
#else
  gl_Position = motorWorldToClipConstants(motor(u_Camera[0], u_Camera[1]), v[0].xyz, u_ProjectionK);
#endif
}
