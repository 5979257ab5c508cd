// shaders/shim/compact.h: shaders/compact_frame.glsl compiled as C++ (see shaders/shim/glsl.h):
// the compact pipelines' decoders as the GPU runs them, for their encoders (which pick the
// codes whose decoding is closest) and tests.
#pragma once
#include "shaders/shim/glsl.h"

namespace mb {

#define MB_GLSL_CLASS CompactShader
#include "shaders/shim/glsl_begin.h"
#include "shaders/compact_frame.glsl"
#include "shaders/shim/glsl_end.h"

}  // namespace mb
