// Motor blending against slerp. The paper blends animations by "directly blending and
// renormalizing PGA motors" (the dual-quaternion pattern: a normalised linear blend), where the
// sampler interpolates rotations with slerp. Measured on every rotation channel of every
// animation of the built-in scenes: for each pair of consecutive keys, the motor blend
// (motor::blend: shortest arc, normalize_m) of their rotors against glm::slerp of the
// quaternions at the same parameter.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

namespace mb::accuracy {

// Parameters t = k / kBlendSteps, k = 1 .. kBlendSteps - 1, per key pair.
inline constexpr int kBlendSteps = 32;

// Rotation angle (degrees) between the motor blend of the rotors of a and b at weight t and
// glm::slerp(a, b, t).
double blendVsSlerpDegrees(const glm::quat& a, const glm::quat& b, float t);

struct BlendDeviation {
  std::string animation;  // "scene/animation"
  int keyPairs = 0;
  double largestDegrees = 0;   // over every key pair and t
  double keyAngleDegrees = 0;  // the angle between the keys where the largest occurs
};

// Every animation of `scenes` (built-in names) with a LINEAR or CUBICSPLINE rotation channel.
std::vector<BlendDeviation> measureBlending(const std::vector<std::string>& scenes);

// The figures blend.* into `figures`, the per-animation deviations into `details`.
void putBlendFigures(const std::vector<BlendDeviation>& animations, nlohmann::json& figures, nlohmann::json& details);

}  // namespace mb::accuracy
