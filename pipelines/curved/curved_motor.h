// CPU companion of the curved motor pipelines: motors of curved-space isometries,
// computed in double with shaders/pga_kappa.glsl (through the shim) and rounded once.
#pragma once
#include <array>

#include <glm/glm.hpp>

#include "pipelines/result.h"
#include "pipelines/scene/scene.h"

namespace mb::curved {

using Motor8 = std::array<double, 8>;  // [s, e23, e31, e12, e01, e02, e03, e0123]

// The motor of CurvedMove (i, j) at `angle` (see scene.h): a rotor for j < 3, translator_k
// along e_i for j = 3. kappa = +1 or -1.
Motor8 elementaryMotor(int kappa, int i, int j, double angle);

// a b (b applied first), and the 4x4 matrix of a unit motor (its sandwich of the basis).
Motor8 compose(int kappa, const Motor8& a, const Motor8& b);
glm::dmat4 matrixOfMotor(int kappa, const Motor8& m);

// The motor of an orientation-preserving isometry `m` (O(4) with det +1 for S3; O(3,1)
// keeping det +1 and w > 0 for H3): the translator that moves the origin where m moves it,
// times the rotor of the rest (a rotation about the origin, GLM's quat_cast). Fails, naming
// the reason, when m is not such an isometry (residual of the round trip > 1e-6).
Result<Motor8> motorOfMatrix(int kappa, const glm::dmat4& m);

// The 8 floats curved_motor.vs takes for `m`: S3 its quaternion pair [L, R] (pga_kappa.glsl's
// pair_from_motor), H3 m itself.
Motor8 shaderMotor(int kappa, const Motor8& m);

// World -> view of `scene` at time t: the inverse moves in reverse order, composed.
Motor8 viewMotor(const CurvedScene& scene, double t);

// The same sandwich as the vertex shader, on the CPU (double): for the lights.
glm::dvec4 sandwich(int kappa, const Motor8& m, const glm::dvec4& p);

}  // namespace mb::curved
