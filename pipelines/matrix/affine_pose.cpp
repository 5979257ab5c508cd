#include "pipelines/matrix/affine_pose.h"

#include "pipelines/scene/drawn_skins.h"

namespace mb::affine {

glm::mat3 normalMatrix(const glm::mat4x3& m) { return glm::transpose(glm::inverse(glm::mat3(m))); }

float mirror(const glm::mat4x3& m) { return glm::determinant(glm::mat3(m)) < 0.0f ? -1.0f : 1.0f; }

[[gnu::flatten]] void drawnNormalMatrices(const Scene& scene, Pose& pose) {
  pose.normals.resize(pose.world.size());
  pose.mirrors.resize(pose.world.size(), 1.0f);
  for (size_t n = 0; n < pose.world.size() && n < scene.nodes.size(); ++n)
    if (scene.nodes[n].mesh >= 0) {
      pose.normals[n] = normalMatrix(pose.world[n]);
      pose.mirrors[n] = mirror(pose.world[n]);
    }
}

namespace {

// flatten: GLM's products inlined into the loop, as on the other pipelines.
[[gnu::flatten]] void skinPalettes(const Scene& scene, const std::vector<glm::mat4>& world,
                                   std::vector<Palette>& palettes) {
  forEachDrawnSkin(scene, palettes, [&](Palette& palette, const Skin& skin, size_t) {
    palette.joints.resize(skin.joints.size());
    for (size_t j = 0; j < skin.joints.size(); ++j)
      palette.joints[j] = glm::mat4x3(jointWorld(skin, world, j) * inverseBind(skin, j));
  });
}

}  // namespace

void poseScene(const Scene& scene, const AnimState& state, MatrixPoseWork& work, Pose& pose, PhaseClock& clock) {
  poseWorldMatrices(scene, state, work, clock);
  pose.world.assign(work.world.begin(), work.world.end());
  clock.lap(&UpdatePhases::conversionMs);
  skinPalettes(scene, work.world, pose.palettes);
  clock.lap(&UpdatePhases::paletteMs);
}

}  // namespace mb::affine
