// Skinning claims (issue 18): motor blending, like dual-quaternion skinning, keeps the mesh's
// volume where linear blend skinning (LBS) pinches. Measured on the built-in skinned_tube's
// "candy_wrapper" animation (the middle joint turns 180 degrees about the tube's axis): each
// ring of the tube is skinned on the CPU both ways from the pipelines' own palettes (matrix
// world-space palette, LBS of the joint matrices; motor palette, motorBlendJoints of
// shaders/motor_transform.glsl), and its radius (mean distance of its vertices from their
// centroid) is compared with the rest pose's, over 64 times of the animation.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "harness/claims/claims_sources.h"
#include "pipelines/matrix/matrix_pose.h"
#include "pipelines/motor/motor_rig.h"
#include "pipelines/scene/loader.h"

namespace mb::claims {
namespace {

struct RingRadii {
  double lbs = 1e30, motor = 1e30;  // smallest ring radius / rest radius over rings and times
  float lbsTime = 0, motorTime = 0;
};

// Mean distance of each ring's vertices (grouped by key) from the ring's centroid.
std::map<int, double> radii(const std::vector<glm::vec3>& p, const std::vector<int>& ring) {
  std::map<int, glm::dvec3> sum;
  std::map<int, int> n;
  for (size_t i = 0; i < p.size(); ++i) sum[ring[i]] += glm::dvec3(p[i]), ++n[ring[i]];
  std::map<int, double> r;
  for (size_t i = 0; i < p.size(); ++i)
    r[ring[i]] += glm::length(glm::dvec3(p[i]) - sum[ring[i]] / double(n[ring[i]])) / n[ring[i]];
  return r;
}

std::string num(double v, const char* f = "%.3f") {
  char b[32];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

}  // namespace

std::vector<Claim> skinningClaims() {
  Claim c{"skinning_volume", "Skinning",
          "motor skinning (the dual-quaternion pattern) keeps volume where linear blend skinning pinches"};
  c.paper = "implied (the dual-quaternion skinning pattern)";
  c.paperValue = nullptr;
  c.method = "built-in skinned_tube, animation candy_wrapper at 64 times over its duration; every ring of the tube "
             "skinned on the CPU from the pipelines' palettes: LBS of the matrix pipeline's world-space joint "
             "matrices, and motorBlendJoints + the skin's uniform scale of the motor pipeline's joint motors; ring "
             "radius = mean distance of the ring's vertices from their centroid, divided by the rest radius; the "
             "smallest over rings and times. Verdict: reproduced when the motor keeps >= 95 % of the radius and "
             "LBS does not.";
  auto scene = loadScene("skinned_tube");
  int anim = -1;
  if (scene)
    for (size_t i = 0; i < scene->animations.size(); ++i)
      if (scene->animations[i].name == "candy_wrapper") anim = int(i);
  const Mesh* mesh = nullptr;
  int node = -1;
  if (scene)
    for (size_t n = 0; n < scene->nodes.size(); ++n)
      if (scene->nodes[n].skin >= 0 && scene->nodes[n].mesh >= 0) node = int(n), mesh = &scene->meshes[size_t(scene->nodes[n].mesh)];
  if (!scene || anim < 0 || !mesh || mesh->primitives.empty()) {
    c.verdict = Verdict::NotMeasurable;
    c.verdictText = "not measurable here: " + (scene ? std::string("skinned_tube has no candy_wrapper skin") : scene.error());
    c.measured = "-";
    return {c};
  }
  const Primitive& p = mesh->primitives[0];
  // Rings: vertices with the same rest height along the tube's axis (y).
  std::vector<int> ring(p.positions.size());
  for (size_t i = 0; i < p.positions.size(); ++i) ring[i] = int(std::lround(p.positions[i].y * 1e4f));
  const std::map<int, double> rest = radii(p.positions, ring);
  const motor::Rig rig = motor::buildRig(*scene);
  RingRadii worst;
  const float duration = scene->animations[size_t(anim)].duration;
  for (int k = 0; k < 64; ++k) {
    const AnimState state{anim, duration * float(k) / 64.0f};
    const matrix::Pose mp = matrix::poseScene(*scene, state, true);
    const auto world = motor::worldPose(*scene, motor::localForState(*scene, rig, state));
    const auto palettes = motor::jointPalettes(*scene, rig, world);
    const matrix::SkinPalette* ms = nullptr;
    const motor::JointPalette* qs = nullptr;
    for (const auto& s : mp.palettes) if (s.node == node) ms = &s;
    for (const auto& s : palettes) if (s.node == node) qs = &s;
    if (!ms || !qs) continue;
    std::vector<glm::vec3> lbs(p.positions.size()), mot(p.positions.size());
    for (size_t i = 0; i < p.positions.size(); ++i) {
      const glm::u16vec4 j = p.joints[i];
      const glm::vec4 w = p.weights[i];
      glm::vec4 x(0.0f);
      Motor jm[4];
      for (int a = 0; a < 4; ++a) {
        x += w[a] * (ms->matrices[2 * size_t(j[a])] * glm::vec4(p.positions[i], 1.0f));
        for (int e = 0; e < 8; ++e) jm[a][e / 4][e % 4] = qs->motors[8 * size_t(j[a]) + size_t(e)];
      }
      lbs[i] = glm::vec3(x);
      motor::ScaledMotor blended;
      blended.motor = mk().motorBlendJoints(jm[0], jm[1], jm[2], jm[3], MK::vec4(w.x, w.y, w.z, w.w));
      blended.scale = qs->scale;
      mot[i] = motor::applyToPoint(blended, p.positions[i]);
    }
    const auto rl = radii(lbs, ring), rm = radii(mot, ring);
    for (const auto& [key, r0] : rest) {
      if (!(r0 > 0)) continue;
      if (rl.at(key) / r0 < worst.lbs) worst.lbs = rl.at(key) / r0, worst.lbsTime = state.time;
      if (rm.at(key) / r0 < worst.motor) worst.motor = rm.at(key) / r0, worst.motorTime = state.time;
    }
  }
  c.measured = "smallest ring radius / rest radius: LBS " + num(worst.lbs) + " (t = " + num(worst.lbsTime, "%.2f") +
               " s), motor " + num(worst.motor) + " (t = " + num(worst.motorTime, "%.2f") + " s)";
  c.measuredValue = {{"lbs", worst.lbs}, {"motor", worst.motor}, {"lbsTime", worst.lbsTime}, {"motorTime", worst.motorTime}};
  const bool kept = worst.motor >= 0.95, pinched = worst.lbs < 0.95;
  c.verdict = kept && pinched ? Verdict::Reproduced : Verdict::Differs;
  c.verdictText = kept && pinched ? "reproduced: the motor keeps " + num(100 * worst.motor, "%.1f") + " % of the ring radius, LBS " +
                                        num(100 * worst.lbs, "%.1f") + " %"
                                  : std::string("differs: ") + (kept ? "" : "the motor ring shrinks; ") + (pinched ? "" : "LBS does not pinch");
  return {c};
}

}  // namespace mb::claims
