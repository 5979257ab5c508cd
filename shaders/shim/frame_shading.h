// shaders/shim/frame_shading.h: shaders/frame_shading.glsl (with the pga.glsl it needs)
// compiled as C++ (see shaders/shim/glsl.h): forward.fs's two ways to the shading normal, for
// tests and `motorbench ops`.
#pragma once
#include "shaders/shim/glsl.h"

namespace mb {

#define MB_GLSL_CLASS FrameShading
#include "shaders/shim/glsl_begin.h"
#include "shaders/pga.glsl"
#include "shaders/frame_shading.glsl"
#include "shaders/shim/glsl_end.h"

}  // namespace mb
