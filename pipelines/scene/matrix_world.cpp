#include "pipelines/scene/matrix_world.h"

#include "pipelines/scene/camera_rule.h"
#include "pipelines/scene/transform.h"

namespace mb {

void prepareMatrixPose(const Scene& scene, MatrixPoseWork& work) {
  work.order = hierarchyOrder(scene);
  work.animated = animatedNodes(scene);
  std::vector<TRS> rest;
  sampleAnimation(scene, -1, 0.0f, rest);
  localMatrices(scene, rest, work.restLocal);
}

// flatten: GLM's operators inlined into the loop (the motor side gets the same, motor_rig.cpp).
[[gnu::flatten]] void localMatrices(const Scene& scene, const std::vector<TRS>& pose,
                                    std::vector<glm::mat4>& local) {
  local.resize(scene.nodes.size());
  for (size_t n = 0; n < local.size(); ++n) {
    const Node& node = scene.nodes[n];
    local[n] = node.hasMatrix ? node.matrix : trsMatrix(n < pose.size() ? pose[n] : node.local);
  }
}

namespace {

// localMatrices for one unblended animation: rest matrices, the driven nodes converted.
[[gnu::flatten]] void animatedLocalMatrices(const Scene& scene, const std::vector<TRS>& pose,
                                            const MatrixPoseWork& work, int anim, std::vector<glm::mat4>& local) {
  local = work.restLocal;
  if (anim < 0 || size_t(anim) >= work.animated.size()) return;
  for (int n : work.animated[size_t(anim)]) {
    const Node& node = scene.nodes[size_t(n)];
    local[size_t(n)] = node.hasMatrix ? node.matrix : trsMatrix(pose[size_t(n)]);
  }
}

}  // namespace

[[gnu::flatten]] void composeWorld(const HierarchyOrder& order, const std::vector<glm::mat4>& local,
                                   std::vector<glm::mat4>& world) {
  world.resize(local.size());
  for (size_t i = 0; i < order.nodes.size(); ++i) {
    const size_t n = size_t(order.nodes[i]);
    const int parent = order.parents[i];
    world[n] = parent >= 0 ? world[size_t(parent)] * local[n] : local[n];
  }
}

void poseWorldMatrices(const Scene& scene, const AnimState& state, MatrixPoseWork& work, PhaseClock& clock) {
  sampleAnimation(scene, state.anim, state.time, work.pose);
  if (state.anim2 >= 0) {
    sampleAnimation(scene, state.anim2, state.time2, work.second);
    clock.lap(&UpdatePhases::samplingMs);
    blendPoses(work.pose, work.second, state.blend, work.pose);
    clock.lap(&UpdatePhases::blendingMs);
  } else {
    clock.lap(&UpdatePhases::samplingMs);
  }
  if (state.anim2 >= 0 || work.restLocal.size() != scene.nodes.size())
    localMatrices(scene, work.pose, work.local);
  else
    animatedLocalMatrices(scene, work.pose, work, state.anim, work.local);
  clock.lap(&UpdatePhases::conversionMs);
  composeWorld(work.order, work.local, work.world);
  clock.lap(&UpdatePhases::hierarchyMs);
}

std::vector<glm::mat4> worldMatrices(const Scene& scene, const std::vector<TRS>& pose) {
  std::vector<glm::mat4> local, world;
  localMatrices(scene, pose, local);
  composeWorld(hierarchyOrder(scene), local, world);
  return world;
}

}  // namespace mb
