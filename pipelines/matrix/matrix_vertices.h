// The matrix pipeline's vertex layout: position, normal, tangent (xyz + handedness w) and
// TEXCOORD_0 interleaved, 12 floats (48 bytes) per vertex, as the glTF-Sample-Viewer feeds
// its matrix shaders.
#pragma once
#include <vector>

#include "pipelines/scene/scene.h"

namespace mb::matrix {

constexpr int kFloatsPerVertex = 12;  // stride; stats are still measured from upload sizes

// Interleaves `p`'s streams. Absent streams are filled so every vertex has the same layout:
// a missing tangent becomes any unit vector perpendicular to the normal (w = +1; no normal
// map samples it), missing uv0 becomes (0, 0), a missing normal (0, 0, 1).
std::vector<float> interleaveVertices(const Primitive& p);

}  // namespace mb::matrix
