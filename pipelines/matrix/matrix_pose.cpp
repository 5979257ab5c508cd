#include "pipelines/matrix/matrix_pose.h"

#include "pipelines/scene/camera_rule.h"

namespace mb::matrix {

glm::mat4 normalMatrix(const glm::mat4& m) {
  glm::mat4 n = glm::transpose(glm::inverse(m));
  n[3] = glm::vec4(0.0f, 0.0f, 0.0f, glm::determinant(glm::mat3(m)) < 0.0f ? -1.0f : 1.0f);
  return n;
}

Pose poseScene(const Scene& scene, const AnimState& state, bool worldPalette) {
  PhaseClock off(nullptr);
  return poseScene(scene, state, worldPalette, off);
}

Pose poseScene(const Scene& scene, const AnimState& state, bool worldPalette, PhaseClock& clock) {
  Pose pose;
  std::vector<TRS> trs = sampleAnimation(scene, state.anim, state.time);  // samplePose, lapped
  clock.lap(&UpdatePhases::samplingMs);
  if (state.anim2 >= 0) {
    const std::vector<TRS> second = sampleAnimation(scene, state.anim2, state.time2);
    clock.lap(&UpdatePhases::samplingMs);
    trs = blendPoses(trs, second, state.blend);
    clock.lap(&UpdatePhases::blendingMs);
  }
  pose.world = worldMatrices(scene, trs);
  clock.lap(&UpdatePhases::hierarchyMs);
  for (size_t n = 0; n < scene.nodes.size(); ++n) {
    const Node& node = scene.nodes[n];
    if (node.mesh < 0 || node.skin < 0 || size_t(node.skin) >= scene.skins.size()) continue;
    const Skin& skin = scene.skins[size_t(node.skin)];
    SkinPalette palette;
    palette.node = int(n);
    const glm::mat4 toMesh = worldPalette ? glm::mat4(1.0f) : glm::inverse(pose.world[n]);
    for (size_t j = 0; j < skin.joints.size(); ++j) {
      int jn = skin.joints[j];
      glm::mat4 joint = jn >= 0 && size_t(jn) < pose.world.size() ? pose.world[size_t(jn)]
                                                                  : glm::mat4(1.0f);
      glm::mat4 bind = j < skin.inverseBind.size() ? skin.inverseBind[j] : glm::mat4(1.0f);
      glm::mat4 m = toMesh * joint * bind;
      palette.matrices.push_back(m);
      palette.matrices.push_back(glm::transpose(glm::inverse(m)));
    }
    pose.palettes.push_back(std::move(palette));
  }
  clock.lap(&UpdatePhases::paletteMs);
  return pose;
}

}  // namespace mb::matrix
