#include "pipelines/scene/scale_analysis.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mb {

bool isNonUniform(const glm::vec3& s) { return scaleNonUniformity(s) > kSimilarityTolerance; }

ScaleClass classifyScale(const glm::vec3& s) {
  if (s.x * s.y * s.z < 0.0f) return ScaleClass::Negative;
  return isNonUniform(s) ? ScaleClass::NonUniform : ScaleClass::Uniform;
}

double scaleNonUniformity(const glm::vec3& s) {
  // The reference's check compares neighbouring components as ratios; in double so that a float
  // scale's own rounding (1e-7) stays far below the 1e-4 rule.
  auto ratio = [](double a, double b) {
    a = std::fabs(a), b = std::fabs(b);
    if (a == b) return 0.0;
    if (b == 0.0) return std::numeric_limits<double>::infinity();
    return std::fabs(a / b - 1.0);
  };
  return std::max(ratio(s.x, s.y), ratio(s.y, s.z));
}

double scaleChange(const glm::vec3& from, const glm::vec3& to) {
  double worst = 0;
  for (int i = 0; i < 3; ++i) {
    const double a = from[i], b = to[i], big = std::max(std::fabs(a), std::fabs(b));
    if (big > 0) worst = std::max(worst, std::fabs(a - b) / big);
  }
  return worst;
}

namespace {

// The key values of a scale channel (CUBICSPLINE: the values, not the tangents).
std::vector<glm::vec3> scaleKeys(const Channel& c) {
  const size_t stride = c.interpolation == Interpolation::CubicSpline ? 3 : 1;
  std::vector<glm::vec3> keys;
  for (size_t k = 0; k < c.times.size(); ++k) {
    const size_t at = (k * stride + stride / 2) * 3;
    if (at + 2 >= c.values.size()) break;
    keys.emplace_back(c.values[at], c.values[at + 1], c.values[at + 2]);
  }
  return keys;
}

}  // namespace

ScaleReport analyzeScale(const Scene& scene) {
  ScaleReport r;
  r.nodes.resize(scene.nodes.size());
  for (size_t i = 0; i < scene.nodes.size(); ++i) {
    const Node& n = scene.nodes[i];
    NodeScale& ns = r.nodes[i];
    ns.restClass = classifyScale(n.local.scale);
    ns.restNonUniform = isNonUniform(n.local.scale);
    ns.shear = n.hasMatrix && n.matrixHasShear;
    ns.leaf = n.children.empty();
    ns.nonUniformity = ns.shear ? std::numeric_limits<double>::infinity() : scaleNonUniformity(n.local.scale);
    ns.leastUniform = n.local.scale;
  }
  for (const Animation& a : scene.animations)
    for (const Channel& c : a.channels) {
      if (c.path != AnimPath::Scale || c.node < 0 || size_t(c.node) >= r.nodes.size()) continue;
      ++r.scaleChannels;
      NodeScale& ns = r.nodes[size_t(c.node)];
      ns.animated = true;
      const glm::vec3 rest = scene.nodes[size_t(c.node)].local.scale;
      const std::vector<glm::vec3> keys = scaleKeys(c);
      bool changes = false, offRest = false, keyNonUniform = false;
      for (const glm::vec3& s : keys) {
        ns.animatedNonUniform |= isNonUniform(s);
        ns.animatedNegative |= s.x * s.y * s.z < 0.0f;
        const double nu = scaleNonUniformity(s);
        if (nu > ns.nonUniformity) ns.nonUniformity = nu, ns.leastUniform = s;
        keyNonUniform |= nu > kSimilarityTolerance;
        // Animating scale = the keys change over time: a key differs from the
        // first. Constant keys (all 1, or a fixed scale other than the rest scale) are counted
        // apart: they set a scale, they do not animate it.
        changes |= scaleChange(keys.front(), s) > kSimilarityTolerance;
        offRest |= scaleChange(rest, s) > kSimilarityTolerance;
      }
      r.changingScaleChannels += changes;
      r.nonUniformChangingChannels += changes && keyNonUniform;
      r.constantScaleChannels += !changes;
      r.constantScaleChannelsOffRest += !changes && offRest;
      r.animatedNonUniformKeys |= keyNonUniform;
    }
  for (size_t i = 0; i < r.nodes.size(); ++i) {
    const NodeScale& ns = r.nodes[i];
    // The statistics and the motor fallback's per-node flags above take the same tolerance.
    const bool nonUniform = ns.shear || ns.nonUniformity > kSimilarityTolerance;
    r.uniformNodes += ns.restClass == ScaleClass::Uniform;
    r.nonUniformNodes += ns.restNonUniform;
    r.negativeNodes += ns.restClass == ScaleClass::Negative || ns.animatedNegative;
    r.shearNodes += ns.shear;
    r.animatedScaleNodes += ns.animated;
    r.animatedNonUniformNodes += ns.animatedNonUniform;
    r.nonUniformScale |= nonUniform;
    r.negativeScale |= ns.restClass == ScaleClass::Negative || ns.animatedNegative;
    r.animatedScale |= ns.animated;
    r.animatedNonUniformScale = r.animatedNonUniformKeys;
    if (nonUniform && !ns.leaf) r.nonUniformOnlyOnLeaves = false;
    if (!ns.leaf && ns.nonUniformity > kSimilarityTolerance) {
      ++r.innerNonUniformNodes;
      if (ns.nonUniformity > r.innerNonUniformityMax) {
        r.innerNonUniformityMax = ns.nonUniformity, r.innerNonUniformNode = int(i);
        r.innerNonUniformName = scene.nodes[i].name, r.innerNonUniformScale = ns.leastUniform;
      }
    }
  }
  return r;
}

}  // namespace mb
