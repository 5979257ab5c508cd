// The motor family's exact fallback for transforms that are not similarities: a
// world transform or joint palette entry A (any affine map, e.g. a non-uniform scale inherited
// from an inner node, a sheared matrix, or joints whose scales differ) is kept as
//
//   x  ->  motor( linear * x ),   normals by normalLinear = inverse-transpose of linear
//
// with the motor the rotation and translation of A's polar decomposition (A = R S, S
// symmetric) and linear = S. It is exact for every A (nothing is approximated), reduces to
// (motor, s I) for a similarity s R, and so to the paper's path when all joints of a skin
// share one scale. Shaders: motorLinearRotorVertex (shaders/motor_transform.glsl), MB_LINEAR_FALLBACK.
#pragma once
#include <glm/glm.hpp>

#include "pipelines/motor/scaled_motor.h"

namespace mb::motor {

struct LinearTransform {
  Motor motor = identityMotor();
  glm::mat3 linear{1.0f};        // applied to positions and tangents before the motor
  glm::mat3 normalLinear{1.0f};  // transpose(inverse(linear)), applied to normals
};

// Any affine matrix (last row 0 0 0 1). A reflection (det < 0) stays in `linear`; a singular
// linear part keeps R = identity and the cofactor matrix as its normal matrix.
LinearTransform linearFromAffine(const glm::mat4& a);

// A ScaledMotor (motor, uniform scale, leaf residual) in the same form.
LinearTransform linearFromScaled(const ScaledMotor& m);

// The 24 floats one joint uploads beside its motor (std430: each mat3 column padded to a
// vec4): linear's three columns, then normalLinear's.
void packLinear(const LinearTransform& t, float* out24);
// The linear part back from those 24 floats (the inverse of packLinear's first half).
glm::mat3 unpackLinear(const float* packed24);

}  // namespace mb::motor
