// motor_c's vertex: 16 bytes, pipelines/compact/compact_encoding.h's layout with
// the frame as the 4-byte tangent rotor (smallest three and an explicit reflection bit).
#pragma once
#include <cstdint>
#include <vector>

#include "pipelines/gl/packed_vertices.h"
#include "pipelines/motor/rotor_signs.h"
#include "pipelines/scene/scene.h"

namespace mb::motor {

// `p`'s vertices in motor_c's layout, quantised in compact::positionCube(p.positions); rotors
// as motor::vertexRotor encodes them, a missing uv0 (0, 0). A rotor scalar of exactly 0
// (zeroScalarFrames) is kept by the reflection bit, not a sign.
gl::PackedStream interleaveCompact(const Primitive& p);

// motor_cf's vertices: motor_c's 16-byte layout with the rotor's sign chosen per
// triangle for interpolation (signRotorsForInterpolation, which may split vertices: the
// primitive to upload comes with its bytes), the frame word's extra bit negating the rotor
// and the handedness in the position's w.
struct SignedCompactStream : SignedRotors {
  std::vector<uint8_t> bytes;  // 16 bytes per vertex of `primitive`
  int zeroScalarFrames = 0;
};
SignedCompactStream interleaveCompactSigned(const Primitive& p);

}  // namespace mb::motor
