// morph.glsl: glTF morph targets in the vertex shader, included by every glTF
// vertex shader built with MB_MORPH. The deltas are a storage buffer read by gl_VertexID
// (pipelines/gl/morph_buffers.h says why not vertex attributes), laid out
// float[targets][vertices][u_MorphStride]; the node's weights are a uniform array of
// MB_MORPH_TARGETS (the scene's largest target count). Morphing happens in object space before
// any skin or transform, as glTF orders it. A zero weight skips its target (exactly what adding
// 0 * delta gives), so a mesh at rest reads nothing.
#ifndef MB_MORPH_GLSL
#define MB_MORPH_GLSL

layout(std430, binding = 2) readonly buffer MorphDeltas { float u_MorphDeltas[]; };
uniform int u_MorphTargetCount;
uniform int u_MorphVertices;
uniform int u_MorphStride;   // floats per vertex per target
uniform int u_MorphNormal;   // first float of the normal (frame) delta; 0: none
uniform int u_MorphTangent;  // first float of the tangent delta; 0: none
uniform float u_MorphWeights[MB_MORPH_TARGETS];

int morphAt(int target, int offset) { return (target * u_MorphVertices + gl_VertexID) * u_MorphStride + offset; }

// base + sum_i w_i delta_i for the 3-float delta at `offset` (the position: 0), in target order
// (the Sample Viewer's sum).
vec3 morphVec3(vec3 base, int offset) {
  for (int i = 0; i < u_MorphTargetCount; ++i) {
    float w = u_MorphWeights[i];
    if (w == 0.0) continue;
    int at = morphAt(i, offset);
    base += w * vec3(u_MorphDeltas[at], u_MorphDeltas[at + 1], u_MorphDeltas[at + 2]);
  }
  return base;
}

// The same for a 4-float delta (a rotor delta, motor method MB_MORPH_ROTOR).
vec4 morphVec4(vec4 base, int offset) {
  for (int i = 0; i < u_MorphTargetCount; ++i) {
    float w = u_MorphWeights[i];
    if (w == 0.0) continue;
    int at = morphAt(i, offset);
    base += w * vec4(u_MorphDeltas[at], u_MorphDeltas[at + 1], u_MorphDeltas[at + 2], u_MorphDeltas[at + 3]);
  }
  return base;
}

vec3 morphPosition(vec3 p) { return morphVec3(p, 0); }
vec3 morphNormal(vec3 n) { return u_MorphNormal > 0 ? morphVec3(n, u_MorphNormal) : n; }
vec3 morphTangent(vec3 t) { return u_MorphTangent > 0 ? morphVec3(t, u_MorphTangent) : t; }

#endif
