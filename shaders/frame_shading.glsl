// frame_shading.glsl: forward.fs's shading normal from the interpolated tangent frame, in the
// two forms a fragment stage can get it (GLSL shim subset: `motorbench ops` counts both).
//   tbnShadingNormal    every pipeline's default: the vertex stage extracted a world normal
//                       and tangent, interpolated separately; re-orthogonalised here
//                       (Gram-Schmidt) into a TBN matrix, as the glTF-Sample-Viewer does.
//   rotorShadingNormal  motor_cf: the vertex stage passes the world tangent rotor
//                       itself (the paper's "pass the tangentRotor to the fragment shader");
//                       normalised and unpacked here. Its frame is orthonormal by
//                       construction: no Gram-Schmidt, no degenerate-tangent test.
// Both take the normal-map sample `m` (tangent space, x and y already scaled by the material's
// normal scale) and `facing` (+1 front face, -1 back face: the normal and the tangent flip,
// the bitangent stays, as the Sample Viewer does for double-sided materials).

#ifndef MB_FRAME_SHADING_GLSL
#define MB_FRAME_SHADING_GLSL

#include "pga.glsl"

// The interpolated normal alone (no normal map).
// counted: 6 mul, 2 add, 1 inversesqrt
vec3 tbnSurfaceNormal(vec3 normal, float facing) { return normalize(normal) * facing; }

// `tangent`.w < 0: bitangent = -cross(n, t). A tangent that interpolation left parallel to
// the normal (or zero) cannot orient the map: the surface normal is returned.
vec3 tbnShadingNormal(vec3 normal, vec4 tangent, vec3 m, float facing) {
  vec3 n = normalize(normal) * facing;
  vec3 t = vec3(tangent.x, tangent.y, tangent.z) * facing;
  t = t - n * dot(n, t);  // interpolation leaves t slightly off the normal plane
  if (dot(t, t) < 1e-12) return n;
  t = normalize(t);
  vec3 b = (tangent.w < 0.0 ? -1.0 : 1.0) * cross(n, t);
  return normalize(mat3(t, b, n) * m);
}

// The normal of an interpolated (shorter than unit, any sign) tangent rotor: R z ~R of a rotor
// R = (s, e23, e31, e12) is |R|^2 times the unit rotor's (extractNormalTangent's normal with
// its 0.5 written as 0.5 |R|^2), and the normalize() that follows removes the |R|^2.
vec3 rotorSurfaceNormal(vec4 r, float facing) {
  vec3 n = vec3(r.y * r.w - r.x * r.z, r.z * r.w + r.y * r.x,
                0.5 * (r.x * r.x + r.w * r.w - r.y * r.y - r.z * r.z));
  return normalize(n) * facing;
}

// `handedness` +1 / -1: the bitangent's sign (a rotor cannot mirror). extractNormalTangent's
// normal and tangent are half length; the bitangent is scaled to match, so one normalize at
// the end serves all three.
vec3 rotorShadingNormal(vec4 rotor, float handedness, vec3 m, float facing) {
  mat2x3 nt = extractNormalTangent(motor(normalize(rotor), vec4(0.0)));
  vec3 b = cross(nt[0], nt[1]) * (2.0 * handedness);
  return normalize(mat3(nt[1] * facing, b, nt[0] * facing) * m);
}

#endif  // MB_FRAME_SHADING_GLSL
