#version 450 core
// matrix.vs: the Khronos glTF-Sample-Viewer vertex path, the paper's matrix baseline.
// Per draw: u_ModelMatrix and u_NormalMatrix (= transpose(inverse(model)), both mat4) and per
// frame u_ViewProjectionMatrix. Three full mat4 * vec4 products per vertex (position, normal,
// tangent), as the Sample Viewer does. With SKINNED: linear blend skinning with a joint matrix
// and a joint normal matrix per joint, read from a shader storage buffer (no joint limit
// beyond GL_MAX_SHADER_STORAGE_BLOCK_SIZE).
//
// Handedness: u_NormalMatrix's last column is never used for a direction (w = 0), so its
// [3][3] entry carries sign(det(model)); a mirrored node flips the tangent handedness, which
// keeps bitangent = w * cross(n, t) equal to the transformed bitangent.

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_tangent;
layout(location = 3) in vec2 a_uv0;
layout(location = 4) in vec2 a_uv1;
layout(location = 5) in vec4 a_color;

uniform mat4 u_ViewProjectionMatrix;
uniform mat4 u_ModelMatrix;
uniform mat4 u_NormalMatrix;

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
  vec4 position = vec4(a_position, 1.0);
  vec4 normal = vec4(a_normal, 0.0);
  vec4 tangent = vec4(a_tangent.xyz, 0.0);
#ifdef SKINNED
  mat4 skin = a_weights.x * u_joints[a_joints.x].matrix +
              a_weights.y * u_joints[a_joints.y].matrix +
              a_weights.z * u_joints[a_joints.z].matrix +
              a_weights.w * u_joints[a_joints.w].matrix;
  mat4 skinNormal = a_weights.x * u_joints[a_joints.x].normalMatrix +
                    a_weights.y * u_joints[a_joints.y].normalMatrix +
                    a_weights.z * u_joints[a_joints.z].normalMatrix +
                    a_weights.w * u_joints[a_joints.w].normalMatrix;
  position = skin * position;
  normal = skinNormal * normal;
  tangent = skin * tangent;
#endif
  vec4 world = u_ModelMatrix * position;
  v_worldPosition = world.xyz / world.w;
  v_worldNormal = normalize((u_NormalMatrix * normal).xyz);
  v_worldTangent = vec4(normalize((u_ModelMatrix * tangent).xyz), a_tangent.w * u_NormalMatrix[3][3]);
  v_uv0 = a_uv0;
  v_uv1 = a_uv1;
  v_color = a_color;
  gl_Position = u_ViewProjectionMatrix * world;
}
