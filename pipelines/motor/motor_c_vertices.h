// motor_c's vertex (issue 29): 16 bytes, pipelines/compact/compact_encoding.h's layout with
// the frame as the 4-byte tangent rotor (smallest three and an explicit reflection bit).
#pragma once
#include <cstdint>
#include <vector>

#include "pipelines/scene/scene.h"

namespace mb::motor {

struct CompactStream {
  std::vector<uint8_t> bytes;  // 16 bytes per vertex
  int zeroScalarFrames = 0;    // rotor scalar exactly 0 (kept by the reflection bit, not a sign)
};

// `p`'s vertices in motor_c's layout, quantised in compact::positionCube(p.positions); frames
// and absent streams as motor::interleaveVertices fills them.
CompactStream interleaveCompact(const Primitive& p);

}  // namespace mb::motor
