#include "pipelines/scene/scale_analysis.h"

#include <algorithm>
#include <cmath>

namespace mb {

bool isNonUniform(const glm::vec3& s) {
  glm::vec3 a = glm::abs(s);
  float hi = std::max({a.x, a.y, a.z}), lo = std::min({a.x, a.y, a.z});
  return hi - lo > kScaleTolerance * hi;
}

ScaleClass classifyScale(const glm::vec3& s) {
  if (s.x * s.y * s.z < 0.0f) return ScaleClass::Negative;
  return isNonUniform(s) ? ScaleClass::NonUniform : ScaleClass::Uniform;
}

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
  }
  for (const Animation& a : scene.animations)
    for (const Channel& c : a.channels) {
      if (c.path != AnimPath::Scale || c.node < 0 || size_t(c.node) >= r.nodes.size()) continue;
      ++r.scaleChannels;
      NodeScale& ns = r.nodes[size_t(c.node)];
      ns.animated = true;
      size_t stride = c.interpolation == Interpolation::CubicSpline ? 3 : 1;
      for (size_t k = 0; k < c.times.size(); ++k) {
        const float* v = &c.values[(k * stride + stride / 2) * 3];  // key values, not tangents
        glm::vec3 s(v[0], v[1], v[2]);
        ns.animatedNonUniform |= isNonUniform(s);
        ns.animatedNegative |= s.x * s.y * s.z < 0.0f;
      }
    }
  for (const NodeScale& ns : r.nodes) {
    bool nonUniform = ns.restNonUniform || ns.animatedNonUniform || ns.shear;
    r.uniformNodes += ns.restClass == ScaleClass::Uniform;
    r.nonUniformNodes += ns.restNonUniform;
    r.negativeNodes += ns.restClass == ScaleClass::Negative || ns.animatedNegative;
    r.shearNodes += ns.shear;
    r.animatedScaleNodes += ns.animated;
    r.animatedNonUniformNodes += ns.animatedNonUniform;
    r.nonUniformScale |= nonUniform;
    r.negativeScale |= ns.restClass == ScaleClass::Negative || ns.animatedNegative;
    r.animatedScale |= ns.animated;
    r.animatedNonUniformScale |= ns.animatedNonUniform;
    if (nonUniform && !ns.leaf) r.nonUniformOnlyOnLeaves = false;
  }
  return r;
}

}  // namespace mb
