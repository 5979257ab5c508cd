// Whether a loaded scene draws anything: a file whose every primitive was skipped (points,
// lines, no POSITION), whose triangles all have zero area, or that places no mesh on a node the
// scene reaches would otherwise render a blank image and call it success. render, compare and
// time refuse it (exit 2); report lists it as not drawn.
#pragma once
#include <string>

#include "pipelines/scene/scene.h"

namespace mb {

// Why `scene` draws nothing ("every primitive is skipped: 2 x mode 1 (lines) not supported"),
// or "" when a node the scene reaches (nodesInDrawOrder) draws a Bezier patch or a triangle
// that can cover a pixel (hasAreaAtRest, or skinned or morphed: a pose may give it area), or it
// is a curved scene.
std::string whyNothingDrawn(const Scene& scene);

// True when some triangle of `p` has an area above zero at rest: twice its area exceeds 1e-6
// times its longest edge squared (its height is more than a millionth of that edge). Collinear
// or repeated corners give none; the rasteriser draws no pixel of such a primitive.
bool hasAreaAtRest(const Primitive& p);

}  // namespace mb
