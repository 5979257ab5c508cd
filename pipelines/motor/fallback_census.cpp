#include "pipelines/motor/fallback_census.h"

#include "pipelines/motor/motor_rig.h"

namespace mb::motor {

FallbackCensus restFallbackCensus(const Scene& scene) {
  FallbackCensus c;
  const Rig rig = buildRig(scene);
  PoseWork work;
  PhaseClock clock(nullptr);
  poseScene(scene, rig, AnimState{}, false, work, nullptr, clock);
  auto meshVertices = [&scene](int mesh) {
    uint64_t v = 0;
    for (const Primitive& p : scene.meshes[size_t(mesh)].primitives) v += p.positions.size();
    return v;
  };
  for (size_t n = 0; n < scene.nodes.size(); ++n) {
    c.generalNodes += rig.general[n];
    const Node& node = scene.nodes[n];
    if (!rig.general[n] || node.mesh < 0 || size_t(node.mesh) >= scene.meshes.size() || drawnSkin(scene, n)) continue;
    const int copies = node.instances.empty() ? 1 : int(node.instances.size());
    c.linearDraws += copies * int(scene.meshes[size_t(node.mesh)].primitives.size());
    c.vertices += uint64_t(copies) * meshVertices(node.mesh);
  }
  for (const JointPalette& p : work.palettes) {
    if (!p.fallback) continue;
    ++c.skinPalettes;
    c.skinJoints += int(p.motors.size() / 8);
    const int mesh = scene.nodes[size_t(p.node)].mesh;
    if (mesh >= 0 && size_t(mesh) < scene.meshes.size()) c.vertices += meshVertices(mesh);
  }
  return c;
}

}  // namespace mb::motor
