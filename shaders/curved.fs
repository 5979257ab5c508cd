#version 450 core
// curved.fs: the one fragment shader of both curved pipelines of a space (MB_KAPPA = 1: S3,
// -1: H3), the reference's lighting (non-euclidean-rendering.txt) written for either form:
// ambient 0.3 plus three lights (red, green, blue), each diffuse with the angle measured in
// the surface point's tangent space and a falloff 1 / (area of the sphere through the point
// around the light) / 4 pi: 1 / sin^2(d) in S3, 1 / sinh^2(d) in H3.

in vec4 v_position;
in vec4 v_normal;

uniform vec4 u_Lights[3];      // view space
uniform float u_LightStrength;

layout(location = 0) out vec4 o_color;

// The space's bilinear form: dot (S3) or Minkowski + + + - (H3).
float form(vec4 a, vec4 b) { return dot(a.xyz, b.xyz) + float(MB_KAPPA) * a.w * b.w; }

// A tangent vector at v pointing towards u.
vec4 directionTo(vec4 u, vec4 v) { return u - v * (form(u, v) / form(v, v)); }

// 1 / sin^2(d(u, v)) (S3) or 1 / sinh^2(d(u, v)) (H3), from the cosine of the distance.
float falloff(vec4 u, vec4 v) {
  float c = form(u, v);
  float c2 = c * c / (form(u, u) * form(v, v));
  return 1.0 / max(float(MB_KAPPA) * (1.0 - c2), 1e-6);
}

void main() {
  vec3 color = vec3(0.3);
  for (int i = 0; i < 3; ++i) {
    vec4 d = directionTo(u_Lights[i], v_position);
    float cosAngle = form(d, v_normal) * inversesqrt(max(form(d, d) * form(v_normal, v_normal), 1e-30));
    color[i] += u_LightStrength * max(0.0, cosAngle) * falloff(u_Lights[i], v_position);
  }
  o_color = vec4(min(color, vec3(1.0)), 1.0);
}
