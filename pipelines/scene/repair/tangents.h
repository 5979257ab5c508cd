// Tangent generation for normal-mapped primitives without TANGENT, following the published
// description of MikkTSpace (Mikkelsen 2008, the convention glTF expects):
//  1. vertices are welded by exact equality of position, normal and uv (as MikkTSpace does);
//  2. per triangle, the tangent is dP/du from the uv derivatives, and the orientation is the
//     sign of the signed uv area (positive: w = +1, negative: w = -1);
//  3. at every corner that tangent is projected into the plane of the vertex normal,
//     normalised and accumulated weighted by the corner angle (measured in that plane),
//     separately per welded vertex and orientation, so mirrored-uv faces never mix;
//  4. the sum is Gram-Schmidt-orthogonalised against the normal and normalised.
// Differences from the reference implementation: (a) MikkTSpace further splits a vertex's
// same-orientation faces into groups connected through shared edges; here all faces of one
// orientation at a welded vertex are merged (identical on manifold meshes, which is where
// groups coincide). (b) Triangles with zero uv area or a zero uv-derivative take the
// accumulated tangent of the same welded vertex (either orientation) instead of MikkTSpace's
// neighbour search, and fallbackTangent(normal) with w = +1 when there is none. (c) Only the
// unit tangent and sign are produced (no magnitudes, no bitangent).
#pragma once
#include "pipelines/scene/scene.h"

namespace mb {

// Fills p.tangents (normals must be valid unit vectors) from uv set `uvSet` (0 or 1). A vertex
// whose corners have different orientations is duplicated (all streams), and indices updated.
// Counts degenerate-uv triangles and split vertices in `stats`.
void generateTangents(Primitive& p, int uvSet, LoadStats& stats);

}  // namespace mb
