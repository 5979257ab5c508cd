// The motor pipeline's shader math compiled as C++ (shaders/shim/glsl.h): the PGA toolbox
// (shaders/pga.glsl) plus the per-vertex transform (shaders/motor_transform.glsl), so the CPU
// side, the tests and the op counter run the very source the GPU runs.
//   mb::MotorKernels<float>, <double>, <mb::Counted>;  mb::motorKernels<S> is an instance.
#pragma once
#include "shaders/shim/glsl.h"

namespace mb {

#define MB_GLSL_CLASS MotorKernels
#include "shaders/shim/glsl_begin.h"
#include "shaders/pga.glsl"
#include "shaders/motor_transform.glsl"
#include "shaders/shim/glsl_end.h"

template <class S> inline MotorKernels<S> motorKernels{};

// The float instance the CPU path uses.
using MK = MotorKernels<float>;
using Motor = MK::motor;  // [[s, e23, e31, e12], [e01, e02, e03, e0123]]
// The shared float instance (its members are non-const, as GLSL functions are).
inline MK& mk() { return motorKernels<float>; }

// The identity motor [1, 0, 0, 0, 0, 0, 0, 0]. Not Motor(1.0f): GLSL's mat2x4(1.0) puts 1 on the
// diagonal, which for a motor also sets e02 (a translation along y).
inline Motor identityMotor() { return Motor(MK::vec4(1.0f, 0.0f, 0.0f, 0.0f), MK::vec4(0.0f)); }

}  // namespace mb
