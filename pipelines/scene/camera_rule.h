// One camera rule for every pipeline: a glTF camera when asked for, otherwise automatic
// framing of the posed scene's bounds from a fixed direction. Pipelines receive the same View
// and each builds its own representation (view matrix, camera motor).
#pragma once
#include <vector>

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

// cameraIndex >= 0: use the first node (in node order) carrying glTF camera `cameraIndex`,
// posed by `state`; its yfov/znear/zfar, the viewport's aspect (an infinite or invalid zfar
// becomes znear * 1e4; orthographic cameras are rendered as perspective with the default
// yfov). When no node carries that camera, or cameraIndex < 0: frame the bounding sphere of
// every posed mesh vertex reachable from Scene::roots (skinned vertices by linear blend
// skinning, joint origins included, radius padded by 5% for other skinning methods; Bezier
// patch primitives by their control points) from a fixed direction: 30 degrees to the +X
// side of +Z and 20 degrees above, yfov 0.8, the sphere
// fully inside the frustum, near/far hugging the sphere. An empty scene gives View{}.
View frameScene(const Scene& scene, const AnimState& state, float aspect, int cameraIndex = -1);

// Nodes reachable from Scene::roots, depth first in child order, each once (malformed graphs
// with shared children or cycles cannot repeat a node). The draw order of every pipeline.
std::vector<int> nodesInDrawOrder(const Scene& scene);

// World matrix of every node for `pose` (one local TRS per node, e.g. from samplePose):
// parent world * local, where local is the authored matrix for nodes authored as one (glTF
// forbids animating those) and T*R*S otherwise. Nodes unreachable from a root get their
// chain up to their topmost ancestor. The camera rule and the GLM pipelines share it
// (pipelines/scene/matrix_world.h: the same composition into reused buffers).
std::vector<glm::mat4> worldMatrices(const Scene& scene, const std::vector<TRS>& pose);

}  // namespace mb
