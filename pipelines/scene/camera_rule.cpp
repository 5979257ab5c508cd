#include "pipelines/scene/camera_rule.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "pipelines/scene/instancing.h"
#include "pipelines/scene/morph.h"
#include "pipelines/scene/transform.h"


namespace mb {
namespace {

constexpr float kAutoYfov = 0.8f;
constexpr float kAutoYaw = glm::radians(30.0f);    // towards +X
constexpr float kAutoPitch = glm::radians(20.0f);  // camera above, looking down
constexpr float kSkinPadding = 1.05f;              // other skinning methods may bulge out
// Points farther out than this do not frame the camera: the squared length of the bounds'
// diagonal (glm::length) overflows a float from about 1.8e19 per coordinate (fuzz finding F14).
constexpr float kMaxFramedCoordinate = 1e18f;

struct Bounds {
  glm::vec3 lo{std::numeric_limits<float>::max()};
  glm::vec3 hi{-std::numeric_limits<float>::max()};
  bool padded = false;
  void add(glm::vec3 p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return;
    if (glm::any(glm::greaterThan(glm::abs(p), glm::vec3(kMaxFramedCoordinate)))) return;
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  bool empty() const { return lo.x > hi.x; }
};

// Adds the posed vertices of the mesh on node `n` (morphed by the node's `weights`).
void addMesh(const Scene& scene, const std::vector<glm::mat4>& world, const std::vector<float>& weights, int n,
             Bounds& b) {
  const Node& node = scene.nodes[size_t(n)];
  if (node.mesh < 0 || size_t(node.mesh) >= scene.meshes.size()) return;
  if (!node.instances.empty()) {  // never skinned: the corners of the morphed mesh's bounds per instance
    const MeshBounds m = meshBounds(scene.meshes[size_t(node.mesh)], weights);
    if (m.empty()) return;
    for (const TRS& instance : node.instances) {
      const glm::mat4 toWorld = world[size_t(n)] * trsMatrix(instance);
      for (int c = 0; c < 8; ++c)
        b.add(glm::vec3(toWorld * glm::vec4(c & 1 ? m.hi.x : m.lo.x, c & 2 ? m.hi.y : m.lo.y, c & 4 ? m.hi.z : m.lo.z, 1.0f)));
    }
    return;
  }
  const Skin* skin = node.skin >= 0 && size_t(node.skin) < scene.skins.size()
                         ? &scene.skins[size_t(node.skin)] : nullptr;
  std::vector<glm::mat4> joints;  // world-space skinning matrices (glTF: node transform unused)
  if (skin) {
    for (size_t j = 0; j < skin->joints.size(); ++j) {
      int jn = skin->joints[j];
      glm::mat4 jw = jn >= 0 && size_t(jn) < world.size() ? world[size_t(jn)] : glm::mat4(1.0f);
      joints.push_back(jw * (j < skin->inverseBind.size() ? skin->inverseBind[j] : glm::mat4(1.0f)));
      b.add(glm::vec3(jw[3]));
    }
    b.padded = true;
  }
  for (const Primitive& p : scene.meshes[size_t(node.mesh)].primitives) {
    // Bezier patches lie inside the convex hull of their control points: the points bound them.
    for (const glm::vec3& c : p.patchPoints) b.add(glm::vec3(world[size_t(n)] * glm::vec4(c, 1.0f)));
    bool skinned = skin && !joints.empty() && p.joints.size() == p.positions.size() &&
                   p.weights.size() == p.positions.size();
    for (size_t v = 0; v < p.positions.size(); ++v) {
      glm::vec4 q(morphedPosition(p, v, weights), 1.0f);
      if (!skinned) {
        b.add(glm::vec3(world[size_t(n)] * q));
        continue;
      }
      glm::mat4 m(0.0f);
      for (int k = 0; k < 4; ++k)
        if (p.weights[v][k] != 0.0f && p.joints[v][k] < joints.size())
          m += p.weights[v][k] * joints[p.joints[v][k]];
      b.add(glm::vec3(m * q));
    }
  }
}

Bounds sceneBounds(const Scene& scene, const std::vector<glm::mat4>& world,
                   const std::vector<std::vector<float>>& weights) {
  Bounds b;
  for (int n : nodesInDrawOrder(scene)) addMesh(scene, world, weights[size_t(n)], n, b);
  return b;
}

// Rotation part of a world matrix with scale (and reflection) removed.
glm::quat rotationOf(const glm::mat4& m) {
  glm::vec3 x = glm::normalize(glm::vec3(m[0])), y = glm::vec3(m[1]);
  y = glm::normalize(y - x * glm::dot(x, y));
  return glm::normalize(glm::quat_cast(glm::mat3(x, y, glm::cross(x, y))));
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
      const Camera& cam = scene.cameras[size_t(cameraIndex)];
      view.eye = glm::vec3(world[n][3]);
      view.orientation = rotationOf(world[n]);
      if (cam.perspective && cam.yfov > 0.0f && cam.yfov < 3.1f) view.yfov = cam.yfov;
      view.znear = cam.znear > 0.0f ? cam.znear : 0.01f;
      view.zfar = std::isfinite(cam.zfar) && cam.zfar > view.znear ? cam.zfar
                                                                   : view.znear * 1e4f;
      return view;
    }
  }

  Bounds b = sceneBounds(scene, world, sampleMorphWeights(scene, state));
  if (b.empty()) return view;
  glm::vec3 center = 0.5f * (b.lo + b.hi);
  float radius = 0.5f * glm::length(b.hi - b.lo) * (b.padded ? kSkinPadding : 1.0f);
  if (!(radius > 1e-6f)) radius = 1.0f;
  view.yfov = kAutoYfov;
  float halfX = std::atan(std::tan(0.5f * kAutoYfov) * view.aspect);
  float half = std::min(0.5f * kAutoYfov, halfX);
  float distance = radius / std::sin(half);
  view.orientation = glm::angleAxis(kAutoYaw, glm::vec3(0, 1, 0)) *
                     glm::angleAxis(-kAutoPitch, glm::vec3(1, 0, 0));
  view.eye = center + view.orientation * glm::vec3(0.0f, 0.0f, distance);
  view.znear = std::max(0.9f * (distance - radius), 1e-4f * distance);
  view.zfar = 1.1f * (distance + radius);
  return view;
}

}  // namespace mb
