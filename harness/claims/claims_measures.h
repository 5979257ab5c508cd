// The measurements behind the claim rows that tests check against independent
// references (hand-derived counts, GLM, closed forms). The rows themselves: claims_sources.h.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "shaders/shim/counted.h"

namespace mb::claims {

// claims_composition.cpp: the affine mat4x3 product counted on mb::Counted.
OpCounts countAffineCompose();

// claims_conversion.cpp: companion::rotorFromQuat counted (as written, on mb::Counted) and
// checked bit for bit on `samples` random unit quaternions plus 16 axis-aligned/signed-zero ones.
OpCounts countRotorFromQuat();
struct QuatRotorCheck {
  int samples = 0, mismatches = 0;
};
QuatRotorCheck checkRotorFromQuat(int samples);

// claims_handedness.cpp: the paper's printed load rule for one vertex frame, in JavaScript
// semantics (float64 arithmetic, Math.sign(+-0) = +-0, map(x => -x) turns +0 into -0), then
// stored as float32 and decoded as the paper's shader does, sign(1 / s).
struct PaperFrame {
  double scalar = 0;       // the rotor's scalar part as stored
  bool scalarZero = false; // fromMatrix3 gave a scalar of exactly +-0
  float handedness = 1;    // sign(1 / float(scalar))
  glm::vec4 rotor{1, 0, 0, 0};  // as stored (float32)
};
PaperFrame paperLoadRule(const glm::vec3& normal, const glm::vec4& tangent);

// claims_blending.cpp: rotation angle (degrees) between the motor blend of the rotors of a and
// b at weight t (motor::blend: shortest arc, normalize_m) and glm::slerp(a, b, t).
double blendVsSlerpDegrees(const glm::quat& a, const glm::quat& b, float t);

// claims_skinning.cpp: enclosed volume of a triangle mesh (sum of signed tetrahedra from the
// origin; meaningful for a closed mesh), and whether the mesh is closed once vertices at the
// same position are welded (every edge shared by exactly two triangles).
double enclosedVolume(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices);
bool isClosed(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices);

}  // namespace mb::claims
