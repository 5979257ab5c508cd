// Flat normals for primitives without NORMAL (glTF 2.0: "client implementations MUST
// calculate flat normals"). Vertices are unwelded so each triangle owns its three corners.
#pragma once
#include "pipelines/scene/scene.h"

namespace mb {

// Expands every stream of `p` to one vertex per triangle corner (indices become 0..3T-1) and
// sets each corner's normal to its face normal; zero-area faces get (0,0,1).
void generateFlatNormals(Primitive& p);

// Copies vertex `src` of every non-empty stream to the end of that stream (used when a vertex
// must be split). Returns the new vertex index.
uint32_t duplicateVertex(Primitive& p, uint32_t src);

}  // namespace mb
