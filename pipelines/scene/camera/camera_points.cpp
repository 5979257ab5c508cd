#include "pipelines/scene/camera/camera_points.h"

#include <cmath>

#include "pipelines/scene/camera_rule.h"
#include "pipelines/scene/instancing.h"
#include "pipelines/scene/morph.h"
#include "pipelines/scene/transform.h"

namespace mb {
namespace {

// Points farther out than this do not frame the camera: the squared length of the bounds'
// diagonal (glm::length) overflows a float from about 1.8e19 per coordinate.
constexpr float kMaxFramedCoordinate = 1e18f;

bool framable(glm::vec3 p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) &&
         !glm::any(glm::greaterThan(glm::abs(p), glm::vec3(kMaxFramedCoordinate)));
}

void addPoint(PosedPoints& out, glm::vec3 p) {
  if (!framable(p)) return;
  if (out.points.empty()) out.lo = out.hi = p;
  out.lo = glm::min(out.lo, p);
  out.hi = glm::max(out.hi, p);
  out.points.push_back(p);
}

// The triangles of `p` posed at `posed` (one entry per vertex), each cross product times
// `winding` (-1 for a mirrored node: its front faces are wound the other way).
void addFrontArea(const Primitive& p, const std::vector<glm::vec3>& posed, double winding, PosedPoints& out) {
  for (size_t t = 0; t + 2 < p.indices.size(); t += 3) {
    const uint32_t i = p.indices[t], j = p.indices[t + 1], k = p.indices[t + 2];
    if (i >= posed.size() || j >= posed.size() || k >= posed.size()) continue;
    if (!framable(posed[i]) || !framable(posed[j]) || !framable(posed[k])) continue;
    const glm::dvec3 a(posed[i]), b(posed[j]), c(posed[k]);
    const glm::dvec3 area = glm::cross(b - a, c - a);
    out.frontArea += winding * area;
    out.absoluteArea += glm::abs(area);
  }
}

void addInstances(const Scene& scene, const glm::mat4& world, const std::vector<float>& weights, const Node& node,
                  PosedPoints& out) {
  const MeshBounds m = meshBounds(scene.meshes[size_t(node.mesh)], weights);
  if (m.empty()) return;
  for (const TRS& instance : node.instances) {
    const glm::mat4 toWorld = world * trsMatrix(instance);
    for (int c = 0; c < 8; ++c)
      addPoint(out, glm::vec3(toWorld * glm::vec4(c & 1 ? m.hi.x : m.lo.x, c & 2 ? m.hi.y : m.lo.y,
                                                  c & 4 ? m.hi.z : m.lo.z, 1.0f)));
  }
}

// World-space skinning matrices of `skin` (glTF: the mesh node's transform is unused); the
// joint origins are framed too.
std::vector<glm::mat4> jointMatrices(const Skin& skin, const std::vector<glm::mat4>& world, PosedPoints& out) {
  std::vector<glm::mat4> joints;
  for (size_t j = 0; j < skin.joints.size(); ++j) {
    const int jn = skin.joints[j];
    const glm::mat4 jw = jn >= 0 && size_t(jn) < world.size() ? world[size_t(jn)] : glm::mat4(1.0f);
    joints.push_back(jw * (j < skin.inverseBind.size() ? skin.inverseBind[j] : glm::mat4(1.0f)));
    addPoint(out, glm::vec3(jw[3]));
  }
  out.skinned = true;
  return joints;
}

// The posed vertices of the mesh on node `n` (morphed by the node's `weights`).
void addMesh(const Scene& scene, const std::vector<glm::mat4>& world, const std::vector<float>& weights, int n,
             PosedPoints& out) {
  const Node& node = scene.nodes[size_t(n)];
  if (node.mesh < 0 || size_t(node.mesh) >= scene.meshes.size()) return;
  const glm::mat4& nodeWorld = world[size_t(n)];
  if (!node.instances.empty()) return addInstances(scene, nodeWorld, weights, node, out);  // never skinned
  const Skin* skin =
      node.skin >= 0 && size_t(node.skin) < scene.skins.size() ? &scene.skins[size_t(node.skin)] : nullptr;
  const std::vector<glm::mat4> joints = skin ? jointMatrices(*skin, world, out) : std::vector<glm::mat4>{};
  const double mirrored = glm::determinant(glm::mat3(nodeWorld)) < 0.0f ? -1.0 : 1.0;
  std::vector<glm::vec3> posed;
  for (const Primitive& p : scene.meshes[size_t(node.mesh)].primitives) {
    // Bezier patches lie inside the convex hull of their control points: the points bound them.
    for (const glm::vec3& c : p.patchPoints) addPoint(out, glm::vec3(nodeWorld * glm::vec4(c, 1.0f)));
    const bool skinned =
        !joints.empty() && p.joints.size() == p.positions.size() && p.weights.size() == p.positions.size();
    posed.resize(p.positions.size());
    for (size_t v = 0; v < p.positions.size(); ++v) {
      const glm::vec4 q(morphedPosition(p, v, weights), 1.0f);
      glm::mat4 m = nodeWorld;
      if (skinned) {
        m = glm::mat4(0.0f);
        for (int k = 0; k < 4; ++k)
          if (p.weights[v][k] != 0.0f && p.joints[v][k] < joints.size()) m += p.weights[v][k] * joints[p.joints[v][k]];
      }
      posed[v] = glm::vec3(m * q);
      addPoint(out, posed[v]);
    }
    addFrontArea(p, posed, skinned ? 1.0 : mirrored, out);
  }
}

}  // namespace

PosedPoints posedPoints(const Scene& scene, const std::vector<glm::mat4>& world,
                        const std::vector<std::vector<float>>& weights) {
  PosedPoints out;
  for (int n : nodesInDrawOrder(scene)) addMesh(scene, world, weights[size_t(n)], n, out);
  return out;
}

}  // namespace mb
