// The affine pipelines' float vertex: position, normal, tangent (xyz + handedness w), uv0 on
// every primitive, 12 floats (48 bytes), as the matrix pipeline uploaded before issue 18 made
// its tangent per primitive. A missing tangent becomes any unit vector perpendicular to the
// normal (w = +1; no normal map samples it), missing uv0 (0, 0), a missing normal (0, 0, 1).
// qtangent packs the same frames (interleaveQTangent).
#pragma once
#include <vector>

#include "pipelines/scene/scene.h"

namespace mb::affine {

constexpr int kFloatsPerVertex = 12;

std::vector<float> interleaveFullFrame(const Primitive& p);

}  // namespace mb::affine
