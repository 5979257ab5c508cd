// The 16-byte vertex of the compact pipelines: position int16x4 SNORM in the mesh's
// cube, the frame in one 2_10_10_10 word, uv0 half2. Pure functions; the decoders are the
// shader's (shaders/compact_frame.glsl through shaders/shim/compact.h).
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/gl/packed_vertices.h"
#include "pipelines/scene/scene.h"

namespace mb::compact {

inline constexpr size_t kVertexBytes = 16;

// The cube positions are quantised in: one half extent for all axes (a motor's scale stays
// uniform). dequant() is what the shader gets: (center, extent).
struct PositionCube {
  glm::vec3 center{0.0f};
  float extent = 1.0f;  // > 0
  glm::vec4 dequant() const { return {center, extent}; }
};
PositionCube positionCube(const std::vector<glm::vec3>& positions);
// Per mesh, per primitive: the cube its positions are quantised in (what its draws fold).
std::vector<std::vector<PositionCube>> primitiveCubes(const Scene& scene);
// SNORM16 of (p - center) / extent; w = SNORM16 of `w` (motor_cf: the handedness, else 0).
void quantizePosition(const glm::vec3& p, const PositionCube& cube, int16_t out[4], float w = 0.0f);
// What the GPU reads back (GL's SNORM rule), dequantised.
glm::vec3 dequantizePosition(const int16_t q[4], const PositionCube& cube);

// GL_UNSIGNED_INT_2_10_10_10_REV: x bits 0-9, y 10-19, z 20-29, w 30-31.
uint32_t packWord(unsigned x, unsigned y, unsigned z, unsigned w);
// The fields as a non-normalised attribute reads them (exact floats).
glm::vec4 wordFields(uint32_t word);

// matrix_c's frame from a normal and a tangent (xyz, handedness w); either may be unnormalised.
uint32_t encodeMatrixFrame(const glm::vec3& normal, const glm::vec4& tangent);
struct MatrixFrame {
  glm::vec3 normal, tangent;  // unit
  float handedness = 1.0f;
};
MatrixFrame decodeMatrixFrame(uint32_t word);

// motor_c's frame from a tangent rotor (s, e23, e31, e12; its sign is irrelevant) and the
// handedness: the reflection bit is explicit, so a scalar part of exactly 0 loses nothing.
uint32_t encodeRotorFrame(const glm::vec4& rotor, bool mirrored);
struct RotorFrame {
  glm::vec4 rotor;  // unit, up to sign
  float handedness = 1.0f;
};
RotorFrame decodeRotorFrame(uint32_t word);
// motor_cf's frame: the rotor WITH its sign (interpolated by the rasteriser); the reflection
// bit of motor_c's word says "negate the decoded rotor" (shaders: compactSignedRotor).
uint32_t encodeSignedRotorFrame(const glm::vec4& rotor);
glm::vec4 decodeSignedRotorFrame(uint32_t word);

// Vertex formats in location order: position, frame, uv0.
std::vector<gl::PackedAttribute> attributes();

// Appends one 16-byte vertex: `position` as quantizePosition(position, cube, _, positionW) writes
// it, `frame`, uv0 as two halves.
void appendVertex(std::vector<uint8_t>& out, const glm::vec3& position, const PositionCube& cube, uint32_t frame,
                  const glm::vec2& uv0, float positionW = 0.0f);

}  // namespace mb::compact
