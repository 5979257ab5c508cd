// motor_q's vertex layout: position float3, the tangent rotor in int16x4 SNORM, TEXCOORD_0
// float2: 28 bytes per vertex against motor's 36.
//
// The handedness is the sign of the rotor's scalar part, and SNORM16 has no -0: companion.h's
// bias rule (|s| >= 1/32767, one SNORM16 step) keeps a zero scalar's sign through quantisation;
// gl::PackedStream counts the frames it changed.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/gl/packed_vertices.h"
#include "pipelines/scene/scene.h"

namespace mb::motor {

// The rotor as int16 SNORM, component order (s, e23, e31, e12).
void quantizeRotor(const glm::vec4& rotor, int16_t out[4]);

// `p`'s vertices in motor_q's layout (gl::snormFrameAttributes, 28 bytes per vertex; rotors as
// motor::vertexRotor encodes them, a missing uv0 (0, 0)).
gl::PackedStream interleaveQuantized(const Primitive& p);

}  // namespace mb::motor
