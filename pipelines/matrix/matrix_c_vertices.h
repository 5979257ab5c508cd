// matrix_c's vertex: 16 bytes, pipelines/compact/compact_encoding.h's layout with
// the frame as an octahedral normal, a diamond-coded tangent and the handedness bit (4 bytes).
#pragma once
#include <cstdint>
#include <vector>

#include "pipelines/scene/scene.h"

namespace mb::affine {

// `p`'s vertices in matrix_c's layout, quantised in compact::positionCube(p.positions);
// frames as gl::vertexFrame fills them (those qtangent packs), a missing uv0 (0, 0).
std::vector<uint8_t> interleaveCompact(const Primitive& p);

}  // namespace mb::affine
