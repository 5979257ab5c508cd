// Vertex data hygiene applied by the loader: every repair is counted in LoadStats.
// Fallbacks (documented contract):
//  - NaN/Inf position component -> the whole position becomes (0,0,0).
//  - Zero-length or NaN normal -> the normalised sum of the area-weighted face normals of the
//    triangles using that vertex; if that is degenerate too, (0,0,1). Other normals are
//    normalised (counted in normalsRenormalised when |n| differs from 1 by more than 1e-3).
//  - Tangents are Gram-Schmidt-orthogonalised against the normal and normalised so every
//    pipeline starts from the same orthonormal frame. A zero-length, NaN or normal-parallel
//    tangent becomes fallbackTangent(normal); w becomes sign(w), with +1 for 0 or NaN.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/scene/scene.h"

namespace mb {

// Replaces non-finite positions by the origin. Returns how many vertices were changed.
int fixPositions(std::vector<glm::vec3>& positions);

// Repairs p.normals (same size as p.positions) as described above; updates stats.
void fixNormals(Primitive& p, LoadStats& stats);

// Repairs p.tangents (same size as p.positions, normals already fixed); updates stats.
void fixTangents(Primitive& p, LoadStats& stats);

// A unit vector perpendicular to unit `n`, chosen deterministically from the coordinate axis
// least aligned with n (Gram-Schmidt of X, or of Y when |n.x| > 0.9).
glm::vec3 fallbackTangent(const glm::vec3& n);

// True when all components are finite.
bool isFinite(const glm::vec3& v);

}  // namespace mb
