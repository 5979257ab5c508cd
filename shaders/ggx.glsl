// ggx.glsl: the glTF 2.0 metallic-roughness BRDF, shared by every pipeline through forward.fs.
// Terms and sources:
//   F  Schlick's Fresnel approximation          - Schlick 1994; glTF 2.0 spec, Appendix B.3.3
//   V  Smith-GGX height-correlated visibility   - Heitz 2014, "Understanding the Masking-
//      (G / (4 N.L N.V) folded in)                Shadowing Function", eq. 99; glTF App. B.3.2
//   D  GGX / Trowbridge-Reitz distribution      - Walter et al. 2007, "Microfacet Models for
//                                                 Refraction", eq. 33; glTF App. B.3.1
//   alpha = roughness^2 remapping               - Karis 2013, "Real Shading in Unreal Engine 4"
//   Lambert diffuse c_diff / pi                 - glTF 2.0 spec, Appendix B.3.4
// The metal/dielectric mix (f0 = mix(0.04, base, metallic), c_diff = mix(base, 0, metallic))
// follows glTF Appendix B.3.5 as implemented by the Khronos glTF-Sample-Viewer.
#ifndef MB_GGX_GLSL
#define MB_GGX_GLSL

const float MB_PI = 3.14159265358979;

// Schlick 1994 / glTF B.3.3: F = f0 + (f90 - f0) (1 - |V.H|)^5.
vec3 ggxFresnelSchlick(vec3 f0, vec3 f90, float VdotH) {
  float m = clamp(1.0 - VdotH, 0.0, 1.0);
  float m2 = m * m;
  return f0 + (f90 - f0) * (m2 * m2 * m);
}

// Heitz 2014 eq. 99 / glTF B.3.2: height-correlated Smith G2 divided by 4 N.L N.V,
// V = 0.5 / (N.L sqrt(N.V^2 (1 - a^2) + a^2) + N.V sqrt(N.L^2 (1 - a^2) + a^2)).
float ggxVisibility(float NdotL, float NdotV, float alpha) {
  float a2 = alpha * alpha;
  float ggxV = NdotL * sqrt(NdotV * NdotV * (1.0 - a2) + a2);
  float ggxL = NdotV * sqrt(NdotL * NdotL * (1.0 - a2) + a2);
  float sum = ggxV + ggxL;
  return sum > 0.0 ? 0.5 / sum : 0.0;
}

// Walter 2007 eq. 33 / glTF B.3.1: D = a^2 / (pi ((N.H)^2 (a^2 - 1) + 1)^2).
float ggxDistribution(float NdotH, float alpha) {
  float a2 = alpha * alpha;
  float f = NdotH * NdotH * (a2 - 1.0) + 1.0;
  return a2 / (MB_PI * f * f);
}

// glTF B.3.4: Lambertian diffuse, weighted by (1 - F) as in the glTF fresnel_mix.
vec3 ggxLambert(vec3 F, vec3 diffuseColor) {
  return (1.0 - F) * diffuseColor / MB_PI;
}

// Outgoing radiance factor (BRDF * N.L) for one light. N, V, L unit vectors in the same space;
// baseColor linear; roughness perceptual (squared here, Karis 2013), clamped away from 0 so
// a mirror-smooth surface keeps a finite highlight.
vec3 ggxBrdfCosine(vec3 N, vec3 V, vec3 L, vec3 baseColor, float metallic, float roughness) {
  float NdotL = clamp(dot(N, L), 0.0, 1.0);
  if (NdotL <= 0.0) return vec3(0.0);
  vec3 H = normalize(L + V);
  float NdotV = clamp(dot(N, V), 0.0, 1.0);
  float NdotH = clamp(dot(N, H), 0.0, 1.0);
  float VdotH = clamp(dot(V, H), 0.0, 1.0);
  float alpha = max(roughness * roughness, 0.002);
  vec3 f0 = mix(vec3(0.04), baseColor, metallic);
  vec3 diffuseColor = mix(baseColor, vec3(0.0), metallic);
  vec3 F = ggxFresnelSchlick(f0, vec3(1.0), VdotH);
  vec3 specular = F * ggxVisibility(NdotL, NdotV, alpha) * ggxDistribution(NdotH, alpha);
  return NdotL * (ggxLambert(F, diffuseColor) + specular);
}

#endif  // MB_GGX_GLSL
