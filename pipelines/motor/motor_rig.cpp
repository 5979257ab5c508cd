#include "pipelines/motor/motor_rig.h"

#include <cmath>

#include "pipelines/scene/transform.h"

namespace mb::motor {
namespace {

void count(const ConversionFlags& f, RigCounts* c) {
  if (!c) return;
  c->nonUniformScaleNodes += f.nonUniform;
  c->nonUniformInnerNodes += f.nonUniformInner;
  c->negativeScaleNodes += f.negative;
  c->shearMatrixNodes += f.shear;
}

bool nodeIndexOk(const Scene& scene, int n) { return n >= 0 && size_t(n) < scene.nodes.size(); }

}  // namespace

Rig buildRig(const Scene& scene) {
  Rig rig;
  const size_t count_ = scene.nodes.size();
  rig.leaf.assign(count_, 1);
  rig.matrixNode.assign(count_, 0);
  for (size_t n = 0; n < count_; ++n)
    if (!scene.nodes[n].children.empty()) rig.leaf[n] = 0;
  // A joint is posed through its palette motor: a residual scale there could not reach the
  // vertices, so joints are converted as inner nodes.
  for (const Skin& s : scene.skins)
    for (int j : s.joints)
      if (nodeIndexOk(scene, j)) rig.leaf[size_t(j)] = 0;

  rig.rest.resize(count_);
  rig.restFlags.resize(count_);
  for (size_t n = 0; n < count_; ++n) {
    const Node& node = scene.nodes[n];
    rig.matrixNode[n] = node.hasMatrix;
    rig.rest[n] = node.hasMatrix ? fromMatrix(node.matrix, node.local, rig.leaf[n], &rig.restFlags[n])
                                 : fromTRS(node.local, rig.leaf[n], &rig.restFlags[n]);
  }
  for (const Skin& s : scene.skins) {
    std::vector<ScaledMotor> binds;
    for (size_t j = 0; j < s.joints.size(); ++j) {
      ConversionFlags f;
      // An inverse bind has no vertices of its own: never a residual (leaf = false).
      TRS approx;
      if (j < s.inverseBind.size()) decomposeMatrix(s.inverseBind[j], &approx);
      binds.push_back(j < s.inverseBind.size() ? fromMatrix(s.inverseBind[j], approx, false, &f)
                                               : identityScaledMotor());
      count(f, &rig.bindCounts);
    }
    rig.inverseBind.push_back(std::move(binds));
  }
  return rig;
}

std::vector<ScaledMotor> localPose(const Rig& rig, const std::vector<TRS>& pose,
                                   RigCounts* counts) {
  std::vector<ScaledMotor> local(rig.rest);
  for (size_t n = 0; n < local.size(); ++n) {
    ConversionFlags f = rig.restFlags[n];
    if (!rig.matrixNode[n] && n < pose.size()) local[n] = fromTRS(pose[n], rig.leaf[n], &f);
    count(f, counts);
  }
  return local;
}

std::vector<ScaledMotor> blendLocal(const std::vector<ScaledMotor>& a,
                                    const std::vector<ScaledMotor>& b, float w) {
  std::vector<ScaledMotor> out(a);
  for (size_t n = 0; n < out.size() && n < b.size(); ++n) out[n] = blend(a[n], b[n], w);
  return out;
}

std::vector<ScaledMotor> localForState(const Scene& scene, const Rig& rig, const AnimState& state,
                                       RigCounts* counts) {
  PhaseClock off(nullptr);
  return localForState(scene, rig, state, counts, off);
}

std::vector<ScaledMotor> localForState(const Scene& scene, const Rig& rig, const AnimState& state,
                                       RigCounts* counts, PhaseClock& clock) {
  const std::vector<TRS> first = sampleAnimation(scene, state.anim, state.time);
  clock.lap(&UpdatePhases::samplingMs);
  std::vector<ScaledMotor> a = localPose(rig, first, counts);
  clock.lap(&UpdatePhases::conversionMs);
  if (state.anim2 < 0) return a;
  const std::vector<TRS> second = sampleAnimation(scene, state.anim2, state.time2);
  clock.lap(&UpdatePhases::samplingMs);
  std::vector<ScaledMotor> b = localPose(rig, second);
  clock.lap(&UpdatePhases::conversionMs);
  std::vector<ScaledMotor> blended = blendLocal(a, b, state.blend);
  clock.lap(&UpdatePhases::blendingMs);
  return blended;
}

std::vector<ScaledMotor> worldPose(const Scene& scene, const std::vector<ScaledMotor>& local) {
  const size_t count_ = scene.nodes.size();
  std::vector<ScaledMotor> world(count_);
  std::vector<char> state(count_, 0);  // 0 todo, 1 on the current chain (cycle guard), 2 done
  for (size_t start = 0; start < count_; ++start) {
    // Walk up to the first finished ancestor, then compose the chain top-down.
    std::vector<size_t> chain;
    for (size_t n = start; state[n] == 0;) {
      state[n] = 1;
      chain.push_back(n);
      const int parent = scene.nodes[n].parent;
      if (!nodeIndexOk(scene, parent)) break;
      n = size_t(parent);
    }
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      const int parent = scene.nodes[*it].parent;
      const bool hasParent = nodeIndexOk(scene, parent) && state[size_t(parent)] == 2;
      world[*it] = hasParent ? compose(world[size_t(parent)], local[*it]) : local[*it];
      state[*it] = 2;
    }
  }
  return world;
}

std::vector<JointPalette> jointPalettes(const Scene& scene, const Rig& rig,
                                        const std::vector<ScaledMotor>& world,
                                        bool relativeToNode) {
  std::vector<JointPalette> out;
  for (size_t n = 0; n < scene.nodes.size(); ++n) {
    const Node& node = scene.nodes[n];
    if (node.mesh < 0 || node.skin < 0 || size_t(node.skin) >= scene.skins.size()) continue;
    const Skin& skin = scene.skins[size_t(node.skin)];
    JointPalette p;
    p.node = int(n);
    p.skin = node.skin;
    p.motors.reserve(skin.joints.size() * 8);
    const Motor toNode = relativeToNode ? mk().reverse_m(world[n].motor) : Motor();
    for (size_t j = 0; j < skin.joints.size(); ++j) {
      const int jn = skin.joints[j];
      const ScaledMotor joint = nodeIndexOk(scene, jn) ? world[size_t(jn)] : identityScaledMotor();
      ScaledMotor m = compose(joint, rig.inverseBind[size_t(node.skin)][j]);
      if (relativeToNode) m.motor = mk().gp_mm(toNode, m.motor);
      if (j == 0) p.scale = m.scale;
      else if (std::fabs(m.scale - p.scale) > 1e-4f * std::fabs(p.scale)) p.uniform = false;
      for (int c = 0; c < 2; ++c)
        for (int r = 0; r < 4; ++r) p.motors.push_back(m.motor[c][r]);
    }
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace mb::motor
