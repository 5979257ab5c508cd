// CPU side of the matrix pipeline: node hierarchy, animation and skin palettes with GLM
// matrices, as the glTF-Sample-Viewer computes them.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/scene/animation.h"
#include "pipelines/scene/matrix_world.h"
#include "pipelines/scene/scene.h"
#include "pipelines/update_phases.h"

namespace mb::matrix {

struct SkinPalette {
  int node = -1;  // the skinned mesh node
  // Two matrices per joint, interleaved as the shader's Joint struct reads them:
  // [2j] = inverse(mesh node world) * joint world * inverse bind (Sample Viewer; with a
  // world-space palette joint world * inverse bind), [2j+1] = its normal matrix.
  std::vector<glm::mat4> matrices;
};

struct Pose {
  std::vector<glm::mat4> world;      // per node
  std::vector<glm::mat4> normals;    // per node with a mesh: normalMatrix(world) (else untouched)
  std::vector<SkinPalette> palettes; // one per skinned mesh node reachable from the roots
};

// Poses `scene` for `state`: samplePose (shared animation sampling and blending), world
// matrices and the normal matrices of the nodes drawn (the Sample Viewer's hierarchy pass
// computes world, inverse world and normal matrix per node), then a palette for every node that has both a mesh and a skin; `worldPalette`:
// the palette without inverse(mesh node world) (SkinSpace::WorldPalette).
Pose poseScene(const Scene& scene, const AnimState& state, bool worldPalette = false);

// The same, per frame: into `pose` (its storage reused), with `work` from prepareMatrixPose,
// the phases lapped into `clock`.
void poseScene(const Scene& scene, const AnimState& state, bool worldPalette, MatrixPoseWork& work,
               Pose& pose, PhaseClock& clock);

// transpose(inverse(m)) with the [3][3] entry set to sign(det(upper 3x3 of m)): matrix.vs
// transforms directions with w = 0 and reads the handedness flip from that free entry.
glm::mat4 normalMatrix(const glm::mat4& m);

}  // namespace mb::matrix
