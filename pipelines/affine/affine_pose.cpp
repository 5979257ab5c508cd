#include "pipelines/affine/affine_pose.h"

#include "pipelines/scene/camera_rule.h"

namespace mb::affine {

glm::mat3 normalMatrix(const glm::mat4x3& m) { return glm::transpose(glm::inverse(glm::mat3(m))); }

float mirror(const glm::mat4x3& m) { return glm::determinant(glm::mat3(m)) < 0.0f ? -1.0f : 1.0f; }

Pose poseScene(const Scene& scene, const AnimState& state) {
  PhaseClock off(nullptr);
  return poseScene(scene, state, off);
}

Pose poseScene(const Scene& scene, const AnimState& state, PhaseClock& clock) {
  std::vector<TRS> trs = sampleAnimation(scene, state.anim, state.time);  // samplePose, lapped
  clock.lap(&UpdatePhases::samplingMs);
  if (state.anim2 >= 0) {
    const std::vector<TRS> second = sampleAnimation(scene, state.anim2, state.time2);
    clock.lap(&UpdatePhases::samplingMs);
    trs = blendPoses(trs, second, state.blend);
    clock.lap(&UpdatePhases::blendingMs);
  }
  const std::vector<glm::mat4> world = worldMatrices(scene, trs);
  clock.lap(&UpdatePhases::hierarchyMs);
  Pose pose;
  pose.world.assign(world.begin(), world.end());
  clock.lap(&UpdatePhases::conversionMs);
  for (size_t n = 0; n < scene.nodes.size(); ++n) {
    const Node& node = scene.nodes[n];
    if (node.mesh < 0 || node.skin < 0 || size_t(node.skin) >= scene.skins.size()) continue;
    const Skin& skin = scene.skins[size_t(node.skin)];
    Palette palette;
    palette.node = int(n);
    palette.joints.reserve(skin.joints.size());
    for (size_t j = 0; j < skin.joints.size(); ++j) {
      const int jn = skin.joints[j];
      const glm::mat4 joint = jn >= 0 && size_t(jn) < world.size() ? world[size_t(jn)] : glm::mat4(1.0f);
      const glm::mat4 bind = j < skin.inverseBind.size() ? skin.inverseBind[j] : glm::mat4(1.0f);
      palette.joints.emplace_back(joint * bind);
    }
    pose.palettes.push_back(std::move(palette));
  }
  clock.lap(&UpdatePhases::paletteMs);
  return pose;
}

}  // namespace mb::affine
