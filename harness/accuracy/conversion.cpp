#include "harness/accuracy/conversion.h"

#include <cstring>
#include <random>

#include "harness/accuracy/accuracy_figure.h"
#include "pipelines/motor/companion.h"

namespace mb::accuracy {
namespace {

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

QuatRotorCheck checkRotorFromQuat(int samples) {
  std::mt19937 g(1806);
  std::normal_distribution<float> n;
  QuatRotorCheck out;
  auto check = [&](glm::quat q) {
    const companion::Motor m = companion::rotorFromQuat(q);
    const bool exact = sameBits(m[0].x, q.w) && sameBits(m[0].y, -q.x) && sameBits(m[0].z, -q.y) &&
                       sameBits(m[0].w, -q.z);
    bool dualZero = true;
    for (int i = 0; i < 4; ++i) dualZero = dualZero && m[1][i] == 0.0f;
    ++out.samples;
    out.mismatches += !(exact && dualZero);
  };
  // The axis-aligned and signed-zero cases, then random unit quaternions.
  for (float s : {1.0f, -1.0f, 0.0f, -0.0f})
    for (int i = 0; i < 4; ++i) {
      glm::quat q(0.0f, 0.0f, 0.0f, 0.0f);
      q[i] = s;
      check(q);
    }
  for (int i = 0; i < samples; ++i) check(glm::normalize(glm::quat(n(g), n(g), n(g), n(g))));
  return out;
}

void putConversionFigures(const QuatRotorCheck& check, nlohmann::json& figures) {
  const std::string scope = "companion::rotorFromQuat (the loader's and the animation sampler's conversion) on 16 "
                            "axis-aligned and signed-zero quaternions and " + std::to_string(check.samples - 16) +
                            " random unit quaternions (fixed seed)";
  putFigure(figures, "conversion.quat_to_rotor.samples", check.samples, check.samples,
            {"quaternions", "counted", scope, "quaternions converted", "CPU, float32"});
  putFigure(figures, "conversion.quat_to_rotor.mismatches", check.mismatches, check.samples,
            {"quaternions", "counted: quaternions whose rotor differs in any bit", scope,
             "conversions whose output is not (w, -x, -y, -z) bit for bit with a zero dual half",
             "CPU, float32"});
}

}  // namespace mb::accuracy
