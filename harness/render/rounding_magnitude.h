// How large the coordinates are that a float pipeline rounds while it takes a vertex to the
// screen: the scale of the last bits by which two correct float pipelines (matrix, motor) place
// the same vertex, which decides the pixels they may draw differently (survey's tie probe).
//
// The bound. A vertex p of a draw with world transform M (sigma: the largest singular value of
// its linear part) reaches clip space through its world position w = M p and its view-space
// position v: matrix by M then the view-projection, motor by the world sandwich then the camera
// sandwich. Every step rounds to float, so each coordinate of v is off by at most c units of
// roundoff u = 2^-24 of m = max(sigma |p|, |w|, |v|) (max norms; a world error passes unchanged
// through the rigid camera), c counting the chained roundings. A view-space error d at depth z
// moves the projection by at most |d| sqrt(1 + tx^2 + ty^2) / z times focal = (H / 2) / tan(yfov
// / 2) pixels (tx, ty: the frustum's half-angle tangents). Two pipelines of c_a and c_b therefore
// place a vertex at most (c_a + c_b) u m sqrt(3) sqrt(1 + tx^2 + ty^2) focal / z pixels apart: the
// scale is m, which for a small mesh far from the origin or the camera (a fractured model's
// cells, a city's props) is many times its own coordinates. Measured, matrix (GLM in float) vs
// motor (the shader source through the shim), the largest over the vertices of |apart| / (u m
// focal / z): hello-fragments.glb 6.4 (cells 0.1 across, 0.3 to 1 from the origin, seen from 2.5
// away: 5.7e-5 px at 128 px), cow.glb 4.8, elephant.glb 2.1.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/scene/animation.h"
#include "pipelines/scene/camera_rule.h"
#include "pipelines/scene/scene.h"

namespace mb {

// survey's float tie probe moves every coordinate by at most this fraction of its primitive's
// rounding magnitude (roundingMagnitudes): 2^-20 = 16 u, 8 to 16 float32 ulps of m, more than the
// c_a + c_b by which matrix and motor differ (6.4 at most above), and at 128 px a move of at most
// 3e-4 pixel where the view coordinates are the largest (m ~ z): far below any transform error the
// rules catch (0.01 px and more).
inline constexpr double kFloatTieJitter = 1.0 / (1 << 20);

// The largest singular value of `a` (the most a linear map stretches a vector; the scale of a
// similarity).
double largestSingularValue(const glm::dmat3& a);

// Per primitive, in the order of the meshes' primitives (mesh 0's, then mesh 1's, ...): the
// largest of |p|, |w| / sigma and |v| / sigma (max norms) over its vertices p, every draw of it
// (each node reachable from the roots that carries its mesh, each instance) and every frame k
// (posed by poses[k], seen from views[k]): m above in the primitive's own units, so that moving
// its positions by up to f of it per axis moves them in the world by up to f times the largest
// world or view coordinate (a similarity's; less along the short axes of a non-uniform scale).
// A primitive no frame draws gets its largest |p|; an empty one 0. Draws whose linear part is
// degenerate (sigma 0 or not finite) are skipped. Skinned and morphed positions are taken as
// their rest positions under the node's transform.
std::vector<double> roundingMagnitudes(const Scene& scene, const std::vector<AnimState>& poses,
                                       const std::vector<View>& views);

}  // namespace mb
