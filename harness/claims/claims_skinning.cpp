// Skinning claims: motor blending, like dual-quaternion skinning, keeps the mesh's
// volume where linear blend skinning (LBS) pinches. Measured on the built-in skinned_tube's
// "candy_wrapper" animation (the middle joint turns 180 degrees about the tube's axis): each
// ring of the tube is skinned on the CPU both ways from the pipelines' own palettes (matrix
// world-space palette, LBS of the joint matrices; motor palette, motorBlendJoints of
// shaders/motor_transform.glsl), and its radius (mean distance of its vertices from their
// centroid) is compared with the rest pose's, over 64 times of the animation.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <tuple>

#include "harness/claims/claims_measures.h"
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

// Every vertex of primitive `p` of skinned mesh node `node` skinned both ways at `state`: LBS of
// the matrix pipeline's world-space joint matrices, and motorBlendJoints + the skin's uniform
// scale of the motor pipeline's joint motors. False when either pipeline has no palette.
static bool skinBothWays(const Scene& scene, const motor::Rig& rig, int node, const Primitive& p, const AnimState& state,
                  std::vector<glm::vec3>& lbs, std::vector<glm::vec3>& mot) {
  const matrix::Pose mp = matrix::poseScene(scene, state, true);
  const auto world = motor::worldPose(scene, motor::localForState(scene, rig, state));
  const auto palettes = motor::jointPalettes(scene, rig, world);
  const matrix::SkinPalette* ms = nullptr;
  const motor::JointPalette* qs = nullptr;
  for (const auto& s : mp.palettes) if (s.node == node) ms = &s;
  for (const auto& s : palettes) if (s.node == node) qs = &s;
  if (!ms || !qs || p.joints.size() != p.positions.size() || p.weights.size() != p.positions.size()) return false;
  const size_t joints = qs->motors.size() / 8;
  lbs.assign(p.positions.size(), glm::vec3(0.0f));
  mot.assign(p.positions.size(), glm::vec3(0.0f));
  for (size_t i = 0; i < p.positions.size(); ++i) {
    const glm::u16vec4 j = p.joints[i];
    const glm::vec4 w = p.weights[i];
    glm::vec4 x(0.0f);
    Motor jm[4];
    for (int a = 0; a < 4; ++a) {
      const size_t ja = size_t(j[a]) < joints ? size_t(j[a]) : 0;
      x += w[a] * (ms->matrices[2 * ja] * glm::vec4(p.positions[i], 1.0f));
      for (int e = 0; e < 8; ++e) jm[a][e / 4][e % 4] = qs->motors[8 * ja + size_t(e)];
    }
    lbs[i] = glm::vec3(x);
    motor::ScaledMotor blended;
    blended.motor = mk().motorBlendJoints(jm[0], jm[1], jm[2], jm[3], MK::vec4(w.x, w.y, w.z, w.w));
    blended.scale = qs->scale;
    mot[i] = motor::applyToPoint(blended, p.positions[i]);
  }
  return true;
}

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
    std::vector<glm::vec3> lbs, mot;
    if (!skinBothWays(*scene, rig, node, p, state, lbs, mot)) continue;
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


double enclosedVolume(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices) {
  double v = 0;
  for (size_t i = 0; i + 2 < indices.size(); i += 3) {
    const glm::dvec3 a(positions[indices[i]]), b(positions[indices[i + 1]]), c(positions[indices[i + 2]]);
    v += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return v;
}

bool isClosed(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices) {
  // Weld vertices at exactly the same position (uv and normal seams split them in glTF).
  std::map<std::tuple<float, float, float>, uint32_t> ids;
  std::vector<uint32_t> weld(positions.size());
  for (size_t i = 0; i < positions.size(); ++i)
    weld[i] = ids.emplace(std::make_tuple(positions[i].x, positions[i].y, positions[i].z), uint32_t(ids.size())).first->second;
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (size_t i = 0; i + 2 < indices.size(); i += 3)
    for (int e = 0; e < 3; ++e) {
      const uint32_t a = weld[indices[i + size_t(e)]], b = weld[indices[i + size_t((e + 1) % 3)]];
      if (a == b) return false;
      ++edges[{std::min(a, b), std::max(a, b)}];
    }
  if (edges.empty()) return false;
  for (const auto& [e, n] : edges)
    if (n != 2) return false;
  return true;
}

namespace {

// Smallest and largest volume ratio (posed / rest) seen, per skinning method.
struct Range {
  double lo = 1e30, hi = -1e30;
  void add(double r) { lo = std::min(lo, r), hi = std::max(hi, r); }
  bool within(double tol) const { return lo >= 1 - tol && hi <= 1 + tol; }
};

// det of the skinning map's Jacobian at each vertex, by finite differences along x, y, z.
std::vector<double> localVolumes(const Scene& s, const motor::Rig& rig, int node, const Primitive& p,
                                 const AnimState& st, bool motorSide, double h) {
  std::vector<glm::vec3> base[2], moved[3][2];
  skinBothWays(s, rig, node, p, st, base[0], base[1]);
  for (int k = 0; k < 3; ++k) {
    Primitive q = p;
    for (glm::vec3& x : q.positions) x[k] += float(h);
    skinBothWays(s, rig, node, q, st, moved[k][0], moved[k][1]);
  }
  const int m = motorSide ? 1 : 0;
  std::vector<double> out;
  for (size_t i = 0; i < base[m].size(); ++i) {
    const glm::dmat3 J(glm::dvec3(moved[0][m][i] - base[m][i]) / h, glm::dvec3(moved[1][m][i] - base[m][i]) / h,
                       glm::dvec3(moved[2][m][i] - base[m][i]) / h);
    out.push_back(glm::determinant(J));
  }
  return out;
}

}  // namespace

Result<nlohmann::json> measureSkinnedFileVolumes(const std::string& corpusDir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (corpusDir.empty() || !fs::is_directory(corpusDir, ec))
    return Result<nlohmann::json>::fail("no corpus folder (" + (corpusDir.empty() ? std::string("none given") : corpusDir + " not found") + ")");
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(corpusDir, ec)) {
    const std::string ext = e.path().extension().string();
    if (e.is_regular_file() && (ext == ".gltf" || ext == ".glb")) files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  nlohmann::json out = {{"schema", kSkinVolumesSchema}, {"folder", corpusDir}, {"files", nlohmann::json::array()},
                        {"meshes", nlohmann::json::array()}};
  for (const std::string& f : files) {
    out["files"].push_back(fs::path(f).filename().string());
    auto scene = loadScene(f);
    if (!scene || scene->skins.empty() || scene->animations.empty()) continue;
    const motor::Rig rig = motor::buildRig(*scene);
    for (size_t n = 0; n < scene->nodes.size(); ++n) {
      const Node& nd = scene->nodes[n];
      if (nd.skin < 0 || nd.mesh < 0) continue;
      const Mesh& mesh = scene->meshes[size_t(nd.mesh)];
      for (size_t pi = 0; pi < mesh.primitives.size(); ++pi) {
        const Primitive& p = mesh.primitives[pi];
        if (p.positions.empty() || p.joints.empty()) continue;
        const bool closed = isClosed(p.positions, p.indices);
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (const glm::vec3& x : p.positions) lo = glm::min(lo, x), hi = glm::max(hi, x);
        const double h = 1e-3 * std::max(1e-6, double(glm::length(hi - lo)));
        Range lbs, mot;
        const AnimState rest{-1, 0.0f};
        std::vector<glm::vec3> rl, rm;
        if (!skinBothWays(*scene, rig, int(n), p, rest, rl, rm)) continue;
        const double vl0 = closed ? enclosedVolume(rl, p.indices) : 0, vm0 = closed ? enclosedVolume(rm, p.indices) : 0;
        const std::vector<double> dl0 = closed ? std::vector<double>{} : localVolumes(*scene, rig, int(n), p, rest, false, h);
        const std::vector<double> dm0 = closed ? std::vector<double>{} : localVolumes(*scene, rig, int(n), p, rest, true, h);
        for (size_t a = 0; a < scene->animations.size(); ++a)
          for (int k = 0; k <= 64; ++k) {
            const AnimState st{int(a), scene->animations[a].duration * float(k) / 64.0f};
            if (closed) {
              std::vector<glm::vec3> l, m;
              if (!skinBothWays(*scene, rig, int(n), p, st, l, m)) continue;
              if (vl0 != 0) lbs.add(enclosedVolume(l, p.indices) / vl0);
              if (vm0 != 0) mot.add(enclosedVolume(m, p.indices) / vm0);
            } else {
              const std::vector<double> dl = localVolumes(*scene, rig, int(n), p, st, false, h);
              const std::vector<double> dm = localVolumes(*scene, rig, int(n), p, st, true, h);
              for (size_t i = 0; i < dl.size() && i < dl0.size(); ++i)
                if (std::fabs(dl0[i]) > 0) lbs.add(dl[i] / dl0[i]);
              for (size_t i = 0; i < dm.size() && i < dm0.size(); ++i)
                if (std::fabs(dm0[i]) > 0) mot.add(dm[i] / dm0[i]);
            }
          }
        if (lbs.hi < lbs.lo || mot.hi < mot.lo) continue;
        const std::string file = fs::path(f).filename().string();
        out["meshes"].push_back(
            {{"id", file + "/" + (mesh.name.empty() ? "mesh" + std::to_string(nd.mesh) : mesh.name) +
                        (mesh.primitives.size() > 1 ? "#" + std::to_string(pi) : "")},
             {"file", file}, {"closed", closed}, {"measure", closed ? "enclosed volume" : "local volume (Jacobian det)"},
             {"lbs", {{"min", lbs.lo}, {"max", lbs.hi}}}, {"motor", {{"min", mot.lo}, {"max", mot.hi}}}});
      }
    }
  }
  return out;
}

namespace {

Claim skinnedFileVolumeRow() {
  Claim c{"skinning_volume_file", "Skinning",
          "motor skinning keeps volume where linear blend skinning loses it, on a real skinned glTF file"};
  c.paper = "implied (the dual-quaternion skinning pattern)";
  c.paperValue = nullptr;
  return c;
}

std::string volumeMethod(const std::string& folder, const std::string& keptIn) {
  return "every skinned mesh of every .gltf/.glb directly in " + folder +
         (keptIn.empty() ? std::string() : " (its figures kept in " + keptIn + ")") +
         ", every animation at 64 times over its duration, skinned on the CPU from both pipelines' palettes "
         "(as skinning_volume). A closed mesh (after welding equal positions): enclosed volume (signed tetrahedra) "
         "posed / at the rest pose, per method. An open mesh: the local volume, det of the skinning map's Jacobian "
         "at each vertex (finite differences), posed / rest. Verdict: reproduced when the motor stays within 5 % "
         "and LBS does not; differs when the motor leaves 5 %; inconclusive when neither does (the file's motion "
         "does not pinch LBS).";
}

}  // namespace

std::vector<Claim> skinnedFileVolumeClaims(const std::string& corpusDir) {
  auto measured = measureSkinnedFileVolumes(corpusDir);
  if (measured) return skinnedFileVolumeClaimsFrom(*measured);
  Claim c = skinnedFileVolumeRow();
  c.method = volumeMethod(corpusDir, "");
  c.verdict = Verdict::NotMeasurable;
  c.measured = "-";
  c.measuredValue = nullptr;
  c.verdictText = "not measurable here: " + measured.error();
  return {c};
}

std::vector<Claim> skinnedFileVolumeClaimsFrom(const nlohmann::json& volumes, const std::string& keptIn) {
  Claim c = skinnedFileVolumeRow();
  const std::string folder = volumes.value("folder", std::string("?"));
  c.method = volumeMethod(folder, keptIn);
  nlohmann::json per = nlohmann::json::object();
  std::string text;
  Range lbsAll, motorAll;
  // Per file: meshes measured closed / open and the ranges over them (the text; JSON per mesh).
  struct FileSum { int closed = 0, open = 0; Range lbs, mot; };
  std::map<std::string, FileSum> byFile;
  const nlohmann::json meshes = volumes.value("meshes", nlohmann::json::array());
  for (const nlohmann::json& m : meshes) {
    const Range lbs{m["lbs"]["min"].get<double>(), m["lbs"]["max"].get<double>()};
    const Range mot{m["motor"]["min"].get<double>(), m["motor"]["max"].get<double>()};
    per[m["id"].get<std::string>()] = {{"measure", m["measure"]}, {"lbs", m["lbs"]}, {"motor", m["motor"]}};
    FileSum& fsum = byFile[m["file"].get<std::string>()];
    (m.value("closed", false) ? fsum.closed : fsum.open) += 1;
    fsum.lbs.add(lbs.lo), fsum.lbs.add(lbs.hi), fsum.mot.add(mot.lo), fsum.mot.add(mot.hi);
    lbsAll.add(lbs.lo), lbsAll.add(lbs.hi), motorAll.add(mot.lo), motorAll.add(mot.hi);
  }
  if (meshes.empty()) {
    c.verdict = Verdict::NotMeasurable;
    c.measured = "-";
    c.measuredValue = nullptr;
    c.verdictText = "not measurable here: no animated skinned mesh in " + folder;
    return {c};
  }
  for (const auto& [file, fsum] : byFile)
    text += (text.empty() ? "" : "; ") + file + " (" +
            (fsum.closed ? std::to_string(fsum.closed) + " closed mesh(es): enclosed volume" : std::string()) +
            (fsum.closed && fsum.open ? ", " : "") +
            (fsum.open ? std::to_string(fsum.open) + " open mesh(es): local volume" : std::string()) + ") LBS " +
            num(fsum.lbs.lo) + ".." + num(fsum.lbs.hi) + ", motor " + num(fsum.mot.lo) + ".." + num(fsum.mot.hi);
  c.measured = "volume posed / rest over every time: " + text;
  c.measuredValue = {{"meshes", per}, {"lbs", {{"min", lbsAll.lo}, {"max", lbsAll.hi}}},
                     {"motor", {{"min", motorAll.lo}, {"max", motorAll.hi}}}};
  const bool kept = motorAll.within(0.05), lost = !lbsAll.within(0.05);
  c.verdict = kept && lost ? Verdict::Reproduced : !kept ? Verdict::Differs : Verdict::Inconclusive;
  c.verdictText = kept && lost ? "reproduced: motor " + num(motorAll.lo) + ".." + num(motorAll.hi) + ", LBS " + num(lbsAll.lo) +
                                     ".." + num(lbsAll.hi) + " of the rest volume"
                  : !kept ? "differs: the motor-skinned volume leaves 5 % (" + num(motorAll.lo) + ".." + num(motorAll.hi) + ")"
                          : "inconclusive: neither method leaves 5 % of the rest volume on these files (LBS " + num(lbsAll.lo) +
                                ".." + num(lbsAll.hi) + ", motor " + num(motorAll.lo) + ".." + num(motorAll.hi) +
                                "): their motion does not pinch";
  return {c};
}

}  // namespace mb::claims
