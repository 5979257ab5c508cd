// shaders/shim/pga.h: shaders/pga.glsl compiled as C++ (see shaders/shim/glsl.h).
//   mb::Pga<float>, mb::Pga<double>, mb::Pga<mb::Counted>: the toolbox's functions as members,
//   with the GLSL type names as member aliases (Pga<float>::motor, ::vec3, ...).
//   mb::pga<S> is a ready-made instance:  mb::pga<float>.sw_mp(M, p)
#pragma once
#include "shaders/shim/glsl.h"

namespace mb {

#define MB_GLSL_CLASS Pga
#include "shaders/shim/glsl_begin.h"
#include "shaders/pga.glsl"
#include "shaders/shim/glsl_end.h"

template <class S> inline Pga<S> pga{};

}  // namespace mb
