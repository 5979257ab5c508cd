// The float-frame vertex of the matrix forms (`matrix` and `affine`), per primitive as the
// glTF-Sample-Viewer feeds its matrix shaders: position, normal, [tangent (xyz + handedness w),]
// TEXCOORD_0 interleaved. The Sample Viewer has a tangent attribute only where the file authors
// TANGENT or the material is normal-mapped (then it generates one); elsewhere its shader has no
// tangent input. So: 12 floats (48 bytes) with a tangent, 8 floats (32 bytes) without. The loader
// fills Primitive::tangents exactly when TANGENT was authored or the material has a normal texture
// (generated then), and built-in scenes set tangents where a file would author them, so the rule
// is "tangents present".
#pragma once
#include <vector>

#include "pipelines/gl/gpu_geometry.h"
#include "pipelines/scene/scene.h"

namespace mb::gl {

// The frame of vertex v as the full-frame vertices (qtangent, matrix_c and the motor family)
// fill it: a missing normal (0, 0, 1), a missing tangent any unit vector perpendicular to the
// normal (w = +1; no normal map samples it), so every pipeline shades the same frames.
struct VertexFrame {
  glm::vec3 normal;
  glm::vec4 tangent;  // xyz + handedness w
};
VertexFrame vertexFrame(const Primitive& p, size_t v);

// uv0 of vertex v, (0, 0) where `p` has none.
inline glm::vec2 vertexUv(const Primitive& p, size_t v) { return v < p.uv0.size() ? p.uv0[v] : glm::vec2(0.0f); }

// The loop every vertex format shares: `p`'s vertices, encode(out, v) appending vertex v's
// `perVertex` values to `out`. Each format's encoder holds only its own encoding.
template <class T, class Encode> std::vector<T> interleave(const Primitive& p, size_t perVertex, Encode&& encode) {
  std::vector<T> out;
  out.reserve(p.positions.size() * perVertex);
  for (size_t v = 0; v < p.positions.size(); ++v) encode(out, v);
  return out;
}

// `p`'s streams interleaved: position, normal, tangent (only when `p` has tangents), uv0, at
// locations 0, 1, 2, 3 (a missing uv0 (0, 0), a missing normal (0, 0, 1)); variant 1 when it has
// no tangent (the shaders' MB_NO_TANGENT).
VertexFormat floatFrameFormat(const Primitive& p);

}  // namespace mb::gl
