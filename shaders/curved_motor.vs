#version 450 core
// curved_motor.vs: curved space with motors: 8 floats per instance (S3: the quaternion pair
// [L, R] of pga_kappa.glsl; H3: the motor [s, e23, e31, e12 | e01, e02, e03, e0123]), the
// camera the same, sandwiched per vertex. MB_KAPPA = 1 (S3) or -1 (H3).
#include "curved_transform.glsl"

layout(location = 0) in vec4 a_position;
layout(location = 1) in vec4 a_normal;
layout(location = 2) in vec4 a_instance0;  // divisor 1
layout(location = 3) in vec4 a_instance1;

uniform vec4 u_Camera[2];   // world -> view
uniform mat4 u_Projection;

out vec4 v_position;
out vec4 v_normal;

void main() {
  mat2x4 v = curvedMotorVertex(mat2x4(u_Camera[0], u_Camera[1]), mat2x4(a_instance0, a_instance1),
                               a_position, a_normal);
  v_position = v[0];
  v_normal = v[1];
  gl_Position = u_Projection * v[0];
}
