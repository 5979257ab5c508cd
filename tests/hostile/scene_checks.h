// Invariants every loaded Scene must satisfy, whatever the input file was: the pipelines index
// GPU buffers and node arrays with these values, so a violation is a crash or a silently wrong
// image later. Used by the hostile-input tests and by the fuzzer (tests/fuzz/fuzz_loader.cpp).
#pragma once
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "pipelines/scene/animation.h"
#include "pipelines/scene/scene.h"

namespace mb::hostile {

inline bool finite(const glm::vec2& v) { return std::isfinite(v.x) && std::isfinite(v.y); }
inline bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
inline bool finite(const glm::vec4& v) { return finite(glm::vec3(v)) && std::isfinite(v.w); }
inline bool finite(const glm::quat& q) {
  return std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z) && std::isfinite(q.w);
}
inline bool finite(const TRS& t) {
  return finite(t.translation) && finite(t.rotation) && finite(t.scale);
}

// The steps of checkSceneInvariants, in its order: each "" or its first violation. Later
// steps index with values the earlier ones checked.
namespace invariants {

inline bool inRange(int i, size_t n) { return i >= -1 && i < int(n); }

// Per node: references in range, parent and child links consistent, finite transforms.
inline std::string nodeLinks(const Scene& s) {
  std::ostringstream err;
  const int nNodes = int(s.nodes.size());
  for (int i = 0; i < nNodes; ++i) {
    const Node& n = s.nodes[size_t(i)];
    if (!inRange(n.parent, s.nodes.size())) return (err << "node " << i << ": parent " << n.parent << " out of range", err.str());
    if (!inRange(n.mesh, s.meshes.size())) return (err << "node " << i << ": mesh " << n.mesh << " out of range", err.str());
    if (!inRange(n.skin, s.skins.size())) return (err << "node " << i << ": skin " << n.skin << " out of range", err.str());
    if (!inRange(n.camera, s.cameras.size())) return (err << "node " << i << ": camera " << n.camera << " out of range", err.str());
    for (int c : n.children) {
      if (c < 0 || c >= nNodes) return (err << "node " << i << ": child " << c << " out of range", err.str());
      if (s.nodes[size_t(c)].parent != i)
        return (err << "node " << i << ": child " << c << " has parent " << s.nodes[size_t(c)].parent, err.str());
    }
    if (n.parent >= 0) {
      const auto& sib = s.nodes[size_t(n.parent)].children;
      if (std::count(sib.begin(), sib.end(), i) != 1)
        return (err << "node " << i << ": not listed exactly once among its parent's children", err.str());
    }
    if (!finite(n.local)) return (err << "node " << i << ": non-finite TRS", err.str());
    for (const TRS& t : n.instances)  // EXT_mesh_gpu_instancing: finite, unit rotations
      if (!finite(t) || std::abs(glm::length(t.rotation) - 1.0f) > 1e-5f)
        return (err << "node " << i << ": instance TRS not finite or rotation not unit", err.str());
    if (!n.instances.empty() && (n.mesh < 0 || n.skin >= 0))
      return (err << "node " << i << ": instances on a node without mesh or with a skin", err.str());
  }
  return "";
}

// Acyclic: walking up from any node reaches a root. Linear: each node is walked once
// (0 = not yet seen, 1 = on the current walk, 2 = known to reach a root). Roots are parentless.
inline std::string parentChains(const Scene& s) {
  std::ostringstream err;
  const int nNodes = int(s.nodes.size());
  std::vector<char> state(size_t(nNodes), 0);
  std::vector<int> walk;
  for (int i = 0; i < nNodes; ++i) {
    walk.clear();
    int p = i;
    while (p >= 0 && state[size_t(p)] == 0) {
      state[size_t(p)] = 1;
      walk.push_back(p);
      p = s.nodes[size_t(p)].parent;
    }
    if (p >= 0 && state[size_t(p)] == 1) return (err << "node " << i << ": parent chain has a cycle", err.str());
    for (int q : walk) state[size_t(q)] = 2;
  }
  for (int r : s.roots) {
    if (r < 0 || r >= nNodes) return (err << "root " << r << " out of range", err.str());
    if (s.nodes[size_t(r)].parent != -1) return (err << "root " << r << " has a parent", err.str());
  }
  return "";
}

// Stream lengths, indices, material, and unit / finite / normalised vertex data.
inline std::string primitives(const Scene& s) {
  std::ostringstream err;
  for (size_t m = 0; m < s.meshes.size(); ++m) {
    for (size_t k = 0; k < s.meshes[m].primitives.size(); ++k) {
      const Primitive& p = s.meshes[m].primitives[k];
      const size_t nv = p.positions.size();
      auto where = [&] { err << "mesh " << m << " prim " << k << ": "; };
      auto sized = [&](size_t n) { return n == 0 || n == nv; };
      if (p.normals.size() != nv) return (where(), err << p.normals.size() << " normals for " << nv << " positions", err.str());
      if (!sized(p.tangents.size()) || !sized(p.uv0.size()) || !sized(p.uv1.size()) ||
          !sized(p.colors.size()) || !sized(p.joints.size()) || !sized(p.weights.size()))
        return (where(), err << "attribute stream length differs from position count " << nv, err.str());
      if (p.joints.size() != p.weights.size()) return (where(), err << "JOINTS/WEIGHTS count mismatch", err.str());
      if (p.indices.size() % 3) return (where(), err << p.indices.size() << " indices: not a triangle list", err.str());
      for (uint32_t ix : p.indices)
        if (ix >= nv) return (where(), err << "index " << ix << " >= vertex count " << nv, err.str());
      if (!inRange(p.material, s.materials.size())) return (where(), err << "material " << p.material << " out of range", err.str());
      for (size_t v = 0; v < nv; ++v) {
        if (!finite(p.positions[v])) return (where(), err << "position " << v << " not finite", err.str());
        const glm::vec3& nrm = p.normals[v];
        if (!finite(nrm) || std::abs(glm::length(nrm) - 1.0f) > 1e-3f)
          return (where(), err << "normal " << v << " not unit length", err.str());
        if (!p.tangents.empty()) {
          const glm::vec4& t = p.tangents[v];
          if (!finite(t) || std::abs(glm::length(glm::vec3(t)) - 1.0f) > 1e-3f || std::abs(std::abs(t.w) - 1.0f) > 1e-6f)
            return (where(), err << "tangent " << v << " not unit length or w not +-1", err.str());
        }
        if (!p.uv0.empty() && !finite(p.uv0[v])) return (where(), err << "uv0 " << v << " not finite", err.str());
        if (!p.uv1.empty() && !finite(p.uv1[v])) return (where(), err << "uv1 " << v << " not finite", err.str());
        if (!p.colors.empty() && !finite(p.colors[v])) return (where(), err << "color " << v << " not finite", err.str());
        if (!p.weights.empty()) {
          const glm::vec4& w = p.weights[v];
          if (!finite(w) || w.x < 0 || w.y < 0 || w.z < 0 || w.w < 0 || std::abs(w.x + w.y + w.z + w.w - 1.0f) > 1e-3f)
            return (where(), err << "weights " << v << " not finite, negative or not summing to 1", err.str());
        }
      }
    }
  }
  return "";
}

// Skinned nodes: every joint index of their primitives addresses a joint of their skin.
inline std::string jointIndices(const Scene& s) {
  std::ostringstream err;
  const int nNodes = int(s.nodes.size());
  for (int i = 0; i < nNodes; ++i) {
    const Node& n = s.nodes[size_t(i)];
    if (n.mesh < 0 || n.skin < 0) continue;
    const size_t nj = s.skins[size_t(n.skin)].joints.size();
    for (const Primitive& p : s.meshes[size_t(n.mesh)].primitives)
      for (const auto& j : p.joints)
        for (int c = 0; c < 4; ++c)
          if (j[c] >= nj) return (err << "node " << i << ": joint index " << j[c] << " >= skin joint count " << nj, err.str());
  }
  return "";
}

// Skins: one inverse bind matrix per joint, joints and skeleton in range, finite matrices.
inline std::string skins(const Scene& s) {
  std::ostringstream err;
  const int nNodes = int(s.nodes.size());
  for (size_t k = 0; k < s.skins.size(); ++k) {
    const Skin& sk = s.skins[k];
    if (sk.inverseBind.size() != sk.joints.size()) return (err << "skin " << k << ": inverseBind count != joint count", err.str());
    for (int j : sk.joints)
      if (j < 0 || j >= nNodes) return (err << "skin " << k << ": joint node " << j << " out of range", err.str());
    if (!inRange(sk.skeleton, s.nodes.size())) return (err << "skin " << k << ": skeleton out of range", err.str());
    for (const glm::mat4& m : sk.inverseBind)
      for (int c = 0; c < 4; ++c)
        if (!finite(m[c])) return (err << "skin " << k << ": non-finite inverse bind matrix", err.str());
  }
  return "";
}

// Cameras finite; material textures, texture images and samplers in range; image sizes.
inline std::string references(const Scene& s) {
  std::ostringstream err;
  for (size_t k = 0; k < s.cameras.size(); ++k) {
    const Camera& c = s.cameras[k];
    for (float v : {c.yfov, c.aspect, c.znear, c.zfar, c.xmag, c.ymag})
      if (!std::isfinite(v)) return (err << "camera " << k << ": non-finite parameter", err.str());
  }
  for (size_t m = 0; m < s.materials.size(); ++m) {
    const Material& mat = s.materials[m];
    for (const TextureRef* t : {&mat.baseColor, &mat.metallicRoughness, &mat.normal, &mat.occlusion, &mat.emissive})
      if (!inRange(t->texture, s.textures.size())) return (err << "material " << m << ": texture " << t->texture << " out of range", err.str());
  }
  for (size_t t = 0; t < s.textures.size(); ++t) {
    if (!inRange(s.textures[t].image, s.images.size())) return (err << "texture " << t << ": image out of range", err.str());
    if (!inRange(s.textures[t].sampler, s.samplers.size())) return (err << "texture " << t << ": sampler out of range", err.str());
  }
  for (size_t i = 0; i < s.images.size(); ++i) {
    const Image& im = s.images[i];
    if (im.width < 0 || im.height < 0 || im.rgba.size() != size_t(im.width) * size_t(im.height) * 4)
      return (err << "image " << i << ": " << im.rgba.size() << " bytes for " << im.width << "x" << im.height, err.str());
  }
  return "";
}

// Animations: finite durations, targets in range, value counts, finite ordered times.
inline std::string animations(const Scene& s) {
  std::ostringstream err;
  const int nNodes = int(s.nodes.size());
  for (size_t a = 0; a < s.animations.size(); ++a) {
    const Animation& an = s.animations[a];
    if (!std::isfinite(an.duration) || an.duration < 0) return (err << "animation " << a << ": bad duration", err.str());
    for (size_t c = 0; c < an.channels.size(); ++c) {
      const Channel& ch = an.channels[c];
      auto where = [&] { err << "animation " << a << " channel " << c << ": "; };
      if (ch.node < 0 || ch.node >= nNodes) return (where(), err << "node " << ch.node << " out of range", err.str());
      if (ch.times.empty()) return (where(), err << "no keyframes", err.str());
      // Floats per key: 4 (rotation), the node's morph target count (weights), else 3.
      const size_t width = ch.path == AnimPath::Rotation ? 4 : ch.path == AnimPath::Weights ? size_t(ch.weightCount) : 3;
      const size_t per = ch.interpolation == Interpolation::CubicSpline ? 3 : 1;
      if (ch.values.size() != ch.times.size() * width * per)
        return (where(), err << ch.values.size() << " values for " << ch.times.size() << " keys", err.str());
      for (size_t k = 0; k < ch.times.size(); ++k) {
        if (!std::isfinite(ch.times[k])) return (where(), err << "time " << k << " not finite", err.str());
        if (k && ch.times[k] < ch.times[k - 1]) return (where(), err << "times decrease at key " << k, err.str());
      }
    }
  }
  return "";
}

}  // namespace invariants

// "" when every invariant holds, else the first violation, e.g. "mesh 0 prim 1: index 7 >= 4".
inline std::string checkSceneInvariants(const Scene& s) {
  using namespace invariants;
  for (auto* step : {nodeLinks, parentChains, primitives, jointIndices, skins, references, animations}) {
    std::string e = step(s);
    if (!e.empty()) return e;
  }
  return "";
}

// True when every authored number a pose or a framing is made from is modest (|x| < 1e6), so a
// non-finite result can only come from the code and not from overflowing arithmetic on absurd
// values.
inline bool poseInputsTame(const Scene& s) {
  auto tame = [](float x) { return std::isfinite(x) && std::abs(x) < 1e6f; };
  for (const Node& n : s.nodes) {
    const float* f = &n.local.translation.x;
    for (int i = 0; i < 3; ++i)
      if (!tame(f[i]) || !tame((&n.local.scale.x)[i])) return false;
  }
  for (const Mesh& m : s.meshes)
    for (const Primitive& p : m.primitives)
      for (const glm::vec3& v : p.positions)
        if (!tame(v.x) || !tame(v.y) || !tame(v.z)) return false;
  for (const Skin& sk : s.skins)
    for (const glm::mat4& m : sk.inverseBind)
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
          if (!tame(m[c][r])) return false;
  for (const Animation& a : s.animations) {
    if (!tame(a.duration)) return false;
    for (const Channel& c : a.channels) {
      for (float t : c.times)
        if (!tame(t)) return false;
      for (float v : c.values)
        if (!tame(v)) return false;
    }
  }
  return true;
}

// Runs what every pipeline runs on a loaded scene: rest pose, each animation sampled at a few
// times (before, inside and after its range) and a blend of two animations. "" when every pose
// has one TRS per node and (for tame inputs) only finite numbers.
inline std::string exercisePoses(const Scene& s) {
  const bool tame = poseInputsTame(s);
  auto check = [&](const std::vector<TRS>& pose, const char* what, int anim, float t) -> std::string {
    std::ostringstream err;
    if (pose.size() != s.nodes.size())
      return (err << what << " anim " << anim << " t=" << t << ": " << pose.size() << " TRS for " << s.nodes.size() << " nodes", err.str());
    if (tame)
      for (size_t i = 0; i < pose.size(); ++i)
        if (!finite(pose[i].translation) || !finite(pose[i].scale) || !finite(pose[i].rotation))
          return (err << what << " anim " << anim << " t=" << t << ": node " << i << " non-finite", err.str());
    return "";
  };
  std::string e = check(samplePose(s, AnimState{}), "rest pose", -1, 0.0f);
  if (!e.empty()) return e;
  const int nAnim = int(s.animations.size());
  for (int a = 0; a < nAnim && a < 8; ++a) {
    const float d = s.animations[size_t(a)].duration;
    for (float t : {-1.0f, 0.0f, 0.37f * d, 0.5f * d, d, d + 1.0f}) {
      e = check(sampleAnimation(s, a, t), "sampleAnimation", a, t);
      if (!e.empty()) return e;
      AnimState st;
      st.anim = a;
      st.time = t;
      st.anim2 = (a + 1) % nAnim;
      st.time2 = 0.5f * t;
      st.blend = 0.3f;
      e = check(samplePose(s, st), "samplePose blend", a, t);
      if (!e.empty()) return e;
    }
  }
  return "";
}

}  // namespace mb::hostile
