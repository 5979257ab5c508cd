// The one tolerance that decides whether a transform is treated as a similarity (rotation,
// translation, one uniform scale): the motor pipelines' fast path below it, their exact
// fallback above it; inspect, render, report, the corpus statistics and the claims all use it.
//
// Definition: a scale (s0, s1, s2) is uniform when |s0/s1 - 1| <= tau and |s1/s2 - 1| <= tau
// (magnitudes; the paper's reference loader applies this check with tau = 1e-4 to a matrix's
// column scales); columns of a matrix are orthogonal when every |cos| between two normalised
// columns is <= tau; a skin's joints share one scale when each joint's scale is within tau
// (relative) of the first's.
//
// Why 1e-4 is invisible (the error the fallback prevents). Replacing diag(s) by its mean m (the
// fast path) moves a point x of the node's frame by |(diag(s) - m I) x| <= 2 tau m |x|; a shear
// with |cos| <= tau moves it by <= tau |x| per column pair. Down a chain of d such nodes the
// first-order errors add, so a vertex moves by at most 2 d tau D, D the model's diameter. The
// automatic camera frames the model's bounds into the image, so D spans at most the H pixels of
// the frame's height (the padded sphere: fewer), and the image moves by at most 2 d tau H
// pixels: 0.1 px for a chain of d = 1 at H = 512 with tau = 1e-4; it reaches a pixel only for
// d * H >= 5,000, e.g. ten noisy nodes in series at 512 px, which real exporter noise (errors of
// 1e-5 .. 2e-5, independent per node, not all pointing one way) does not approach. Real scale
// on purpose (a squash, a stretched bone) is 1e-2 and more: far above tau, exact fallback.
// Normals and tangents turn by at most 2 tau radians (0.01 degree) per node.
#pragma once

namespace mb {

inline constexpr double kSimilarityTolerance = 1e-4;

}  // namespace mb
