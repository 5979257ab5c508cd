#version 450 core
// forward.fs: the ONE fragment shader of every pipeline (glTF metallic-roughness shading).
// Image differences between pipelines therefore come only from their vertex stages.
//
// Inputs every vertex shader must write (world space; the contract between pipelines):
//   v_worldPosition  vec3   surface position
//   v_worldNormal    vec3   vertex normal (need not be unit length)
//   v_worldTangent   vec4   xyz tangent, w = handedness (+1/-1): bitangent = w * cross(n, t)
//   v_uv0, v_uv1     vec2   TEXCOORD_0/1 (uv1 = uv0 or zero when absent)
//   v_color          vec4   COLOR_0 (1,1,1,1 when absent)
// With MB_FRAGMENT_ROTOR (motor_cf) v_worldNormal and v_worldTangent are replaced by
//   v_worldRotor     vec4   the world tangent rotor (s, e23, e31, e12), signed so that a
//                           triangle's three rotors lie in one hemisphere (rotor_signs.h)
//   v_handedness     float  +1 / -1 (the bitangent's sign), sent as v_worldPositionHandedness.w
//                           (one vec4 with the position: 5 vec4 slots instead of 6)
// and the frame is unpacked here (frame_shading.glsl) instead of in the vertex stage.
//
// Uniforms (bound by pipelines/gl/scene_textures.h: setFrameUniforms + bindMaterial):
//   per frame    u_CameraPosition vec3; u_KeyLightDirection, u_FillLightDirection vec3 (unit,
//                world space, pointing towards the light; fixed relative to the camera)
//   per material u_BaseColorFactor vec4; u_MetallicFactor, u_RoughnessFactor float;
//                u_EmissiveFactor vec3; u_NormalScale, u_OcclusionStrength float;
//                u_AlphaMode int (0 OPAQUE, 1 MASK, 2 BLEND); u_AlphaCutoff float;
//                u_BaseColorUV, u_MetallicRoughnessUV, u_NormalUV, u_OcclusionUV,
//                u_EmissiveUV int (texture coordinate set 0/1, or -1 = no texture; 2/3: set
//                0/1 through the slot's KHR_texture_transform matrix below)
//                u_BaseColorUVTransform, ... u_EmissiveUVTransform mat3: uv' = M * (uv, 1)
//                (set only for slots with a transform; the others never read theirs)
//   samplers     u_BaseColorTexture (unit 0), u_MetallicRoughnessTexture (1),
//                u_NormalTexture (2), u_OcclusionTexture (3), u_EmissiveTexture (4).
//                Base colour and emissive textures are sRGB textures (decoded by GL).
#include "ggx.glsl"
#include "frame_shading.glsl"

#ifdef MB_FRAGMENT_ROTOR
in vec4 v_worldPositionHandedness;
#define v_worldPosition v_worldPositionHandedness.xyz
#define v_handedness v_worldPositionHandedness.w
in vec4 v_worldRotor;
#else
in vec3 v_worldPosition;
in vec3 v_worldNormal;
in vec4 v_worldTangent;
#endif
in vec2 v_uv0;
in vec2 v_uv1;
in vec4 v_color;

uniform vec3 u_CameraPosition;
uniform vec3 u_KeyLightDirection;
uniform vec3 u_FillLightDirection;

uniform vec4 u_BaseColorFactor;
uniform float u_MetallicFactor;
uniform float u_RoughnessFactor;
uniform vec3 u_EmissiveFactor;
uniform float u_NormalScale;
uniform float u_OcclusionStrength;
uniform int u_AlphaMode;
uniform float u_AlphaCutoff;
uniform int u_BaseColorUV;
uniform int u_MetallicRoughnessUV;
uniform int u_NormalUV;
uniform int u_OcclusionUV;
uniform int u_EmissiveUV;
uniform mat3 u_BaseColorUVTransform;
uniform mat3 u_MetallicRoughnessUVTransform;
uniform mat3 u_NormalUVTransform;
uniform mat3 u_OcclusionUVTransform;
uniform mat3 u_EmissiveUVTransform;

layout(binding = 0) uniform sampler2D u_BaseColorTexture;
layout(binding = 1) uniform sampler2D u_MetallicRoughnessTexture;
layout(binding = 2) uniform sampler2D u_NormalTexture;
layout(binding = 3) uniform sampler2D u_OcclusionTexture;
layout(binding = 4) uniform sampler2D u_EmissiveTexture;

layout(location = 0) out vec4 o_color;

// The fixed light rig: a key and a fill light (radiance at normal incidence), and a
// hemispherical ambient term (sky above, ground below) standing in for image-based light.
const vec3 KEY_RADIANCE = vec3(2.6, 2.5, 2.35);
const vec3 FILL_RADIANCE = vec3(0.55, 0.6, 0.7);
const vec3 AMBIENT_SKY = vec3(0.30, 0.32, 0.36);
const vec3 AMBIENT_GROUND = vec3(0.16, 0.15, 0.14);

// The uvs a texture slot samples: set 0/1 as interpolated, or (set 2/3) through the slot's
// KHR_texture_transform. Without a transform the uvs are untouched, so files without the
// extension draw exactly as before it was supported.
vec2 uvSet(int set, mat3 transform) {
  vec2 uv = (set & 1) == 1 ? v_uv1 : v_uv0;
  return set >= 2 ? (transform * vec3(uv, 1.0)).xy : uv;
}

// IEC 61966-2-1 sRGB encoding of a linear value in [0, 1].
vec3 linearToSrgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  vec3 lo = c * 12.92;
  vec3 hi = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
  return mix(hi, lo, lessThanEqual(c, vec3(0.0031308)));
}

// The shading normal: interpolated frame, flipped for back faces (double-sided materials;
// single-sided back faces are culled), perturbed by the normal map (frame_shading.glsl).
vec3 shadingNormal() {
  float facing = gl_FrontFacing ? 1.0 : -1.0;
#ifdef MB_FRAGMENT_ROTOR
  if (u_NormalUV < 0) return rotorSurfaceNormal(v_worldRotor, facing);
#else
  if (u_NormalUV < 0) return tbnSurfaceNormal(v_worldNormal, facing);
#endif
  vec3 m = texture(u_NormalTexture, uvSet(u_NormalUV, u_NormalUVTransform)).rgb * 2.0 - 1.0;
  m.xy *= u_NormalScale;
#ifdef MB_FRAGMENT_ROTOR
  return rotorShadingNormal(v_worldRotor, v_handedness, m, facing);
#else
  return tbnShadingNormal(v_worldNormal, v_worldTangent, m, facing);
#endif
}

void main() {
  vec4 base = u_BaseColorFactor * v_color;
#ifdef MB_GEOMETRY_VIEW
  // The geometry view (survey, corpus-check's 16-byte rule): the material's base colour factor and
  // the vertex colour alone, no texture, no frame, no light, so that positions decide the pixels
  // (the 16-byte vertex's half-float uv moves sharp texel edges by a texel or two, which is not a
  // position error).
  o_color = vec4(linearToSrgb(base.rgb), u_AlphaMode == 2 ? base.a : 1.0);
  return;
#endif
  if (u_BaseColorUV >= 0) base *= texture(u_BaseColorTexture, uvSet(u_BaseColorUV, u_BaseColorUVTransform));
  if (u_AlphaMode == 1 && base.a < u_AlphaCutoff) discard;

  float metallic = u_MetallicFactor, roughness = u_RoughnessFactor;
  if (u_MetallicRoughnessUV >= 0) {
    vec4 mr = texture(u_MetallicRoughnessTexture, uvSet(u_MetallicRoughnessUV, u_MetallicRoughnessUVTransform));
    roughness *= mr.g;  // glTF: roughness in G, metalness in B
    metallic *= mr.b;
  }
  metallic = clamp(metallic, 0.0, 1.0);
  roughness = clamp(roughness, 0.0, 1.0);

  vec3 N = shadingNormal();
  vec3 V = normalize(u_CameraPosition - v_worldPosition);
  vec3 color = KEY_RADIANCE * ggxBrdfCosine(N, V, u_KeyLightDirection, base.rgb, metallic, roughness);
  color += FILL_RADIANCE * ggxBrdfCosine(N, V, u_FillLightDirection, base.rgb, metallic, roughness);

  // Ambient: hemisphere irradiance on the diffuse part, and its Fresnel-weighted
  // reflection on the specular part; occlusion darkens only this indirect term (glTF spec).
  float ao = 1.0;
  if (u_OcclusionUV >= 0)
    ao = 1.0 + u_OcclusionStrength * (texture(u_OcclusionTexture, uvSet(u_OcclusionUV, u_OcclusionUVTransform)).r - 1.0);
  vec3 sky = mix(AMBIENT_GROUND, AMBIENT_SKY, 0.5 + 0.5 * N.y);
  vec3 f0 = mix(vec3(0.04), base.rgb, metallic);
  vec3 Fv = ggxFresnelSchlick(f0, vec3(1.0), clamp(dot(N, V), 0.0, 1.0));
  vec3 diffuseColor = mix(base.rgb, vec3(0.0), metallic);
  color += ao * sky * ((1.0 - Fv) * diffuseColor + Fv * (1.0 - 0.5 * roughness));

  vec3 emissive = u_EmissiveFactor;
  if (u_EmissiveUV >= 0) emissive *= texture(u_EmissiveTexture, uvSet(u_EmissiveUV, u_EmissiveUVTransform)).rgb;
  color += emissive;

  o_color = vec4(linearToSrgb(color), u_AlphaMode == 2 ? base.a : 1.0);
}
