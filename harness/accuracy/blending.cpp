#include "harness/accuracy/blending.h"

#include <algorithm>
#include <cmath>

#include "harness/accuracy/accuracy_figure.h"
#include "pipelines/motor/companion.h"
#include "pipelines/motor/scaled_motor.h"
#include "pipelines/scene/loader.h"

namespace mb::accuracy {
namespace {

using json = nlohmann::json;

// Rotation angle between two unit quaternions, degrees (q and -q are the same rotation). The
// quaternions lie b = 2 atan2(|a - b|, |a + b|) apart on the unit sphere (accurate for tiny
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

// The largest deviation over the rotation channels of `a`; keyPairs 0 when it has none.
BlendDeviation deviationOf(const Animation& a) {
  BlendDeviation d;
  for (const Channel& ch : a.channels) {
    if (ch.path != AnimPath::Rotation || ch.interpolation == Interpolation::Step) continue;
    for (size_t k = 0; k + 1 < ch.times.size(); ++k) {
      const glm::quat q0 = keyAt(ch, k), q1 = keyAt(ch, k + 1);
      ++d.keyPairs;
      for (int s = 1; s < kBlendSteps; ++s) {
        const double dev = blendVsSlerpDegrees(q0, q1, float(s) / kBlendSteps);
        if (dev > d.largestDegrees) d.largestDegrees = dev, d.keyAngleDegrees = angleDegrees(q0, q1);
      }
    }
  }
  return d;
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

std::vector<BlendDeviation> measureBlending(const std::vector<std::string>& scenes) {
  std::vector<BlendDeviation> out;
  for (const std::string& name : scenes) {
    auto scene = loadScene(name);
    if (!scene) continue;
    for (const Animation& a : scene->animations) {
      BlendDeviation d = deviationOf(a);
      if (!d.keyPairs) continue;
      d.animation = name + "/" + (a.name.empty() ? std::string("(unnamed)") : a.name);
      out.push_back(d);
    }
  }
  return out;
}

void putBlendFigures(const std::vector<BlendDeviation>& animations, json& figures, json& details) {
  json per = json::object();
  double worst = 0;
  int pairs = 0;
  for (const BlendDeviation& d : animations) {
    per[d.animation] = {{"keyPairs", d.keyPairs}, {"largestDegrees", d.largestDegrees}, {"keyAngleDegrees", d.keyAngleDegrees}};
    worst = std::max(worst, d.largestDegrees);
    pairs += d.keyPairs;
  }
  details["blend"] = per;
  const int n = int(animations.size());
  const std::string scope = "every LINEAR or CUBICSPLINE rotation channel of the " + std::to_string(n) +
                            " animations of the built-in scenes that have one, consecutive key pairs at t = k/" +
                            std::to_string(kBlendSteps) + ", k = 1.." + std::to_string(kBlendSteps - 1);
  const double nan = std::nan("");
  putFigure(figures, "blend.max_angle_error_deg", n ? worst : nan, n,
            {"deg", "measured: worst over every key pair and parameter of every animation", scope,
             "rotation angle between the rotors of two consecutive keys blended by motor::blend (the pipeline's "
             "animation blend: shortest arc, normalize_m) and glm::slerp (double) of the quaternions at the same t",
             "CPU, double precision", "no rotation channel with two keys in the built-in scenes"});
  putFigure(figures, "blend.key_pairs", pairs, n,
            {"key pairs", "counted: sum over animations", scope, "consecutive rotation key pairs blended both ways"});
}

}  // namespace mb::accuracy
