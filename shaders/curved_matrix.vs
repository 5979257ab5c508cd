#version 450 core
// curved_matrix.vs: curved space with 4x4 matrices (non-euclidean-rendering.txt): one O(4) /
// O(3,1) matrix per instance (16 floats), the camera a matrix. MB_KAPPA = 1 (S3) or -1 (H3).
#include "curved_transform.glsl"

layout(location = 0) in vec4 a_position;  // on the quadric
layout(location = 1) in vec4 a_normal;    // tangent at a_position
layout(location = 2) in mat4 a_instance;  // locations 2..5, divisor 1

uniform mat4 u_View;        // world -> view
uniform mat4 u_Projection;  // the space's perspective (pipelines/curved/curved_pipeline.cpp)

out vec4 v_position;  // view space
out vec4 v_normal;

void main() {
  mat2x4 v = curvedMatrixVertex(u_View, a_instance, a_position, a_normal);
  v_position = v[0];
  v_normal = v[1];
  gl_Position = u_Projection * v[0];
}
