#include "pipelines/scene/camera_rule.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "pipelines/scene/camera/camera_framing.h"
#include "pipelines/scene/camera/camera_points.h"

namespace mb {
namespace {

// Shading's viewpoint behind an orthographic camera, in frame sizes (shadingEye).
constexpr float kOrthographicShadingDistance = 1e4f;

// Rotation part of a world matrix with scale (and reflection) removed.
glm::quat rotationOf(const glm::mat4& m) {
  glm::vec3 x = glm::normalize(glm::vec3(m[0])), y = glm::vec3(m[1]);
  y = glm::normalize(y - x * glm::dot(x, y));
  return glm::normalize(glm::quat_cast(glm::mat3(x, y, glm::cross(x, y))));
}

// An orthographic camera's half-height: |ymag|, else |xmag| / aspect, else 1 (camera_rule.h).
float orthographicHalfHeight(const Camera& cam, float aspect) {
  const float y = std::abs(cam.ymag), x = std::abs(cam.xmag);
  if (std::isfinite(y) && y > 0.0f) return y;
  if (std::isfinite(x) && x > 0.0f) return x / aspect;
  return 1.0f;
}

// `view` (eye, orientation, aspect set) given the projection of glTF camera `cam`.
void setProjection(const Camera& cam, View& view) {
  if (!cam.perspective) {
    view.orthographic = true;
    view.ymag = orthographicHalfHeight(cam, view.aspect);
    view.znear = cam.znear > 0.0f ? cam.znear : 0.0f;
    view.zfar = std::isfinite(cam.zfar) && cam.zfar > view.znear ? cam.zfar : view.znear + 1e4f * view.ymag;
    return;
  }
  if (cam.yfov > 0.0f && cam.yfov < 3.1f) view.yfov = cam.yfov;
  view.znear = cam.znear > 0.0f ? cam.znear : 0.01f;
  view.zfar = std::isfinite(cam.zfar) && cam.zfar > view.znear ? cam.zfar : view.znear * 1e4f;
}

}  // namespace

std::vector<int> nodesInDrawOrder(const Scene& scene) {
  std::vector<int> order;
  std::vector<int> stack(scene.roots.rbegin(), scene.roots.rend());
  std::vector<bool> seen(scene.nodes.size(), false);
  while (!stack.empty()) {
    int n = stack.back();
    stack.pop_back();
    if (n < 0 || size_t(n) >= scene.nodes.size() || seen[size_t(n)]) continue;
    seen[size_t(n)] = true;
    order.push_back(n);
    const std::vector<int>& children = scene.nodes[size_t(n)].children;
    stack.insert(stack.end(), children.rbegin(), children.rend());
  }
  return order;
}

View frameScene(const Scene& scene, const AnimState& state, float aspect, int cameraIndex) {
  View view;
  view.aspect = aspect > 0.0f ? aspect : 1.0f;
  std::vector<glm::mat4> world = worldMatrices(scene, samplePose(scene, state));

  if (cameraIndex >= 0 && size_t(cameraIndex) < scene.cameras.size()) {
    for (size_t n = 0; n < scene.nodes.size(); ++n) {
      if (scene.nodes[n].camera != cameraIndex) continue;
      view.eye = glm::vec3(world[n][3]);
      view.orientation = rotationOf(world[n]);
      setProjection(scene.cameras[size_t(cameraIndex)], view);
      return view;
    }
  }

  const PosedPoints points = posedPoints(scene, world, sampleMorphWeights(scene, state));
  if (points.empty()) return view;
  return scene.framing == Framing::BoundingSphere ? sphereFraming(points, view.aspect)
                                                  : fitFraming(points, view.aspect);
}

glm::mat4 projectionMatrix(const View& view) {
  if (!view.orthographic) return glm::perspective(view.yfov, view.aspect, view.znear, view.zfar);
  const float halfWidth = view.ymag * view.aspect;
  return glm::ortho(-halfWidth, halfWidth, -view.ymag, view.ymag, view.znear, view.zfar);
}

glm::vec3 shadingEye(const View& view) {
  if (!view.orthographic) return view.eye;
  const float behind = kOrthographicShadingDistance * view.ymag * std::max(1.0f, view.aspect);
  return view.eye + view.orientation * glm::vec3(0.0f, 0.0f, behind);
}

bool hasOrthographicCamera(const Scene& scene) {
  return std::any_of(scene.cameras.begin(), scene.cameras.end(), [](const Camera& c) { return !c.perspective; });
}

}  // namespace mb
