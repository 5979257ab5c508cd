// Whether a loaded scene draws anything: a file whose every primitive was skipped (points,
// lines, no POSITION) or that places no mesh on a node would otherwise render a blank image
// and call it success. render, compare and time refuse it (exit 2); report lists it as not drawn.
#pragma once
#include <string>

#include "pipelines/scene/scene.h"

namespace mb {

// Why `scene` draws nothing ("every primitive is skipped: 2 x mode 1 (lines) not supported"),
// or "" when a node draws a primitive with a triangle or a Bezier patch, or it is a curved scene.
std::string whyNothingDrawn(const Scene& scene);

}  // namespace mb
