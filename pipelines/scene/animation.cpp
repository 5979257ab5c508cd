#include "pipelines/scene/animation.h"

#include <algorithm>
#include <cmath>

namespace mb {
namespace {

// The keyframe interval containing t: values of keys k0 and k1 with t = lerp(t0, t1, u).
// Outside the keyed range both keys are the end key (clamp).
struct Segment {
  size_t k0 = 0, k1 = 0;
  float u = 0.0f, dt = 0.0f;
};

Segment locate(const std::vector<float>& times, float t) {
  Segment s;
  size_t last = times.size() - 1;
  if (!(t > times.front())) return s;  // also catches NaN
  if (t >= times[last]) {
    s.k0 = s.k1 = last;
    return s;
  }
  s.k1 = size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin());
  s.k0 = s.k1 - 1;
  s.dt = times[s.k1] - times[s.k0];
  s.u = s.dt > 0.0f ? (t - times[s.k0]) / s.dt : 1.0f;
  return s;
}

glm::vec4 load(const Channel& c, size_t element, int comps) {
  const float* v = &c.values[element * size_t(comps)];
  return comps == 4 ? glm::vec4(v[0], v[1], v[2], v[3]) : glm::vec4(v[0], v[1], v[2], 0.0f);
}

glm::quat toQuat(const glm::vec4& xyzw) { return glm::quat(xyzw.w, xyzw.x, xyzw.y, xyzw.z); }

glm::quat shortestSlerp(glm::quat a, glm::quat b, float u) {
  float d = glm::dot(a, b);
  if (d < 0.0f) {
    b = -b;
    d = -d;
  }
  if (d > 0.9995f) return glm::normalize(a * (1.0f - u) + b * u);  // nearly equal: nlerp
  float theta = std::acos(std::min(d, 1.0f));
  float s = std::sin(theta);
  return a * (std::sin((1.0f - u) * theta) / s) + b * (std::sin(u * theta) / s);
}

// Value of channel c at time t, as vec4 (xyz for T/S; quaternion x,y,z,w for R).
glm::vec4 evaluate(const Channel& c, float t) {
  int comps = c.path == AnimPath::Rotation ? 4 : 3;
  Segment s = locate(c.times, t);
  bool cubic = c.interpolation == Interpolation::CubicSpline;
  size_t stride = cubic ? 3 : 1, mid = cubic ? 1 : 0;
  glm::vec4 v0 = load(c, s.k0 * stride + mid, comps);
  if (s.k0 == s.k1 || c.interpolation == Interpolation::Step) return v0;
  glm::vec4 v1 = load(c, s.k1 * stride + mid, comps);
  if (!cubic) {
    if (comps == 4) {
      glm::quat q = shortestSlerp(toQuat(v0), toQuat(v1), s.u);
      return glm::vec4(q.x, q.y, q.z, q.w);
    }
    return v0 + (v1 - v0) * s.u;
  }
  // glTF 2.0 Appendix C: Hermite spline with tangents scaled by the key interval.
  glm::vec4 out0 = load(c, s.k0 * 3 + 2, comps), in1 = load(c, s.k1 * 3, comps);
  float u = s.u, u2 = u * u, u3 = u2 * u;
  glm::vec4 r = (2 * u3 - 3 * u2 + 1) * v0 + s.dt * (u3 - 2 * u2 + u) * out0 + (-2 * u3 + 3 * u2) * v1 +
                s.dt * (u3 - u2) * in1;
  if (comps == 4) {
    float len = glm::length(r);
    r = len > 0.0f ? r / len : glm::vec4(0, 0, 0, 1);
  }
  return r;
}

// Weights channel c at time t into out[0..weightCount): the same interval and spline as
// evaluate(), per weight (no normalisation).
void evaluateWeights(const Channel& c, float t, float* out) {
  const size_t n = size_t(c.weightCount);
  Segment s = locate(c.times, t);
  bool cubic = c.interpolation == Interpolation::CubicSpline;
  size_t stride = cubic ? 3 : 1, mid = cubic ? 1 : 0;
  auto at = [&](size_t element, size_t i) { return c.values[element * n + i]; };
  for (size_t i = 0; i < n; ++i) {
    float v0 = at(s.k0 * stride + mid, i);
    if (s.k0 == s.k1 || c.interpolation == Interpolation::Step) {
      out[i] = v0;
      continue;
    }
    float v1 = at(s.k1 * stride + mid, i);
    if (!cubic) {
      out[i] = v0 + (v1 - v0) * s.u;
      continue;
    }
    float u = s.u, u2 = u * u, u3 = u2 * u;
    out[i] = (2 * u3 - 3 * u2 + 1) * v0 + s.dt * (u3 - 2 * u2 + u) * at(s.k0 * 3 + 2, i) + (-2 * u3 + 3 * u2) * v1 +
             s.dt * (u3 - u2) * at(s.k1 * 3, i);
  }
}

}  // namespace

std::vector<TRS> sampleAnimation(const Scene& scene, int anim, float time) {
  std::vector<TRS> pose;
  sampleAnimation(scene, anim, time, pose);
  return pose;
}

void sampleAnimation(const Scene& scene, int anim, float time, std::vector<TRS>& pose) {
  pose.resize(scene.nodes.size());
  for (size_t i = 0; i < pose.size(); ++i) pose[i] = scene.nodes[i].local;
  if (anim < 0 || size_t(anim) >= scene.animations.size()) return;
  for (const Channel& c : scene.animations[size_t(anim)].channels) {
    if (c.node < 0 || size_t(c.node) >= pose.size() || c.times.empty() || c.path == AnimPath::Weights) continue;
    glm::vec4 v = evaluate(c, time);
    TRS& trs = pose[size_t(c.node)];
    switch (c.path) {
      case AnimPath::Translation: trs.translation = glm::vec3(v); break;
      case AnimPath::Rotation: trs.rotation = toQuat(v); break;
      case AnimPath::Scale: trs.scale = glm::vec3(v); break;
      case AnimPath::Weights: break;  // sampleMorphWeights
    }
  }
}

std::vector<TRS> blendPoses(const std::vector<TRS>& a, const std::vector<TRS>& b, float w) {
  std::vector<TRS> out;
  blendPoses(a, b, w, out);
  return out;
}

void blendPoses(const std::vector<TRS>& a, const std::vector<TRS>& b, float w, std::vector<TRS>& out) {
  if (&out != &a) out = a;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    TRS& o = out[i];  // may be a[i]: each field is read before it is written
    o.translation = glm::mix(o.translation, b[i].translation, w);
    o.scale = glm::mix(o.scale, b[i].scale, w);
    o.rotation = shortestSlerp(o.rotation, b[i].rotation, w);
  }
}

std::vector<std::vector<int>> animatedNodes(const Scene& scene) {
  std::vector<std::vector<int>> out;
  for (const Animation& a : scene.animations) {
    std::vector<char> driven(scene.nodes.size(), 0);
    for (const Channel& c : a.channels)
      if (c.node >= 0 && size_t(c.node) < driven.size() && !c.times.empty() && c.path != AnimPath::Weights)
        driven[size_t(c.node)] = 1;
    std::vector<int> nodes;
    for (size_t n = 0; n < driven.size(); ++n)
      if (driven[n]) nodes.push_back(int(n));
    out.push_back(std::move(nodes));
  }
  return out;
}

void sampleMorphWeights(const Scene& scene, int anim, float time, std::vector<std::vector<float>>& weights) {
  weights.resize(scene.nodes.size());
  for (size_t n = 0; n < scene.nodes.size(); ++n) {
    const Node& node = scene.nodes[n];
    const Mesh* mesh = node.mesh >= 0 && size_t(node.mesh) < scene.meshes.size() ? &scene.meshes[size_t(node.mesh)] : nullptr;
    if (!mesh || morphTargetCount(*mesh) == 0) weights[n].clear();
    else weights[n] = node.weights.empty() ? mesh->weights : node.weights;
  }
  if (anim < 0 || size_t(anim) >= scene.animations.size()) return;
  for (const Channel& c : scene.animations[size_t(anim)].channels) {
    if (c.path != AnimPath::Weights || c.node < 0 || size_t(c.node) >= weights.size() || c.times.empty()) continue;
    std::vector<float>& w = weights[size_t(c.node)];
    if (w.size() != size_t(c.weightCount)) continue;  // the loader made them equal
    evaluateWeights(c, time, w.data());
  }
}

std::vector<std::vector<float>> sampleMorphWeights(const Scene& scene, const AnimState& state) {
  std::vector<std::vector<float>> a, b;
  sampleMorphWeights(scene, state.anim, state.time, a);
  if (state.anim2 < 0) return a;
  sampleMorphWeights(scene, state.anim2, state.time2, b);
  for (size_t n = 0; n < a.size(); ++n)
    for (size_t i = 0; i < a[n].size(); ++i) a[n][i] += (b[n][i] - a[n][i]) * state.blend;
  return a;
}

std::vector<TRS> samplePose(const Scene& scene, const AnimState& state) {
  std::vector<TRS> a = sampleAnimation(scene, state.anim, state.time);
  if (state.anim2 < 0) return a;
  return blendPoses(a, sampleAnimation(scene, state.anim2, state.time2), state.blend);
}

}  // namespace mb
