#include "pipelines/scene/drawable.h"

#include <map>

namespace mb {

std::string whyNothingDrawn(const Scene& scene) {
  if (scene.curved.space != Space::Euclidean) return "";
  bool meshOnNode = false;
  for (const Node& n : scene.nodes) {
    if (n.mesh < 0 || size_t(n.mesh) >= scene.meshes.size()) continue;
    meshOnNode = true;
    for (const Primitive& p : scene.meshes[size_t(n.mesh)].primitives)
      if (p.indices.size() >= 3 || !p.patchPoints.empty()) return "";
  }
  if (!scene.skipped.empty()) {
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
  if (scene.meshes.empty()) return "the file has no meshes (" + std::to_string(scene.nodes.size()) + " nodes)";
  if (!meshOnNode) return "no node draws a mesh (" + std::to_string(scene.meshes.size()) + " meshes, none on a node)";
  return "no primitive drawn by a node has a whole triangle";
}

}  // namespace mb
