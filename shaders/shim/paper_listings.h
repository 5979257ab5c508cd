// shaders/shim/paper_listings.h: the paper's printed listings (shaders/paper_listings.glsl)
// compiled as C++ beside the toolbox they need (shaders/pga.glsl), for counting.
//   mb::PaperListings<mb::Counted>{}.paper_normalize_m(M), ... and every pga.glsl function.
#pragma once
#include "shaders/shim/glsl.h"

namespace mb {

#define MB_GLSL_CLASS PaperListings
#include "shaders/shim/glsl_begin.h"
#include "shaders/pga.glsl"
#include "shaders/paper_listings.glsl"
#include "shaders/shim/glsl_end.h"

}  // namespace mb
