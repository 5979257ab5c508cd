#include "pipelines/matrix/matrix_pose.h"

#include "pipelines/scene/drawn_skins.h"

namespace mb::matrix {
namespace {

// The palettes of every skinned mesh node into `palettes` (storage reused). flatten: GLM's
// inverse and products inlined into the loop (the motor palette gets the same).
[[gnu::flatten]] void skinPalettes(const Scene& scene, const std::vector<glm::mat4>& world, bool worldPalette,
                                   std::vector<SkinPalette>& palettes) {
  forEachDrawnSkin(scene, palettes, [&](SkinPalette& palette, const Skin& skin, size_t n) {
    palette.matrices.resize(2 * skin.joints.size());
    const glm::mat4 toMesh = worldPalette ? glm::mat4(1.0f) : glm::inverse(world[n]);
    for (size_t j = 0; j < skin.joints.size(); ++j) {
      const glm::mat4 m = toMesh * jointWorld(skin, world, j) * inverseBind(skin, j);
      palette.matrices[2 * j] = m;
      palette.matrices[2 * j + 1] = glm::transpose(glm::inverse(m));
    }
  });
}

// normalMatrix of every node with a mesh: per-frame CPU work of the matrix form (the motor
// pipeline has none), timed with the hierarchy as the Sample Viewer's hierarchy pass does it.
[[gnu::flatten]] void drawnNormalMatrices(const Scene& scene, const std::vector<glm::mat4>& world,
                                          std::vector<glm::mat4>& normals) {
  normals.resize(world.size());
  for (size_t n = 0; n < world.size() && n < scene.nodes.size(); ++n)
    if (scene.nodes[n].mesh >= 0) normals[n] = normalMatrix(world[n]);
}

}  // namespace

glm::mat4 normalMatrix(const glm::mat4& m) {
  glm::mat4 n = glm::transpose(glm::inverse(m));
  n[3] = glm::vec4(0.0f, 0.0f, 0.0f, glm::determinant(glm::mat3(m)) < 0.0f ? -1.0f : 1.0f);
  return n;
}

Pose poseScene(const Scene& scene, const AnimState& state, bool worldPalette) {
  MatrixPoseWork work;
  prepareMatrixPose(scene, work);
  Pose pose;
  PhaseClock off(nullptr);
  poseScene(scene, state, worldPalette, work, pose, off);
  return pose;
}

void poseScene(const Scene& scene, const AnimState& state, bool worldPalette, MatrixPoseWork& work,
               Pose& pose, PhaseClock& clock) {
  poseWorldMatrices(scene, state, work, clock);
  pose.world.swap(work.world);  // the pipeline keeps the result, work keeps last frame's storage
  drawnNormalMatrices(scene, pose.world, pose.normals);
  clock.lap(&UpdatePhases::hierarchyMs);
  skinPalettes(scene, pose.world, worldPalette, pose.palettes);
  clock.lap(&UpdatePhases::paletteMs);
}

}  // namespace mb::matrix
