#include "harness/cli/morph_cost.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "harness/cli/survey_probe.h"
#include "harness/figures/figure.h"
#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "harness/render/skin_reference.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"

namespace mb::morph {
namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

bool skinnedScene(const Scene& scene) {
  for (const Node& n : scene.nodes)
    if (n.skin >= 0 && n.mesh >= 0) return true;
  return false;
}

// The rest pose and every animation at a quarter, half and three quarters of its duration.
std::vector<FrameSettings> frameList(const Scene& scene, int size) {
  std::vector<FrameSettings> out;
  FrameSettings rest;
  rest.width = rest.height = size;
  out.push_back(rest);
  for (size_t a = 0; a < scene.animations.size(); ++a)
    for (float f : {0.25f, 0.5f, 0.75f}) {
      FrameSettings s = rest;
      s.anim = AnimState{int(a), f * scene.animations[a].duration};
      out.push_back(s);
    }
  return out;
}

json metricsJson(const ImageMetrics& m) {
  return {{"psnr", std::isfinite(m.psnr) ? json(m.psnr) : json(nullptr)}, {"maxError", m.maxError}};
}

// One scene: every frame by every method, against matrix (unskinned) or the skin reference.
json measureScene(const std::string& spec, int size, json& glInfo) {
  json doc = {{"scene", spec}};
  auto loaded = loadScene(spec);
  if (!loaded) return doc["error"] = loaded.error(), doc;
  Scene& scene = *loaded;
  const bool skinned = skinnedScene(scene);
  doc["skinned"] = skinned;
  const FileStats stats = computeFileStats(scene);  // inspect's counts of the same scene
  doc["targets"] = stats.morphTargets;
  doc["weightChannels"] = stats.weightsChannels;
  const std::vector<FrameSettings> frames = frameList(scene, size);
  const std::vector<View> views = framings(scene, frames);
  doc["reference"] = skinned ? json{{"available", true}, {"why", nullptr}} : json(nullptr);
  json bytes = json::object();
  for (size_t k = 0; k < frames.size(); ++k) {
    json row = {{"anim", frames[k].anim.anim}, {"time", frames[k].anim.time}, {"methods", json::object()},
                {"morphedNodes", morphedNodes(scene, frames[k].anim)}};
    std::vector<RgbaImage> images;
    for (const Method& m : methods()) {
      FrameSettings s = frames[k];
      if (m.pipeline != "matrix") s.options.morph = m.rotorDeltas ? MorphMethod::Rotor : MorphMethod::Frame;
      auto f = renderFrame(scene, m.pipeline, s);
      if (!f) return doc["error"] = f.error(), doc;
      if (glInfo.is_null()) glInfo = toJson(f->gl);
      if (m.pipeline == "matrix") row["morphDraws"] = f->stats.morphDraws;
      row["methods"][m.id] = {{"morphDraws", f->stats.morphDraws}};
      if (!bytes.contains(m.id) && f->stats.vertices && f->stats.morphTargetVertices)
        bytes[m.id] = {{"vertexBytes", f->stats.vertexBytes}, {"vertices", f->stats.vertices},
                       {"morphBytes", f->stats.morphBytes}, {"morphTargetVertices", f->stats.morphTargetVertices}};
      images.push_back(f->image);
    }
    std::optional<RgbaImage> reference;
    if (skinned && doc["reference"]["available"].get<bool>()) {
      PreSkinnedScene pre(scene, frames[k].anim);
      if (!pre.available()) {
        doc["reference"] = {{"available", false}, {"why", pre.why()}};
      } else {
        auto r = drawFromViews(scene, "matrix", {frames[k]}, {views[k]});
        if (!r) return doc["error"] = r.error(), doc;
        reference = r->front();
      }
    }
    for (size_t i = 0; i < methods().size(); ++i) {
      const RgbaImage* base = skinned ? (reference ? &*reference : nullptr) : (i ? &images[0] : nullptr);
      if (!base) continue;
      auto metrics = compareImages(*base, images[i]);
      if (!metrics) return doc["error"] = metrics.error(), doc;
      row["methods"][methods()[i].id].update(metricsJson(*metrics));
    }
    doc["frames"].push_back(row);
  }
  // What the motor pipeline morphs with when not told (PipelineDefault): its upload's bytes per
  // target vertex, which tell the methods apart (9 floats for (a), 7 for (b)).
  if (auto f = renderFrame(scene, "motor", frames.front()); f && f->stats.morphTargetVertices)
    bytes["motor_default"] = {{"morphBytes", f->stats.morphBytes}, {"morphTargetVertices", f->stats.morphTargetVertices}};
  doc["bytes"] = bytes;
  return doc;
}

// The worst (lowest PSNR) frame of method `id` over the frames `use` accepts.
void worstOf(const json& doc, const std::string& id, bool skinned, const std::string& size, json& figures,
             json& worst) {
  double psnr = std::numeric_limits<double>::infinity(), maxError = 0;
  int n = 0;
  json where = nullptr;
  for (const json& s : doc["scenes"]) {
    if (s.contains("error") || s.value("skinned", false) != skinned) continue;
    for (const json& f : s["frames"]) {
      const json& m = f["methods"][id];
      if (f.value("morphDraws", 0) == 0 || !m.contains("maxError")) continue;
      ++n;
      maxError = std::max(maxError, m["maxError"].get<double>());
      const double p = m["psnr"].is_null() ? std::numeric_limits<double>::infinity() : m["psnr"].get<double>();
      if (p < psnr || where.is_null())
        psnr = p, where = {{"scene", s["scene"]}, {"anim", f["anim"]}, {"time", f["time"]}, {"maxError", m["maxError"]}};
    }
  }
  const std::string kind = skinned ? "skinned" : "rigid";
  const std::string against = skinned ? "the CPU skin reference (harness/render/skin_reference.h)" : "matrix";
  figures::Figure f;
  f.kind = "measured";
  f.name = "morph.worst_psnr." + kind + "." + id;
  f.unit = "dB";
  f.statistic = "minimum over frames";
  f.scope = std::string(skinned ? "skinned" : "unskinned") + " morph scenes, frames where matrix morphs a draw, " +
            size + " px";
  f.device = doc["gl"].is_object() ? doc["gl"].value("renderer", "GL") : "GL";
  f.n = n;
  f.tolerance = skinned ? "" : ">= 50 dB (the rigid image rule of every pipeline against matrix)";
  f.definition = "PSNR of the method's image against " + against + " on the same frame; the lowest frame";
  f.value = std::isfinite(psnr) ? psnr : std::nan("");
  if (!n) f.why = "no frame of these scenes has a non-zero morph weight on a drawn node";
  else if (!std::isfinite(psnr)) f.why = "identical to " + against + " on every such frame";
  figures::put(figures, f);
  figures::Figure e = f;
  e.name = "morph.max_error." + kind + "." + id;
  e.unit = "of 1";
  e.statistic = "maximum over frames";
  e.tolerance = "";
  e.definition = "largest channel difference (0..1) against " + against + " over the same frames";
  e.value = n ? maxError : std::nan("");
  e.why = n ? "" : f.why;
  figures::put(figures, e);
  worst[f.name] = where;
}

}  // namespace

const std::vector<Method>& methods() {
  static const std::vector<Method> m = {
      {"matrix", "matrix", "glTF deltas on position, normal, tangent, then the matrices", "rigid, morph", false},
      {"motor_frame", "motor", "(a) frame: deltas on the rotor's normal and tangent, rotor re-formed per vertex",
       "rigid, morph frame (a)", false},
      {"motor_rotor", "motor", "(b) rotor deltas made at load, blended and renormalised", "rigid, morph rotor (b)",
       true},
  };
  return m;
}

nlohmann::json morphFigures(const nlohmann::json& doc) {
  json figures = json::object(), worst = json::object();
  const std::string size = std::to_string(doc.value("size", 0));
  for (const Method& m : methods()) {
    if (m.id != "matrix") worstOf(doc, m.id, false, size + "x" + size, figures, worst);
    worstOf(doc, m.id, true, size + "x" + size, figures, worst);
    // Bytes: on the first scene that uploaded morph targets for this method.
    for (const json& s : doc["scenes"]) {
      if (!s.contains("bytes") || !s["bytes"].contains(m.id)) continue;
      const json& b = s["bytes"][m.id];
      figures::Figure v;
      v.kind = "measured";
      v.name = "morph.bytes_per_vertex." + m.id;
      v.unit = "bytes";
      v.statistic = "one scene";
      v.scope = s["scene"].get<std::string>() + ", every uploaded vertex";
      v.device = "the pipeline's uploads";
      v.n = 1;
      v.definition = "vertex attribute bytes uploaded / vertices uploaded (PipelineStats vertexBytes / vertices)";
      v.value = double(b["vertexBytes"].get<uint64_t>()) / double(b["vertices"].get<uint64_t>());
      figures::put(figures, v);
      v.name = "morph.bytes_per_target_vertex." + m.id;
      v.definition = "morph delta bytes uploaded / (targets x vertices) they hold (PipelineStats morphBytes / "
                     "morphTargetVertices): one target's bytes per vertex";
      v.value = double(b["morphBytes"].get<uint64_t>()) / double(b["morphTargetVertices"].get<uint64_t>());
      figures::put(figures, v);
      break;
    }
  }
  // The motor pipeline's default method: the one whose delta bytes per target vertex the default
  // upload matched on the first scene that has both.
  json defaultMethod = nullptr;
  for (const json& s : doc["scenes"]) {
    const json b = s.value("bytes", json::object());
    if (!b.contains("motor_default")) continue;
    auto perTarget = [&](const char* id) {
      return b.contains(id) ? b[id]["morphBytes"].get<double>() / b[id]["morphTargetVertices"].get<double>() : -1.0;
    };
    const double d = perTarget("motor_default");
    for (const char* id : {"motor_frame", "motor_rotor"})
      if (perTarget(id) == d) defaultMethod = id;
    break;
  }
  return {{"figures", figures}, {"worst", worst}, {"motorDefault", defaultMethod}};
}

nlohmann::json measureMorphCost(const std::vector<std::string>& scenes, int size, int* errors) {
  json doc = {{"schema", "motorbench-morph/1"}, {"size", size}, {"gl", nullptr}, {"scenes", json::array()}};
  for (const Method& m : methods())
    doc["methods"].push_back({{"id", m.id}, {"pipeline", m.pipeline}, {"method", m.method}, {"program", m.label}});
  int failed = 0;
  for (const std::string& s : scenes) {
    json r = measureScene(s, size, doc["gl"]);
    failed += r.contains("error");
    doc["scenes"].push_back(std::move(r));
  }
  if (errors) *errors = failed;
  doc.update(morphFigures(doc));
  return doc;
}

std::vector<std::string> manifestMorphFiles(const std::string& folder) {
  std::vector<std::string> out;
  std::ifstream in(fs::path(folder) / "MANIFEST.tsv");
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cols;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, '\t');) cols.push_back(c);
    if (cols.size() > 8 && cols[8].find("morph-targets") != std::string::npos)
      out.push_back((fs::path(folder) / cols[0]).string());
  }
  return out;
}

}  // namespace mb::morph
