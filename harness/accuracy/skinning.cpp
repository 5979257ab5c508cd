#include "harness/accuracy/skinning.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <tuple>

#include "harness/accuracy/accuracy_figure.h"
#include "harness/render/scene_inputs.h"
#include "pipelines/matrix/matrix_pose.h"
#include "pipelines/motor/motor_rig.h"
#include "pipelines/scene/loader.h"

namespace mb::accuracy {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

constexpr int kCandyTimes = 64;  // times over candy_wrapper's duration
constexpr int kFileTimes = 64;   // intervals over each animation of a file (65 times, both ends)

// Every vertex of primitive `p` of skinned mesh node `node` skinned both ways at `state`: LBS of
// the matrix pipeline's world-space joint matrices, and motorBlendJoints + the skin's uniform
// scale of the motor pipeline's joint motors. False when either pipeline has no palette.
bool skinBothWays(const Scene& scene, const motor::Rig& rig, int node, const Primitive& p, const AnimState& state,
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

// Smallest and largest volume ratio (posed / rest) seen, per skinning method.
struct Range {
  double lo = 1e30, hi = -1e30;
  void add(double r) { lo = std::min(lo, r), hi = std::max(hi, r); }
  bool empty() const { return hi < lo; }
  double deviation() const { return std::max(std::fabs(lo - 1), std::fabs(hi - 1)); }
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

// Posed / rest volume ranges of one skinned primitive over every animation; false when it
// cannot be skinned both ways.
bool primitiveVolumes(const Scene& scene, const motor::Rig& rig, int node, const Primitive& p, bool closed,
                      Range& lbs, Range& mot) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& x : p.positions) lo = glm::min(lo, x), hi = glm::max(hi, x);
  const double h = 1e-3 * std::max(1e-6, double(glm::length(hi - lo)));
  const AnimState rest{-1, 0.0f};
  std::vector<glm::vec3> rl, rm;
  if (!skinBothWays(scene, rig, node, p, rest, rl, rm)) return false;
  const double vl0 = closed ? enclosedVolume(rl, p.indices) : 0, vm0 = closed ? enclosedVolume(rm, p.indices) : 0;
  const std::vector<double> dl0 = closed ? std::vector<double>{} : localVolumes(scene, rig, node, p, rest, false, h);
  const std::vector<double> dm0 = closed ? std::vector<double>{} : localVolumes(scene, rig, node, p, rest, true, h);
  for (size_t a = 0; a < scene.animations.size(); ++a)
    for (int k = 0; k <= kFileTimes; ++k) {
      const AnimState st{int(a), scene.animations[a].duration * float(k) / float(kFileTimes)};
      if (closed) {
        std::vector<glm::vec3> l, m;
        if (!skinBothWays(scene, rig, node, p, st, l, m)) continue;
        if (vl0 != 0) lbs.add(enclosedVolume(l, p.indices) / vl0);
        if (vm0 != 0) mot.add(enclosedVolume(m, p.indices) / vm0);
        continue;
      }
      const std::vector<double> dl = localVolumes(scene, rig, node, p, st, false, h);
      const std::vector<double> dm = localVolumes(scene, rig, node, p, st, true, h);
      for (size_t i = 0; i < dl.size() && i < dl0.size(); ++i)
        if (std::fabs(dl0[i]) > 0) lbs.add(dl[i] / dl0[i]);
      for (size_t i = 0; i < dm.size() && i < dm0.size(); ++i)
        if (std::fabs(dm0[i]) > 0) mot.add(dm[i] / dm0[i]);
    }
  return !lbs.empty() && !mot.empty();
}

// The measured meshes of one loaded file, appended to `meshes`.
void fileVolumes(const Scene& scene, const std::string& file, json& meshes) {
  if (scene.skins.empty() || scene.animations.empty()) return;
  const motor::Rig rig = motor::buildRig(scene);
  for (size_t n = 0; n < scene.nodes.size(); ++n) {
    const Node& nd = scene.nodes[n];
    if (nd.skin < 0 || nd.mesh < 0) continue;
    const Mesh& mesh = scene.meshes[size_t(nd.mesh)];
    for (size_t pi = 0; pi < mesh.primitives.size(); ++pi) {
      const Primitive& p = mesh.primitives[pi];
      if (p.positions.empty() || p.joints.empty()) continue;
      const bool closed = isClosed(p.positions, p.indices);
      Range lbs, mot;
      if (!primitiveVolumes(scene, rig, int(n), p, closed, lbs, mot)) continue;
      meshes.push_back({{"id", file + "/" + (mesh.name.empty() ? "mesh" + std::to_string(nd.mesh) : mesh.name) +
                                   (mesh.primitives.size() > 1 ? "#" + std::to_string(pi) : "")},
                        {"file", file}, {"closed", closed},
                        {"measure", closed ? "enclosed volume" : "local volume (Jacobian det)"},
                        {"lbs", {{"min", lbs.lo}, {"max", lbs.hi}}}, {"motor", {{"min", mot.lo}, {"max", mot.hi}}}});
    }
  }
}

}  // namespace

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

RingRadii measureCandyWrapper() {
  RingRadii out;
  auto scene = loadScene("skinned_tube");
  if (!scene) {
    out.why = scene.error();
    return out;
  }
  int anim = -1, node = -1;
  for (size_t i = 0; i < scene->animations.size(); ++i)
    if (scene->animations[i].name == "candy_wrapper") anim = int(i);
  for (size_t n = 0; n < scene->nodes.size(); ++n)
    if (scene->nodes[n].skin >= 0 && scene->nodes[n].mesh >= 0) node = int(n);
  if (anim < 0 || node < 0 || scene->meshes[size_t(scene->nodes[size_t(node)].mesh)].primitives.empty()) {
    out.why = "skinned_tube has no candy_wrapper animation on a skinned mesh";
    return out;
  }
  const Primitive& p = scene->meshes[size_t(scene->nodes[size_t(node)].mesh)].primitives[0];
  // Rings: vertices with the same rest height along the tube's axis (y).
  std::vector<int> ring(p.positions.size());
  for (size_t i = 0; i < p.positions.size(); ++i) ring[i] = int(std::lround(p.positions[i].y * 1e4f));
  const std::map<int, double> rest = radii(p.positions, ring);
  out.rings = int(rest.size());
  const motor::Rig rig = motor::buildRig(*scene);
  const float duration = scene->animations[size_t(anim)].duration;
  for (int k = 0; k < kCandyTimes; ++k) {
    const AnimState state{anim, duration * float(k) / float(kCandyTimes)};
    std::vector<glm::vec3> lbs, mot;
    if (!skinBothWays(*scene, rig, node, p, state, lbs, mot)) continue;
    ++out.times;
    const auto rl = radii(lbs, ring), rm = radii(mot, ring);
    for (const auto& [key, r0] : rest) {
      if (!(r0 > 0)) continue;
      if (rl.at(key) / r0 < out.lbs) out.lbs = rl.at(key) / r0, out.lbsTime = state.time;
      if (rm.at(key) / r0 < out.motor) out.motor = rm.at(key) / r0, out.motorTime = state.time;
    }
  }
  out.measured = out.times > 0;
  if (!out.measured) out.why = "neither pipeline gave skinned_tube a palette";
  return out;
}

void putCandyWrapperFigures(const RingRadii& r, json& figures, json& details) {
  details["candy_wrapper"] = {{"rings", r.rings}, {"times", r.times}, {"lbsTime", r.lbsTime}, {"motorTime", r.motorTime}};
  const std::string scope = "built-in skinned_tube, animation candy_wrapper (the middle joint turns 180 degrees about "
                            "the tube's axis), every ring of the tube at " + std::to_string(kCandyTimes) +
                            " times over its duration";
  const std::string radius = "ring radius (mean distance of a ring's vertices from their centroid) / the ring's rest "
                             "radius, the ring's vertices skinned on the CPU ";
  const double nan = std::nan("");
  FigureText lbs{"of rest", "measured: smallest over every ring and time", scope,
                 radius + "by linear blend skinning of the matrix pipeline's world-space joint matrices"};
  lbs.device = "CPU, float skinning as the pipelines' palettes";
  lbs.why = r.why;
  FigureText mot = lbs;
  mot.definition = radius + "by motorBlendJoints of the motor pipeline's joint motors and the skin's uniform scale";
  putFigure(figures, "skin.ring_radius.candy_wrapper.lbs.min", r.measured ? r.lbs : nan, r.times, lbs);
  putFigure(figures, "skin.ring_radius.candy_wrapper.motor.min", r.measured ? r.motor : nan, r.times, mot);
}

Result<json> measureSkinnedFileVolumes(const std::string& dir) {
  std::error_code ec;
  if (dir.empty() || !fs::is_directory(dir, ec))
    return Result<json>::fail(dir.empty() ? std::string("no folder given") : dir + ": not a folder");
  const std::vector<std::string> files = expandSceneInputs({dir});
  if (files.empty()) return Result<json>::fail(dir + ": folder holds no .gltf or .glb files");
  json out = {{"folder", dir}, {"files", json::array()}, {"meshes", json::array()}, {"failed", json::array()}};
  for (const std::string& f : files) {
    const std::string name = fs::path(f).lexically_relative(dir).generic_string();
    out["files"].push_back(name);
    auto scene = loadScene(f);
    if (!scene) {
      out["failed"].push_back({{"file", name}, {"error", scene.error()}});
      continue;
    }
    fileVolumes(*scene, name, out["meshes"]);
  }
  return out;
}

void putSkinnedFileFigures(const json& volumes, json& figures, json& details) {
  details["skinned_files"] = volumes;
  Range lbs, mot;
  std::map<std::string, int> byFile;
  int closed = 0;
  const json meshes = volumes.value("meshes", json::array());
  for (const json& m : meshes) {
    lbs.add(m["lbs"]["min"].get<double>()), lbs.add(m["lbs"]["max"].get<double>());
    mot.add(m["motor"]["min"].get<double>()), mot.add(m["motor"]["max"].get<double>());
    ++byFile[m["file"].get<std::string>()];
    closed += m.value("closed", false);
  }
  const int n = int(meshes.size()), files = int(volumes.value("files", json::array()).size());
  const std::string folder = volumes.value("folder", std::string("?"));
  const std::string scope = "every animated skinned mesh of the " + std::to_string(files) + " .gltf/.glb files under " +
                            folder + " (" + std::to_string(byFile.size()) + " skinned and animated; " +
                            std::to_string(closed) + " closed meshes: enclosed volume, " + std::to_string(n - closed) +
                            " open: local volume), every animation at " + std::to_string(kFileTimes + 1) +
                            " times over its duration";
  const std::string volume = "volume posed / at the rest pose: a closed mesh (after welding equal positions) its "
                             "enclosed volume (signed tetrahedra), an open mesh the local volume at each vertex (det of "
                             "the skinning map's Jacobian, finite differences); skinned on the CPU ";
  const std::string lbsWay = "by linear blend skinning of the matrix pipeline's world-space joint matrices";
  const std::string motorWay = "by motorBlendJoints of the motor pipeline's joint motors and the skin's uniform scale";
  const double nan = std::nan("");
  auto text = [&](const char* statistic, const std::string& way) {
    FigureText t{"of rest", statistic, scope, volume + way};
    t.device = "CPU, float skinning as the pipelines' palettes";
    t.why = "no animated skinned mesh under " + folder;
    return t;
  };
  const char* lo = "measured: smallest over every mesh, time and (open meshes) vertex";
  const char* hi = "measured: largest over every mesh, time and (open meshes) vertex";
  const char* dev = "measured: largest |posed / rest - 1| over every mesh, time and (open meshes) vertex";
  putFigure(figures, "skin.volume.files.lbs.min", n ? lbs.lo : nan, n, text(lo, lbsWay));
  putFigure(figures, "skin.volume.files.lbs.max", n ? lbs.hi : nan, n, text(hi, lbsWay));
  putFigure(figures, "skin.volume.files.lbs.max_deviation", n ? lbs.deviation() : nan, n, text(dev, lbsWay));
  putFigure(figures, "skin.volume.files.motor.min", n ? mot.lo : nan, n, text(lo, motorWay));
  putFigure(figures, "skin.volume.files.motor.max", n ? mot.hi : nan, n, text(hi, motorWay));
  putFigure(figures, "skin.volume.files.motor.max_deviation", n ? mot.deviation() : nan, n, text(dev, motorWay));
  putFigure(figures, "skin.volume.files.files", files, files,
            {"files", "counted", scope, ".gltf/.glb files read under the folder", "CPU"});
  putFigure(figures, "skin.volume.files.skinned_files", double(byFile.size()), files,
            {"files", "counted", scope, "files with at least one animated skinned mesh measured", "CPU"});
  putFigure(figures, "skin.volume.files.meshes", n, files,
            {"meshes", "counted", scope, "animated skinned meshes (primitives) measured", "CPU"});
}

}  // namespace mb::accuracy
