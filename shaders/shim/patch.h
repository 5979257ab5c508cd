// shaders/shim/patch.h: the Bezier patch modules compiled as C++ (see shaders/shim/glsl.h):
// bezier_patch.glsl (evaluation) and patch_transform.glsl (the matrix and motor frames), with
// the modules they need (pga.glsl, matrix_transform.glsl).
//   mb::PatchShaders<float | double | mb::Counted>; mb::patchShaders<S> is an instance.
#pragma once
#include "shaders/shim/glsl.h"

namespace mb {

#define MB_GLSL_CLASS PatchShaders
#include "shaders/shim/glsl_begin.h"
#include "shaders/pga.glsl"
#include "shaders/matrix_transform.glsl"
#include "shaders/bezier_patch.glsl"
#include "shaders/patch_transform.glsl"
#include "shaders/shim/glsl_end.h"

template <class S> inline PatchShaders<S> patchShaders{};

}  // namespace mb
