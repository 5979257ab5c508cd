// The paper's tangent-frame handedness rule, measured on the built-in scenes. The paper stores
// the handedness in the sign of the tangent rotor's scalar part, chosen at load time with
//   if (Math.sign(motor[0]) != tangents[i*4+3]) motor = motor.map(x => -x);
// and decodes it in the shader as sign(1/x). When fromMatrix3 returns a scalar of exactly +-0
// (a half turn of the basis frame), Math.sign gives +-0, which never equals +-1, so the rotor is
// always negated: +0 becomes -0 (decoded -1) and -0 becomes +0 (decoded +1), right for one
// handedness and wrong for the other.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace mb::accuracy {

// The paper's printed load rule for one vertex frame, in JavaScript semantics (float64
// arithmetic, Math.sign(+-0) = +-0, map(x => -x) turns +0 into -0), then stored as float32 and
// decoded as the paper's shader does, sign(1 / s).
struct PaperFrame {
  double scalar = 0;             // the rotor's scalar part as stored
  bool scalarZero = false;       // fromMatrix3 gave a scalar of exactly +-0
  float handedness = 1;          // sign(1 / float(scalar))
  glm::vec4 rotor{1, 0, 0, 0};   // as stored (float32)
};
PaperFrame paperLoadRule(const glm::vec3& normal, const glm::vec4& tangent);

// One scene's frames under the rule: every vertex frame the motor pipeline converts (the inputs
// of motor::interleaveVertices), and at each wrong frame of a normal-mapped primitive the angle
// between the shading normal with the right and with the flipped bitangent.
struct HandednessCount {
  std::string scene;
  int frames = 0;
  int zeroScalar = 0;      // fromMatrix3's scalar exactly +-0 in float64
  int zeroScalarOurs = 0;  // our float conversion's zero-scalar frames (motor::interleaveVertices)
  int wrong = 0;           // decoded handedness != the tangent's w
  int wrongNormalMapped = 0;
  double worstDegrees = 0;  // worst shading-normal change at a wrong, normal-mapped vertex
};

// Every built-in scene in `scenes` that loads and has frames.
std::vector<HandednessCount> measureHandedness(const std::vector<std::string>& scenes);

// The figures handedness.* (documented in README.md) into `figures`, the per-scene counts into
// `details`.
void putHandednessFigures(const std::vector<HandednessCount>& counts, nlohmann::json& figures, nlohmann::json& details);

}  // namespace mb::accuracy
