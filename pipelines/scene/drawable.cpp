#include "pipelines/scene/drawable.h"

#include <algorithm>
#include <map>

#include "pipelines/scene/camera_rule.h"

namespace mb {
namespace {

bool triangleHasArea(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::vec3 ab = b - a, ac = c - a, bc = c - b;
  const float longest = std::max({glm::dot(ab, ab), glm::dot(ac, ac), glm::dot(bc, bc)});
  return glm::length(glm::cross(ab, ac)) > 1e-6f * longest;
}

// A primitive a node can draw pixels of.
bool drawsPixels(const Primitive& p) {
  if (!p.patchPoints.empty()) return true;
  if (p.indices.size() < 3) return false;
  return !p.joints.empty() || !p.targets.empty() || hasAreaAtRest(p);
}

std::string skippedReasons(const Scene& scene) {
  std::map<std::string, int> reasons;
  bool onlyPointsLines = true;
  for (const SkippedPrimitive& s : scene.skipped) {
    ++reasons[s.reason];
    onlyPointsLines = onlyPointsLines && s.reason.rfind("mode ", 0) == 0;
  }
  std::string list;
  for (const auto& [why, n] : reasons) list += (list.empty() ? "" : ", ") + std::to_string(n) + " x " + why;
  return std::string(onlyPointsLines ? "only points/lines" : "every primitive is skipped") + " (" +
         std::to_string(scene.skipped.size()) + " skipped: " + list + ")";
}

}  // namespace

bool hasAreaAtRest(const Primitive& p) {
  const size_t nv = p.positions.size();
  for (size_t t = 0; t + 2 < p.indices.size(); t += 3) {
    const uint32_t i = p.indices[t], j = p.indices[t + 1], k = p.indices[t + 2];
    if (i < nv && j < nv && k < nv && triangleHasArea(p.positions[i], p.positions[j], p.positions[k])) return true;
  }
  return false;
}

std::string whyNothingDrawn(const Scene& scene) {
  if (scene.curved.space != Space::Euclidean) return "";
  bool meshOnNode = false;
  int zeroArea = 0;  // primitives with whole triangles, none of them with area
  for (int n : nodesInDrawOrder(scene)) {
    const Node& node = scene.nodes[size_t(n)];
    if (node.mesh < 0 || size_t(node.mesh) >= scene.meshes.size()) continue;
    meshOnNode = true;
    for (const Primitive& p : scene.meshes[size_t(node.mesh)].primitives) {
      if (drawsPixels(p)) return "";
      zeroArea += p.indices.size() >= 3;
    }
  }
  const std::string flat = "every triangle has zero area (" + std::to_string(zeroArea) + " primitives)";
  if (!scene.skipped.empty()) return skippedReasons(scene) + (zeroArea ? "; " + flat : "");
  if (zeroArea) return flat;
  if (scene.meshes.empty()) return "the file has no meshes (" + std::to_string(scene.nodes.size()) + " nodes)";
  if (!meshOnNode) {
    const bool outside = std::any_of(scene.nodes.begin(), scene.nodes.end(), [](const Node& n) { return n.mesh >= 0; });
    return outside ? "no node the scene reaches draws a mesh (" + std::to_string(scene.meshes.size()) +
                         " meshes, on nodes outside the scene only)"
                   : "no node draws a mesh (" + std::to_string(scene.meshes.size()) + " meshes, none on a node)";
  }
  return "no primitive drawn by a node has a whole triangle";
}

}  // namespace mb
