#include "pipelines/scene/matrix_world.h"

#include "pipelines/scene/camera_rule.h"
#include "pipelines/scene/transform.h"

namespace mb {

void prepareMatrixPose(const Scene& scene, MatrixPoseWork& work) { work.order = hierarchyOrder(scene); }

// flatten: GLM's operators inlined into the loop (the motor side gets the same, motor_rig.cpp).
[[gnu::flatten]] void localMatrices(const Scene& scene, const std::vector<TRS>& pose,
                                    std::vector<glm::mat4>& local) {
  local.resize(scene.nodes.size());
  for (size_t n = 0; n < local.size(); ++n) {
    const Node& node = scene.nodes[n];
    local[n] = node.hasMatrix ? node.matrix : trsMatrix(n < pose.size() ? pose[n] : node.local);
  }
}

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
  localMatrices(scene, work.pose, work.local);
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
