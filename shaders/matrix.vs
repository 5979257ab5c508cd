#version 450 core
// matrix.vs: the Khronos glTF-Sample-Viewer vertex path, the paper's matrix baseline.
// Per draw: u_ModelMatrix and u_NormalMatrix (= transpose(inverse(model)), both mat4) and per
// frame u_ViewProjectionMatrix. Three full mat4 * vec4 products per vertex (position, normal,
// tangent), as the Sample Viewer does. With SKINNED: linear blend skinning with a joint matrix
// and a joint normal matrix per joint, read from a shader storage buffer (no joint limit
// beyond GL_MAX_SHADER_STORAGE_BLOCK_SIZE).
//
// Variants (#define), as the Sample Viewer's:
//   MB_NO_TANGENT     no tangent attribute (the primitive has no TANGENT and no normal map;
//                     the Sample Viewer's HAS_TANGENT_VEC4 unset): position + normal + uv
//   MB_WORLD_PALETTE  with SKINNED: the joint matrices are in world space (joint world *
//                     inverse bind) and no model matrix is applied per vertex (the motor
//                     default, so both time alike; the Sample Viewer applies it)
//   MB_INSTANCED      model and normal matrix per instance (vertex attributes, divisor 1)
//                     instead of per draw: EXT_mesh_gpu_instancing / --instances
//   MB_MORPH          morph targets (morph.glsl): position, normal and tangent deltas added in
//                     object space before the skin and the model matrix, as the Sample Viewer
//
// Handedness: u_NormalMatrix's last column is never used for a direction (w = 0), so its
// [3][3] entry carries sign(det(model)); a mirrored node flips the tangent handedness, which
// keeps bitangent = w * cross(n, t) equal to the transformed bitangent.

#include "matrix_transform.glsl"
#ifdef MB_MORPH
#include "morph.glsl"
#endif

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
#ifndef MB_NO_TANGENT
layout(location = 2) in vec4 a_tangent;
#endif

layout(location = 3) in vec2 a_uv0;
layout(location = 4) in vec2 a_uv1;
layout(location = 5) in vec4 a_color;

uniform mat4 u_ViewProjectionMatrix;
#ifdef MB_INSTANCED
// Per instance (divisor 1, pipelines/gl/instance_stream.h): the same two matrices a draw's
// uniforms hold, node world * instance TRS composed on the CPU; never with SKINNED.
layout(location = 8) in mat4 a_instanceModel;
layout(location = 12) in mat4 a_instanceNormal;
#define u_ModelMatrix a_instanceModel
#define u_NormalMatrix a_instanceNormal
#else
uniform mat4 u_ModelMatrix;
uniform mat4 u_NormalMatrix;
#endif

#ifdef SKINNED
layout(location = 6) in uvec4 a_joints;
layout(location = 7) in vec4 a_weights;

struct Joint {
  mat4 matrix;        // inverse(mesh node world) * joint world * inverse bind
  mat4 normalMatrix;  // transpose(inverse(matrix))
};
layout(std430, binding = 0) readonly buffer JointPalette {
  Joint u_joints[];
};
#endif

out vec3 v_worldPosition;
out vec3 v_worldNormal;
out vec4 v_worldTangent;
out vec2 v_uv0;
out vec2 v_uv1;
out vec4 v_color;

void main() {
#ifdef MB_MORPH  // the transform below reads the morphed attributes under the inputs' names
  vec3 m_position = morphPosition(a_position);
  vec3 m_normal = morphNormal(a_normal);
#ifndef MB_NO_TANGENT
  vec4 m_tangent = vec4(morphTangent(a_tangent.xyz), a_tangent.w);
#endif
#define a_position m_position
#define a_normal m_normal
#define a_tangent m_tangent
#endif
  // The transform itself is matrix_transform.glsl's (the source `motorbench ops` counts and
  // `motorbench bench` times); main() adds the varyings' perspective divide and normalisation.
#ifdef SKINNED
#if defined(MB_WORLD_PALETTE) && defined(MB_NO_TANGENT)
  mat3x4 v = matrixSkinnedVertexWorldNoTangent(
      u_joints[a_joints.x].matrix, u_joints[a_joints.y].matrix, u_joints[a_joints.z].matrix,
      u_joints[a_joints.w].matrix, u_joints[a_joints.x].normalMatrix,
      u_joints[a_joints.y].normalMatrix, u_joints[a_joints.z].normalMatrix,
      u_joints[a_joints.w].normalMatrix, a_weights, a_position, a_normal);
#elif defined(MB_WORLD_PALETTE)
  mat3x4 v = matrixSkinnedVertexWorld(
      u_joints[a_joints.x].matrix, u_joints[a_joints.y].matrix, u_joints[a_joints.z].matrix,
      u_joints[a_joints.w].matrix, u_joints[a_joints.x].normalMatrix,
      u_joints[a_joints.y].normalMatrix, u_joints[a_joints.z].normalMatrix,
      u_joints[a_joints.w].normalMatrix, a_weights, u_NormalMatrix, a_position, a_normal, a_tangent);
#elif defined(MB_NO_TANGENT)
  mat3x4 v = matrixSkinnedVertexNoTangent(
      u_joints[a_joints.x].matrix, u_joints[a_joints.y].matrix, u_joints[a_joints.z].matrix,
      u_joints[a_joints.w].matrix, u_joints[a_joints.x].normalMatrix,
      u_joints[a_joints.y].normalMatrix, u_joints[a_joints.z].normalMatrix,
      u_joints[a_joints.w].normalMatrix, a_weights, u_ModelMatrix, u_NormalMatrix, a_position, a_normal);
#else
  mat3x4 v = matrixSkinnedVertex(
      u_joints[a_joints.x].matrix, u_joints[a_joints.y].matrix, u_joints[a_joints.z].matrix,
      u_joints[a_joints.w].matrix, u_joints[a_joints.x].normalMatrix,
      u_joints[a_joints.y].normalMatrix, u_joints[a_joints.z].normalMatrix,
      u_joints[a_joints.w].normalMatrix, a_weights, u_ModelMatrix, u_NormalMatrix, a_position,
      a_normal, a_tangent);
#endif
#elif defined(MB_NO_TANGENT)
  mat3x4 v = matrixRigidVertexNoTangent(u_ModelMatrix, u_NormalMatrix, a_position, a_normal);
#else
  mat3x4 v = matrixRigidVertex(u_ModelMatrix, u_NormalMatrix, a_position, a_normal, a_tangent);
#endif
  v_worldPosition = v[0].xyz / v[0].w;
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
