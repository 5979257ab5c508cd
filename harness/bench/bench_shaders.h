// The two pipelines' per-vertex shader modules compiled as C++ through the GLSL shim
// (shaders/shim/glsl.h), for `motorbench ops` (scalar mb::Counted) and `motorbench bench`
// (scalar float): the measured math is the source the GPU runs (DESIGN.md, core idea 4).
//   MatrixShader<S>: shaders/matrix_transform.glsl
//   AffineShader<S>: shaders/matrix_transform.glsl + shaders/affine_transform.glsl
//   MotorShader<S>:  shaders/pga.glsl + shaders/motor_transform.glsl
#pragma once
#include "shaders/shim/glsl.h"

namespace mb {

#define MB_GLSL_CLASS MatrixShader
#include "shaders/shim/glsl_begin.h"
#include "shaders/matrix_transform.glsl"
#include "shaders/shim/glsl_end.h"

#define MB_GLSL_CLASS AffineShader
#include "shaders/shim/glsl_begin.h"
#include "shaders/affine_transform.glsl"
#include "shaders/shim/glsl_end.h"

#define MB_GLSL_CLASS MotorShader
#include "shaders/shim/glsl_begin.h"
#include "shaders/pga.glsl"
#include "shaders/motor_transform.glsl"
#include "shaders/shim/glsl_end.h"

}  // namespace mb
