// One camera rule for every pipeline: a glTF camera when asked for, otherwise automatic
// framing of the posed scene's bounds from a fixed direction. Pipelines receive the same View
// and each builds its own representation (view matrix, camera motor).
#pragma once
#include "pipelines/scene/animation.h"
#include "pipelines/scene/scene.h"

namespace mb {

struct View {
  glm::vec3 eye{0.0f, 0.0f, 5.0f};           // camera position, world space
  glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f};  // camera-to-world rotation; camera looks down -Z
  float yfov = 0.8f;     // vertical field of view, radians
  float aspect = 1.0f;   // width / height
  float znear = 0.05f, zfar = 100.0f;
};

// cameraIndex >= 0: use the node carrying glTF camera `cameraIndex` (posed by `state`).
// Otherwise frame the bounds of every posed mesh from a fixed direction.
View frameScene(const Scene& scene, const AnimState& state, float aspect, int cameraIndex = -1);

}  // namespace mb
