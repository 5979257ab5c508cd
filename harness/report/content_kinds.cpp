#include "harness/report/content_kinds.h"

#include <algorithm>
#include <map>
#include <tuple>

#include "pipelines/gl/gpu_geometry.h"
#include "pipelines/gl/scene_textures.h"

namespace mb::report {

using json = nlohmann::json;

ContentKind contentKindOf(const Scene& scene, const Node& node, const Primitive& p) {
  ContentKind k;
  k.normalMapped = gl::normalMapped(scene, p);
  k.deformation = node.skin >= 0 && !p.joints.empty() ? "skinned" : !p.targets.empty() ? "morph" : "rigid";
  k.instanced = !node.instances.empty();
  return k;
}

std::string materialKey(const ContentKind& k) { return k.normalMapped ? "normalMapped" : "notNormalMapped"; }

json contentKindsJson(const Scene& scene) {
  std::map<std::tuple<bool, std::string, bool>, std::pair<long long, long long>> cells;  // vertices, primitives
  for (const gl::DrawItem& d : gl::buildDrawList(scene)) {
    const Node& node = scene.nodes[size_t(d.node)];
    const Primitive& p = scene.meshes[size_t(d.mesh)].primitives[size_t(d.primitive)];
    if (!p.patchPoints.empty()) continue;
    const ContentKind k = contentKindOf(scene, node, p);
    const long long times = std::max<long long>(1, (long long)node.instances.size());
    auto& c = cells[{k.normalMapped, k.deformation, k.instanced}];
    c.first += times * (long long)p.positions.size();
    c.second += times;
  }
  json out = json::array();
  for (const auto& [key, c] : cells)
    out.push_back({{"normalMapped", std::get<0>(key)}, {"deformation", std::get<1>(key)},
                   {"instanced", std::get<2>(key)}, {"vertices", c.first}, {"primitives", c.second}});
  return {{"cells", out}};
}

}  // namespace mb::report
