#version 450 core
// affine.vs: the vertex stage of the production matrix pipelines (pipelines/matrix/:
// `affine`, `qtangent`, `hybrid`). Per draw: the model as mat4x3 (12 floats), the normal matrix
// as mat3 (9 floats) and the mirror factor sign(det(model)); per frame the view-projection
// mat4. The transform itself is affine_transform.glsl's (what `motorbench ops` counts).
//
// Variants (#define):
//   MB_SKINNED   linear blend skinning, 4 joints per vertex, one mat4x3 per joint (12 floats,
//                joint world * inverse bind, stored as three row vec4s), normals through the
//                cofactor of the blended matrix
//   MB_QTANGENT  the vertex frame is one quaternion (int16x4 SNORM, read as a vec4 in
//                -1..1) instead of normal + tangent: 28-byte vertices
//   MB_COMPACT   matrix_c: position int16x4 SNORM, the frame in one 2_10_10_10
//                word read as integers (compactMatrixFrame), uv half2: 16-byte vertices.
//                Rigid draws get the mesh's dequantisation folded into u_ModelMatrix;
//                skinned and instanced draws apply u_Dequant per vertex (compactPosition)
//   MB_NO_TANGENT float frame without tangent (no TANGENT, no normal map), as matrix.vs's:
//                position + normal + uv, 32-byte vertices
//   MB_INSTANCED model, normal matrix and mirror per instance (vertex attributes, divisor 1)
//                instead of per draw: EXT_mesh_gpu_instancing / --instances
//   MB_MORPH     morph targets (morph.glsl): position, normal and tangent deltas added in
//                object space before the skin and the model, as matrix.vs. MB_QTANGENT and
//                MB_COMPACT decode their frame to a normal and a (unit) tangent first and
//                then run the float frame's transform; MB_COMPACT's position is dequantised
//                per vertex (u_Dequant, never folded into the model) before the float deltas
#include "affine_transform.glsl"
#ifdef MB_MORPH
#include "morph.glsl"
#endif

layout(location = 0) in vec3 a_position;
#ifdef MB_QTANGENT
layout(location = 1) in vec4 a_qtangent;
layout(location = 2) in vec2 a_uv0;
#elif defined(MB_COMPACT)
layout(location = 1) in vec4 a_compactFrame;  // integer fields as floats, not normalised
layout(location = 2) in vec2 a_uv0;
#if defined(MB_SKINNED) || defined(MB_INSTANCED) || defined(MB_MORPH)
uniform vec4 u_Dequant;  // the mesh's cube: center xyz, half extent w
#endif
#else
layout(location = 1) in vec3 a_normal;
#ifndef MB_NO_TANGENT
layout(location = 2) in vec4 a_tangent;
#endif
layout(location = 3) in vec2 a_uv0;
#endif
layout(location = 4) in vec2 a_uv1;    // locations 4..7: pipelines/gl/scene_textures.h
layout(location = 5) in vec4 a_color;

uniform mat4 u_ViewProjectionMatrix;
#ifdef MB_INSTANCED
// Per instance (divisor 1, pipelines/gl/instance_stream.h): what a draw's uniforms hold,
// node world * instance TRS composed on the CPU; never with MB_SKINNED.
layout(location = 8) in mat4x3 a_instanceModel;
layout(location = 12) in mat3 a_instanceNormal;
layout(location = 15) in float a_instanceMirror;
#define u_ModelMatrix a_instanceModel
#define u_NormalMatrix a_instanceNormal
#define u_Mirror a_instanceMirror
#else
uniform mat4x3 u_ModelMatrix;
uniform mat3 u_NormalMatrix;
uniform float u_Mirror;
#endif

#ifdef MB_SKINNED
layout(location = 6) in uvec4 a_joints;
layout(location = 7) in vec4 a_weights;
// row_major: a mat4x3 is stored as its three rows (3 x vec4 = 48 bytes, no std430 padding).
layout(std430, row_major, binding = 0) readonly buffer AffineJoints { mat4x3 u_joints[]; };
#endif

out vec3 v_worldPosition;
out vec3 v_worldNormal;
out vec4 v_worldTangent;
out vec2 v_uv0;
out vec2 v_uv1;
out vec4 v_color;

void main() {
#ifdef MB_MORPH  // the float frame's transform below reads the morphed attributes
#ifdef MB_QTANGENT
  mat2x4 f = qtangentFrame(a_qtangent);
  vec3 m_position = morphPosition(a_position);
#elif defined(MB_COMPACT)
  mat2x4 f = compactMatrixFrame(a_compactFrame);
  f[1].xyz = normalize(f[1].xyz);  // a direction of any length: the deltas add to a unit tangent
  vec3 m_position = morphPosition(compactPosition(a_position, u_Dequant));
#elif defined(MB_NO_TANGENT)
  mat2x4 f = mat2x4(vec4(a_normal, 0.0), vec4(0.0, 0.0, 0.0, 1.0));  // the tangent is unread
  vec3 m_position = morphPosition(a_position);
#else
  mat2x4 f = mat2x4(vec4(a_normal, 0.0), a_tangent);
  vec3 m_position = morphPosition(a_position);
#endif
  vec3 m_normal = morphNormal(f[0].xyz);
  vec4 m_tangent = vec4(morphTangent(f[1].xyz), f[1].w);
#ifdef MB_SKINNED
#ifdef MB_NO_TANGENT
  mat3x4 v = affineSkinnedVertexNoTangent(u_joints[a_joints.x], u_joints[a_joints.y],
                                          u_joints[a_joints.z], u_joints[a_joints.w], a_weights,
                                          m_position, m_normal);
#else
  mat3x4 v = affineSkinnedVertex(u_joints[a_joints.x], u_joints[a_joints.y],
                                 u_joints[a_joints.z], u_joints[a_joints.w], a_weights, u_Mirror,
                                 m_position, m_normal, m_tangent);
#endif
#elif defined(MB_NO_TANGENT)
  mat3x4 v = affineVertexNoTangent(u_ModelMatrix, u_NormalMatrix, m_position, m_normal);
#else
  mat3x4 v = matrixAffineVertex(u_ModelMatrix, u_NormalMatrix, u_Mirror, m_position, m_normal, m_tangent);
#endif
#elif defined(MB_SKINNED)
#ifdef MB_COMPACT
  mat3x4 v = compactSkinnedVertex(u_joints[a_joints.x], u_joints[a_joints.y],
                                  u_joints[a_joints.z], u_joints[a_joints.w], a_weights,
                                  u_Mirror, a_position, u_Dequant, a_compactFrame);
#elif defined(MB_QTANGENT)
  mat3x4 v = qtangentSkinnedVertex(u_joints[a_joints.x], u_joints[a_joints.y],
                                   u_joints[a_joints.z], u_joints[a_joints.w], a_weights,
                                   u_Mirror, a_position, a_qtangent);
#elif defined(MB_NO_TANGENT)
  mat3x4 v = affineSkinnedVertexNoTangent(u_joints[a_joints.x], u_joints[a_joints.y],
                                          u_joints[a_joints.z], u_joints[a_joints.w], a_weights,
                                          a_position, a_normal);
#else
  mat3x4 v = affineSkinnedVertex(u_joints[a_joints.x], u_joints[a_joints.y],
                                 u_joints[a_joints.z], u_joints[a_joints.w], a_weights, u_Mirror,
                                 a_position, a_normal, a_tangent);
#endif
#else
#if defined(MB_COMPACT) && defined(MB_INSTANCED)
  mat3x4 v = compactRigidVertex(u_ModelMatrix, u_NormalMatrix, u_Mirror,
                                compactPosition(a_position, u_Dequant), a_compactFrame);
#elif defined(MB_COMPACT)
  mat3x4 v = compactRigidVertex(u_ModelMatrix, u_NormalMatrix, u_Mirror, a_position, a_compactFrame);
#elif defined(MB_QTANGENT)
  mat3x4 v = qtangentRigidVertex(u_ModelMatrix, u_NormalMatrix, u_Mirror, a_position, a_qtangent);
#elif defined(MB_NO_TANGENT)
  mat3x4 v = affineVertexNoTangent(u_ModelMatrix, u_NormalMatrix, a_position, a_normal);
#else
  mat3x4 v = matrixAffineVertex(u_ModelMatrix, u_NormalMatrix, u_Mirror, a_position, a_normal,
                                a_tangent);
#endif
#endif
  // As matrix.vs: unit normal and tangent in the varyings.
  v_worldPosition = v[0].xyz;
  v_worldNormal = normalize(v[1].xyz);
#ifdef MB_NO_TANGENT
  v_worldTangent = v[2];  // (0, 0, 0, 1): unread without a normal map
#else
  v_worldTangent = vec4(normalize(v[2].xyz), v[2].w);
#endif
  v_uv0 = a_uv0;
  v_uv1 = a_uv1;
  v_color = a_color;
  gl_Position = matrixWorldToClip(u_ViewProjectionMatrix, v[0]);
}
