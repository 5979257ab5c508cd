// The GLM pipelines' per-frame node pass (matrix, affine, qtangent): sampled TRS -> local
// matrices -> world matrices in hierarchy order, into buffers reused from frame to frame.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/scene/animation.h"
#include "pipelines/scene/hierarchy.h"
#include "pipelines/scene/scene.h"
#include "pipelines/update_phases.h"

namespace mb {

// What one GLM pipeline keeps between updates.
struct MatrixPoseWork {
  HierarchyOrder order;              // hierarchyOrder(scene), set by prepareMatrixPose
  std::vector<TRS> pose, second;     // sampled TRS (second: the animation blended in)
  std::vector<glm::mat4> restLocal;  // per node: localMatrices of the rest pose
  std::vector<std::vector<int>> animated;  // animatedNodes(scene)
  std::vector<glm::mat4> local;      // per node
  std::vector<glm::mat4> world;      // per node: the result
};

void prepareMatrixPose(const Scene& scene, MatrixPoseWork& work);

// local[n] = the authored matrix of a node authored as one (glTF forbids animating those),
// else T*R*S of pose[n] (the node's rest TRS past pose's end).
void localMatrices(const Scene& scene, const std::vector<TRS>& pose, std::vector<glm::mat4>& local);

// world[n] = world[parent] * local[n] in `order` (local[n] where the node starts a chain).
void composeWorld(const HierarchyOrder& order, const std::vector<glm::mat4>& local,
                  std::vector<glm::mat4>& world);

// work.world for `state`: sampleAnimation (and blendPoses when the state blends), then
// localMatrices (unblended: the rest matrices, converting only the nodes the animation drives;
// the same values) and composeWorld; the phases lap into `clock`.
void poseWorldMatrices(const Scene& scene, const AnimState& state, MatrixPoseWork& work, PhaseClock& clock);

// The two factors of every matrix pipeline's palette entry, joint world x inverse bind: the
// identity for a joint index out of range and for a missing inverse bind (glTF's default).
inline glm::mat4 jointWorld(const Skin& skin, const std::vector<glm::mat4>& world, size_t j) {
  const int jn = skin.joints[j];
  return jn >= 0 && size_t(jn) < world.size() ? world[size_t(jn)] : glm::mat4(1.0f);
}
inline glm::mat4 inverseBind(const Skin& skin, size_t j) {
  return j < skin.inverseBind.size() ? skin.inverseBind[j] : glm::mat4(1.0f);
}

}  // namespace mb
