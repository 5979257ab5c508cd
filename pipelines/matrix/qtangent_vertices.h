// The QTangent vertex layout (Crytek, Filament): position float3, the tangent frame as one
// unit quaternion in int16x4 SNORM, TEXCOORD_0 float2: 28 bytes per vertex against the matrix
// pipeline's 48. The quaternion is that of the rotation with columns (tangent,
// normal x tangent, normal); the handedness is the sign of w, and |w| is kept >= 1/32767 (the
// bias rule) so that the sign survives integer storage, where -0 does not exist.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/gl/packed_vertices.h"
#include "pipelines/scene/scene.h"

namespace mb::affine {

inline constexpr float kMinQuaternionW = 1.0f / 32767.0f;  // one SNORM16 step

struct QTangent {
  glm::vec4 q{0.0f, 0.0f, 0.0f, 1.0f};  // (x, y, z, w), sign(w) = handedness, |w| >= bias
  bool biased = false;                  // |w| was raised to kMinQuaternionW
};

// (normal, tangent, w) -> QTangent. normal and tangent need not be unit or orthogonal
// (Gram-Schmidt: the normal wins); w < 0 means handedness -1.
QTangent encodeQTangent(const glm::vec3& normal, const glm::vec3& tangent, float w);

// `p`'s vertices in the QTangent layout (gl::snormFrameAttributes, 28 bytes per vertex); frames
// as gl::vertexFrame fills them, a missing uv0 (0, 0).
gl::PackedStream interleaveQTangent(const Primitive& p);

}  // namespace mb::affine
