#include "pipelines/motor/motor_rig.h"

#include <cmath>

#include "pipelines/motor/linear_fallback.h"
#include "pipelines/scene/drawn_skins.h"
#include "pipelines/scene/scale_analysis.h"
#include "pipelines/scene/transform.h"

namespace mb::motor {
namespace {

void count(const ConversionFlags& f, RigCounts* c, int sign = 1) {
  if (!c) return;
  c->nonUniformScaleNodes += sign * f.nonUniform;
  c->negativeScaleNodes += sign * f.negative;
  c->shearMatrixNodes += sign * f.shear;
}

// localPose for one unblended animation: the rest motors, the driven nodes converted.
void animatedLocalPose(const Rig& rig, const std::vector<TRS>& pose, int anim, std::vector<ScaledMotor>& local,
                       RigCounts* counts) {
  local = rig.rest;
  if (counts) {
    counts->nonUniformScaleNodes += rig.restCounts.nonUniformScaleNodes;
    counts->negativeScaleNodes += rig.restCounts.negativeScaleNodes;
    counts->shearMatrixNodes += rig.restCounts.shearMatrixNodes;
  }
  if (anim < 0 || size_t(anim) >= rig.animated.size()) return;
  for (int i : rig.animated[size_t(anim)]) {
    const size_t n = size_t(i);
    if (rig.matrixNode[n] || n >= pose.size()) continue;
    ConversionFlags f = rig.restFlags[n];
    local[n] = fromTRS(pose[n], rig.leaf[n], &f);
    count(rig.restFlags[n], counts, -1);
    count(f, counts);
  }
}

bool nodeIndexOk(const Scene& scene, int n) { return n >= 0 && size_t(n) < scene.nodes.size(); }

// Animation blending by blending motors, in place in `a`: per node shortest-arc blend +
// normalize_m, scales lerped (scaled_motor.h blend). w = weight of b.
void blendLocal(std::vector<ScaledMotor>& a, const std::vector<ScaledMotor>& b, float w) {
  for (size_t n = 0; n < a.size() && n < b.size(); ++n) a[n] = blend(a[n], b[n], w);
}

}  // namespace

Rig buildRig(const Scene& scene) {
  Rig rig;
  const size_t count_ = scene.nodes.size();
  rig.leaf.assign(count_, 1);
  rig.matrixNode.assign(count_, 0);
  for (size_t n = 0; n < count_; ++n)
    // An instanced node's scale sits under each instance's rotation: not a leaf either.
    if (!scene.nodes[n].children.empty() || !scene.nodes[n].instances.empty()) rig.leaf[n] = 0;
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
  // General nodes: a local transform that cannot be a uniform scale on a node with children (or a
  // sheared one anywhere), then their subtrees (the order visits parents first).
  const ScaleReport scales = analyzeScale(scene);
  rig.order = hierarchyOrder(scene);
  rig.general.assign(count_, 0);
  for (size_t i = 0; i < rig.order.nodes.size(); ++i) {
    const size_t n = size_t(rig.order.nodes[i]);
    const int parent = rig.order.parents[i];
    const bool animatedNonUniform = n < scales.nodes.size() && scales.nodes[n].animatedNonUniform;
    rig.general[n] = rig.restFlags[n].nonUniformInner || rig.restFlags[n].shear ||
                     (!rig.leaf[n] && animatedNonUniform) || (parent >= 0 && rig.general[size_t(parent)]);
  }
  for (const Skin& s : scene.skins) {
    std::vector<ScaledMotor> binds;
    bool general = false;
    for (size_t j = 0; j < s.joints.size(); ++j) {
      ConversionFlags f;
      // An inverse bind has no vertices of its own: never a residual (leaf = false).
      TRS approx;
      if (j < s.inverseBind.size()) decomposeMatrix(s.inverseBind[j], &approx);
      binds.push_back(j < s.inverseBind.size() ? fromMatrix(s.inverseBind[j], approx, false, &f)
                                               : ScaledMotor{});
      count(f, &rig.bindCounts);
      general = general || f.nonUniform || f.shear || (nodeIndexOk(scene, s.joints[j]) && rig.general[size_t(s.joints[j])]);
    }
    rig.inverseBind.push_back(std::move(binds));
    rig.generalSkin.push_back(general);
  }
  for (char g : rig.general) rig.exact = rig.exact || g;
  for (char g : rig.generalSkin) rig.exact = rig.exact || g;
  rig.animated = animatedNodes(scene);
  for (const ConversionFlags& f : rig.restFlags) count(f, &rig.restCounts);
  return rig;
}

std::vector<ScaledMotor> localPose(const Rig& rig, const std::vector<TRS>& pose,
                                   RigCounts* counts) {
  std::vector<ScaledMotor> local;
  localPose(rig, pose, local, counts);
  return local;
}

void localPose(const Rig& rig, const std::vector<TRS>& pose, std::vector<ScaledMotor>& local,
               RigCounts* counts) {
  local.resize(rig.rest.size());
  for (size_t n = 0; n < local.size(); ++n) {
    ConversionFlags f = rig.restFlags[n];
    local[n] = !rig.matrixNode[n] && n < pose.size() ? fromTRS(pose[n], rig.leaf[n], &f) : rig.rest[n];
    count(f, counts);
  }
}

std::vector<ScaledMotor> localForState(const Scene& scene, const Rig& rig, const AnimState& state,
                                       RigCounts* counts) {
  std::vector<ScaledMotor> a = localPose(rig, sampleAnimation(scene, state.anim, state.time), counts);
  if (state.anim2 < 0) return a;
  blendLocal(a, localPose(rig, sampleAnimation(scene, state.anim2, state.time2)), state.blend);
  return a;
}

std::vector<ScaledMotor> worldPose(const Scene& scene, const std::vector<ScaledMotor>& local) {
  std::vector<ScaledMotor> world;
  worldPose(hierarchyOrder(scene), local, world);
  return world;
}

// flatten: composeInto's geometric product inlined into the loop (the GLM side gets the same,
// pipelines/scene/matrix_world.cpp).
[[gnu::flatten]] void worldPose(const HierarchyOrder& order, const std::vector<ScaledMotor>& local,
                                std::vector<ScaledMotor>& world) {
  world.resize(local.size());
  for (size_t i = 0; i < order.nodes.size(); ++i) {
    const size_t n = size_t(order.nodes[i]);
    const int parent = order.parents[i];
    if (parent >= 0)
      composeInto(world[size_t(parent)], local[n], world[n]);
    else
      world[n] = local[n];
  }
}

std::vector<JointPalette> jointPalettes(const Scene& scene, const Rig& rig,
                                        const std::vector<ScaledMotor>& world,
                                        bool relativeToNode) {
  std::vector<JointPalette> out;
  jointPalettes(scene, rig, world, relativeToNode, out);
  return out;
}

[[gnu::flatten]] void jointPalettes(const Scene& scene, const Rig& rig, const std::vector<ScaledMotor>& world,
                                    bool relativeToNode, std::vector<JointPalette>& palettes,
                                    const std::vector<glm::mat4>* exactWorld) {
  forEachDrawnSkin(scene, palettes, [&](JointPalette& p, const Skin& skin, size_t n) {
    p.skin = scene.nodes[n].skin;
    p.scale = 1.0f;
    bool uniform = true;  // the joints' scales agree
    p.motors.resize(skin.joints.size() * 8);
    const Motor toNode = relativeToNode ? mk().reverse_m(world[n].motor) : Motor();
    const bool general = rig.generalSkin[size_t(p.skin)] && exactWorld;
    // Joint j's world composed with its inverse bind, and a motor stored as joint j's 8 floats.
    auto jointMotor = [&](size_t j) {
      const int jn = skin.joints[j];
      ScaledMotor m;
      composeInto(nodeIndexOk(scene, jn) ? world[size_t(jn)] : ScaledMotor{}, rig.inverseBind[size_t(p.skin)][j], m);
      return m;
    };
    auto store = [&](size_t j, const Motor& motor) {
      for (int c = 0; c < 2; ++c)
        for (int r = 0; r < 4; ++r) p.motors[8 * j + size_t(4 * c + r)] = motor[c][r];
    };
    for (size_t j = 0; j < skin.joints.size(); ++j) {
      ScaledMotor m = jointMotor(j);
      if (relativeToNode) m.motor = gpMotors(toNode, m.motor);
      if (j == 0) p.scale = m.scale;
      else if (std::fabs(m.scale - p.scale) > float(kSimilarityTolerance) * std::fabs(p.scale)) uniform = false;
      store(j, m.motor);
    }
    p.fallback = general || !uniform || !(p.scale > 0.0f);
    if (!p.fallback) return;
    // Every joint as motor + linear part, in world space: exact per joint (linear_fallback.h).
    p.linear.resize(skin.joints.size() * 24);
    for (size_t j = 0; j < skin.joints.size(); ++j) {
      const LinearTransform t = general ? linearFromAffine(jointWorld(skin, *exactWorld, j) * inverseBind(skin, j))
                                        : linearFromScaled(jointMotor(j));
      store(j, t.motor);
      packLinear(t, &p.linear[24 * j]);
    }
  });
}

void poseScene(const Scene& scene, const Rig& rig, const AnimState& state, bool relativeToNode,
               PoseWork& work, RigCounts* counts, PhaseClock& clock) {
  sampleAnimation(scene, state.anim, state.time, work.pose);
  clock.lap(&UpdatePhases::samplingMs);
  if (state.anim2 >= 0)
    localPose(rig, work.pose, work.local, counts);
  else
    animatedLocalPose(rig, work.pose, state.anim, work.local, counts);
  clock.lap(&UpdatePhases::conversionMs);
  if (state.anim2 >= 0) {
    sampleAnimation(scene, state.anim2, state.time2, work.second);
    clock.lap(&UpdatePhases::samplingMs);
    localPose(rig, work.second, work.localSecond);
    clock.lap(&UpdatePhases::conversionMs);
    blendLocal(work.local, work.localSecond, state.blend);
    clock.lap(&UpdatePhases::blendingMs);
  }
  worldPose(rig.order, work.local, work.world);
  clock.lap(&UpdatePhases::hierarchyMs);
  if (rig.exact) {  // the fallback's exact worlds: the matrix pipeline's pass, its phases lapped too
    if (work.exact.order.nodes.size() != scene.nodes.size()) prepareMatrixPose(scene, work.exact);
    poseWorldMatrices(scene, state, work.exact, clock);
  }
  jointPalettes(scene, rig, work.world, relativeToNode, work.palettes, rig.exact ? &work.exact.world : nullptr);
  clock.lap(&UpdatePhases::paletteMs);
}

}  // namespace mb::motor
