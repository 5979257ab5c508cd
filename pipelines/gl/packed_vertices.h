// Vertex layouts with mixed component types (float positions and uvs next to int16 SNORM
// frames): the attribute formats (the float layouts' too), the SNORM rule and byte appending.
// Used by the quantized-frame pipelines (qtangent, hybrid, motor_q) through SceneGeometry::uploadPacked.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/gl/gl_api.h"

namespace mb::gl {

// One vertex attribute at shader `location`: `size` components of `type`, normalised to
// -1..1 / 0..1 when `normalized` (GL's SNORM / UNORM), read by the shader as floats.
struct PackedAttribute {
  GLuint location = 0;
  GLint size = 4;
  GLenum type = GL_FLOAT;
  bool normalized = false;
  // Bytes of one attribute value (a packed 2_10_10_10 type is one 4-byte word).
  size_t bytes() const {
    if (type == GL_UNSIGNED_INT_2_10_10_10_REV || type == GL_INT_2_10_10_10_REV) return 4;
    const size_t c = type == GL_SHORT || type == GL_UNSIGNED_SHORT || type == GL_HALF_FLOAT ? 2
                   : type == GL_BYTE || type == GL_UNSIGNED_BYTE   ? 1
                                                                   : 4;
    return c * size_t(size);
  }
};

// The 28-byte vertex of qtangent and motor_q: position float3, the frame (quaternion or rotor)
// int16x4 SNORM, uv0 float2.
inline std::vector<PackedAttribute> snormFrameAttributes() {
  return {{0, 3, GL_FLOAT, false}, {1, 4, GL_SHORT, true}, {2, 2, GL_FLOAT, false}};
}

// A primitive's packed vertices and what their frame encoding counted.
struct PackedStream {
  std::vector<uint8_t> bytes;
  int zeroScalarFrames = 0;  // tangent rotors whose scalar part was exactly 0 (before any bias)
  int biasedFrames = 0;      // frames whose scalar (rotor) or w (quaternion) the bias rule raised
};

// float -> int16 SNORM: round(clamp(v, -1, 1) * 32767). The decoder (GL 4.2+ and
// fromSnorm16) gives max(c / 32767, -1), so +-1/32767 survives exactly and -0 becomes +0.
inline int16_t snorm16(float v) {
  return int16_t(std::lround(std::clamp(v, -1.0f, 1.0f) * 32767.0f));
}
inline float fromSnorm16(int16_t c) { return std::max(float(c) / 32767.0f, -1.0f); }

// Appends the bytes of `n` values.
template <class T> void appendBytes(std::vector<uint8_t>& out, const T* v, size_t n) {
  const size_t at = out.size();
  out.resize(at + n * sizeof(T));
  std::memcpy(out.data() + at, v, n * sizeof(T));
}

// Appends one vertex of snormFrameAttributes' layout, its frame already SNORM16.
inline void appendSnormFrameVertex(std::vector<uint8_t>& out, const glm::vec3& position, const int16_t frame[4],
                                   const glm::vec2& uv) {
  appendBytes(out, &position.x, 3);
  appendBytes(out, frame, 4);
  appendBytes(out, &uv.x, 2);
}

}  // namespace mb::gl
