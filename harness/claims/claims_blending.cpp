// Motor blending against slerp. The paper blends animations by "directly blending
// and renormalizing PGA motors" (the dual-quaternion pattern: a normalised linear blend), where
// the sampler interpolates rotations with slerp. How far apart are the two? Measured on every
// rotation channel of every animation of the built-in scenes: for each pair of consecutive
// keys, the motor blend (motor::blend: shortest arc, normalize_m) of their rotors against
// glm::slerp of the quaternions at the same parameter.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "harness/claims/claims_measures.h"
#include "harness/claims/claims_sources.h"
#include "pipelines/motor/companion.h"
#include "pipelines/motor/scaled_motor.h"
#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/loader.h"

namespace mb::claims {
namespace {

using json = nlohmann::json;

constexpr int kSteps = 32;  // parameters t = k / kSteps per key pair

// Rotation angle between two unit quaternions, degrees (q and -q are the same rotation);
// The quaternions lie b = 2 atan2(|a - b|, |a + b|) apart on the unit sphere (accurate for tiny
// angles, where acos(dot) is not), and the rotations twice that.
double angleDegrees(const glm::dquat& a, glm::dquat b) {
  const glm::dquat x = glm::normalize(a);
  b = glm::normalize(b);
  if (glm::dot(x, b) < 0.0) b = -b;
  const glm::dvec4 d(x.x - b.x, x.y - b.y, x.z - b.z, x.w - b.w), s(x.x + b.x, x.y + b.y, x.z + b.z, x.w + b.w);
  return glm::degrees(4.0 * std::atan2(glm::length(d), glm::length(s)));
}

glm::quat keyAt(const Channel& c, size_t k) {
  const size_t stride = c.interpolation == Interpolation::CubicSpline ? 12 : 4;
  const size_t at = k * stride + (c.interpolation == Interpolation::CubicSpline ? 4 : 0);
  const float* v = &c.values[at];
  return glm::normalize(glm::quat(v[3], v[0], v[1], v[2]));  // glTF x, y, z, w
}

}  // namespace

double blendVsSlerpDegrees(const glm::quat& a, const glm::quat& b, float t) {
  motor::ScaledMotor ma, mb;
  ma.motor = companion::rotorFromQuat(a), mb.motor = companion::rotorFromQuat(b);
  const motor::ScaledMotor m = motor::blend(ma, mb, t);
  // rotor [w, -x, -y, -z] -> quaternion
  const glm::dquat blended(m.motor[0].x, -m.motor[0].y, -m.motor[0].z, -m.motor[0].w);
  const glm::dquat slerp = glm::slerp(glm::dquat(a), glm::dquat(b), double(t));
  return angleDegrees(blended, slerp);
}

std::vector<Claim> blendingClaims() {
  Claim c{"blend_vs_slerp", "Animation blending",
          "blending and renormalising motors stands in for slerp (animation blending)"};
  c.paper = "the dual-quaternion technique, \"directly blending and renormalizing PGA motors\" (no figure)";
  c.paperValue = nullptr;
  json per = json::object();
  std::string text;
  double worst = 0;
  int animations = 0;
  for (const std::string& name : builtinSceneNames()) {
    auto scene = loadScene(name);
    if (!scene) continue;
    for (const Animation& a : scene->animations) {
      double dev = 0, keyAngle = 0;
      int pairs = 0;
      for (const Channel& ch : a.channels) {
        if (ch.path != AnimPath::Rotation || ch.interpolation == Interpolation::Step) continue;
        for (size_t k = 0; k + 1 < ch.times.size(); ++k) {
          const glm::quat q0 = keyAt(ch, k), q1 = keyAt(ch, k + 1);
          ++pairs;
          for (int s = 1; s < kSteps; ++s) {
            const double d = blendVsSlerpDegrees(q0, q1, float(s) / kSteps);
            if (d > dev) dev = d, keyAngle = angleDegrees(q0, q1);
          }
        }
      }
      if (!pairs) continue;
      ++animations;
      const std::string id = name + "/" + (a.name.empty() ? std::string("(unnamed)") : a.name);
      per[id] = {{"keyPairs", pairs}, {"largestDegrees", dev}, {"keyAngleDegrees", keyAngle}};
      text += (text.empty() ? "" : "; ") + id + " " + fmt("%.3g deg", dev) + " (keys " + fmt("%.0f deg", keyAngle) + " apart)";
      worst = std::max(worst, dev);
    }
  }
  c.measured = "largest rotation difference per animation: " + (text.empty() ? std::string("none") : text);
  c.measuredValue = {{"largestDegrees", worst}, {"animations", per}};
  c.method = "every LINEAR or CUBICSPLINE rotation channel of every animation of the built-in scenes; for each pair of "
             "consecutive keys (their values) and t = k/" + std::to_string(kSteps) + ", k = 1.." +
             std::to_string(kSteps - 1) + ": the rotors of the two quaternions blended by motor::blend (the pipeline's "
             "animation blend: shortest arc, normalize_m) against glm::slerp (double) at t; the rotation angle between "
             "the two, the largest per animation (with the angle between the keys where it occurs). The sampler itself "
             "interpolates keys with slerp in both pipelines; this measures what blending motors in place of slerp "
             "would change.";
  if (!animations) {
    c.verdict = Verdict::NotMeasurable;
    c.verdictText = "not measurable here: no rotation channel with two keys in the built-in scenes";
  } else {
    c.verdict = Verdict::Inconclusive;
    c.verdictText = "inconclusive: the paper states no tolerance; the normalised blend departs from slerp by up to " +
                    fmt("%.3g degrees", worst) + " (largest where keys are far apart; zero at t = 0, 1/2, 1)";
  }
  return {c};
}

}  // namespace mb::claims
