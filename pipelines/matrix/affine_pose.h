// The CPU side of the affine pipelines: world transforms per node and joint palettes as GLSL
// mat4x3 (the affine 3x4 part of a transform, 12 floats), and the GLM poser of `affine` and
// `qtangent` (pipelines/hybrid poses the same struct from motors).
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/scene/animation.h"
#include "pipelines/scene/matrix_world.h"
#include "pipelines/scene/scene.h"
#include "pipelines/update_phases.h"

namespace mb::affine {

struct Palette {
  int node = -1;                    // the skinned mesh node
  std::vector<glm::mat4x3> joints;  // joint world * inverse bind (glTF: no mesh-node transform)
};

struct Pose {
  std::vector<glm::mat4x3> world;  // per node
  std::vector<glm::mat3> normals;  // per node with a mesh: normalMatrix(world) (else untouched)
  std::vector<float> mirrors;      // per node with a mesh: mirror(world)
  std::vector<Palette> palettes;   // one per node with a mesh and a skin, in node order
};

// GLM: samplePose (shared sampling and blending), world matrices, palettes, into `pose`
// (storage reused), with `work` from prepareMatrixPose; the mat4 -> mat4x3 copy of the world
// matrices laps as conversion.
void poseScene(const Scene& scene, const AnimState& state, MatrixPoseWork& work, Pose& pose, PhaseClock& clock);

// The normal matrix of an affine transform's linear part: transpose(inverse(m)).
glm::mat3 normalMatrix(const glm::mat4x3& m);

// sign(det(linear part)): -1 for a mirroring transform, else +1.
float mirror(const glm::mat4x3& m);

// pose.normals and pose.mirrors of every node with a mesh, from pose.world: per-frame CPU work
// of the matrix forms (the Sample Viewer's hierarchy pass computes the normal matrix per node),
// lapped by the caller as hierarchy time.
void drawnNormalMatrices(const Scene& scene, Pose& pose);

}  // namespace mb::affine
