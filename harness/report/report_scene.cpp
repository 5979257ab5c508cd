#include "harness/report/report_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <set>

#include "harness/figures/figure_statistics.h"
#include "harness/render/drawn_check.h"
#include "harness/render/flip.h"
#include "harness/render/frame_notes.h"
#include "harness/render/image_metrics.h"
#include "harness/report/content_kinds.h"
#include "harness/report/report_animation.h"
#include "harness/report/report_sources.h"
#include "harness/report/vertex_fetch.h"
#include "harness/render/render_frame.h"
#include "harness/render/skin_judgement.h"
#include "pipelines/scene/curved_space.h"
#include "pipelines/scene/drawable.h"
#include "pipelines/scene/instancing.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scale_analysis.h"
#include "pipelines/scene/scene_stats.h"

namespace mb::report {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// Bytes and floats as uploaded. bytesPerVertex counts the shading attributes only (the
// paper's 12 vs 9 floats); bytesPerVertexAll adds skin and optional streams.
json memoryJson(const PipelineStats& s) {
  const double v = double(s.vertices);
  auto per = [&](uint64_t bytes) { return v > 0 ? json(double(bytes) / v) : json(nullptr); };
  return {{"vertices", s.vertices},
          {"vertexBytes", s.vertexBytes},
          {"skinVertexBytes", s.skinVertexBytes},
          {"extraVertexBytes", s.extraVertexBytes},
          {"indexBytes", s.indexBytes},
          {"textureBytes", s.textureBytes},
          {"uniformBytesPerFrame", s.uniformBytesPerFrame},
          {"skinBytesPerFrame", s.skinBytesPerFrame},
          {"bytesPerVertex", per(s.vertexBytes)},
          {"bytesPerVertexAll", per(s.vertexBytes + s.skinVertexBytes + s.extraVertexBytes)},
          // Split by material: the paper's 12-vs-9 floats is the normal-mapped case.
          {"normalMappedVertices", s.normalMappedVertices},
          {"bytesPerVertexNormalMapped",
           s.normalMappedVertices ? json(double(s.normalMappedVertexBytes) / double(s.normalMappedVertices)) : json(nullptr)},
          {"bytesPerVertexNotNormalMapped",
           s.vertices > s.normalMappedVertices
               ? json(double(s.vertexBytes - s.normalMappedVertexBytes) / double(s.vertices - s.normalMappedVertices))
               : json(nullptr)},
          {"floatsPerVertex", s.floatsPerVertex},
          // null: no node transform uploaded (every draw skinned, or every draw instanced: the
          // joint palette or the per-instance stream moves the mesh), not a transform of 0 floats.
          {"floatsPerTransform", s.floatsPerTransform > 0 ? json(s.floatsPerTransform) : json(nullptr)},
          {"floatsPerTransformWithScale",
           s.floatsPerTransformWithScale > 0 ? json(s.floatsPerTransformWithScale) : json(nullptr)},
          {"floatsPerJoint", s.floatsPerJoint},
          // Instanced draws: the per-instance transforms of one frame and their size each.
          {"instances", s.instances},
          {"instanceBytes", s.instanceBytes},
          {"bytesPerInstance", s.instances ? json(double(s.instanceBytes) / double(s.instances)) : json(nullptr)}};
}

// Every fallback counter, zeros included: the list render and compare print (frame_notes.h).
json fallbacksJson(const PipelineStats& s) { return pipelineFallbackJson(s); }

std::string timeText(float t) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", double(t));
  return buf;
}

// One frame's judge of skinned frames by their own skinning method (skin_judgement.h): the
// references are made once per frame, when first needed (matrix's image: the frame's own when
// matrix drew it; the motor-blend reference), and each judgement is written into the frame:
// "skinJudgement.<p>" and, judged, "referenceMetrics.<p>" (with FLIP against the reference);
// a reference frame's error into "errors.skin_<p>".
class OwnMethodJudge {
public:
  OwnMethodJudge(Scene& scene, const FrameSettings& settings, const std::map<std::string, RgbaImage>& images,
                 std::function<void(const std::string&)> progress)
      : scene_(scene), settings_(settings), images_(images), progress_(std::move(progress)) {}

  const SkinnedFrameJudgement* judge(const std::string& p, json& frame) {
    if (auto it = done_.find(p); it != done_.end()) return &it->second;
    const RgbaImage* matrix = matrixImage();
    if (!matrix) {
      frame["errors"]["skin_" + p] = matrixError_;
      return nullptr;
    }
    const MotorBlendFrames& own = motorBlend();
    auto j = judgeSkinnedFrame(p, images_.at(p), *matrix, own.images.empty() ? nullptr : &own.images[0], own.why, nullptr);
    if (!j) {
      frame["errors"]["skin_" + p] = j.error();
      return nullptr;
    }
    frame["skinJudgement"][p] = toJson(*j);
    if (j->judged) {
      const RgbaImage& reference = j->reference == kMatrixReference ? *matrix : own.images[0];
      auto flip = computeFlip(reference, images_.at(p));
      frame["referenceMetrics"][p] = flip ? toJson(j->vsReference.metrics, *flip) : toJson(j->vsReference.metrics);
    }
    return &done_.emplace(p, j.take()).first->second;
  }

private:
  const RgbaImage* matrixImage() {
    if (auto it = images_.find(kMatrixReference); it != images_.end()) return &it->second;
    if (!matrix_ && matrixError_.empty()) {
      progress_("rendering matrix (the linear blend's reference)");
      auto f = renderFrame(scene_, kMatrixReference, settings_);
      if (f) matrix_ = std::move(f->image);
      else matrixError_ = f.error();
    }
    return matrix_ ? &*matrix_ : nullptr;
  }
  const MotorBlendFrames& motorBlend() {
    if (!motorBlendMade_) {
      progress_("rendering the motor-blend reference");
      motorBlend_ = motorBlendReferenceFrames(scene_, {settings_});
      motorBlendMade_ = true;
    }
    return motorBlend_;
  }

  Scene& scene_;
  const FrameSettings& settings_;
  const std::map<std::string, RgbaImage>& images_;
  std::function<void(const std::string&)> progress_;
  std::optional<RgbaImage> matrix_;
  std::string matrixError_;
  bool motorBlendMade_ = false;
  MotorBlendFrames motorBlend_;
  std::map<std::string, SkinnedFrameJudgement> done_;
};

}  // namespace

std::vector<float> imageTimes(const Scene& scene, int anim) {
  if (anim < 0 || size_t(anim) >= scene.animations.size() || !(scene.animations[size_t(anim)].duration > 0.0f))
    return {0.0f};
  const float d = scene.animations[size_t(anim)].duration;
  return {0.0f, d / 3.0f, 2.0f * d / 3.0f};
}

json vertexMix(const Scene& scene) {
  const ScaleReport scale = analyzeScale(scene);
  long rigid = 0, skinned = 0, scaled = 0, patch = 0;
  std::set<int> seen;
  std::vector<int> stack(scene.roots.rbegin(), scene.roots.rend());
  while (!stack.empty()) {  // every reachable node once, even in malformed graphs
    const int n = stack.back();
    stack.pop_back();
    if (n < 0 || size_t(n) >= scene.nodes.size() || !seen.insert(n).second) continue;
    const Node& node = scene.nodes[size_t(n)];
    for (auto c = node.children.rbegin(); c != node.children.rend(); ++c) stack.push_back(*c);
    if (node.mesh < 0 || size_t(node.mesh) >= scene.meshes.size()) continue;
    const NodeScale& ns = scale.nodes.size() > size_t(n) ? scale.nodes[size_t(n)] : NodeScale{};
    const bool ownFallback = ns.restNonUniform || ns.restClass == ScaleClass::Negative || ns.shear;
    for (const Primitive& p : scene.meshes[size_t(node.mesh)].primitives) {
      // Bezier patches: (N+1)^2 pattern vertices per patch, through the patch vertex shaders.
      patch += long(p.patchPoints.size() / 16) * long(scene.patchLevel + 1) * long(scene.patchLevel + 1);
      // Instanced nodes (never skinned) run the rigid vertex once per instance.
      const long count = long(p.positions.size()) * long(std::max<size_t>(1, node.instances.size()));
      if (node.skin >= 0 && !p.joints.empty()) skinned += count;
      else {
        rigid += count;
        if (ownFallback) scaled += count;
      }
    }
  }
  // Curved scenes: every instance draws the shared triangle list.
  const long curved = long(scene.curved.positions.size()) * long(scene.curved.instances.size());
  json mix = {{"rigid", rigid}, {"skinned", skinned}, {"scaledFallback", scaled}, {"bezierPatch", patch},
              {"curvedInstance", curved}};
  if (curved > 0) mix["curvedSpace"] = scene.curved.space == Space::Spherical ? "S3" : "H3";
  return mix;
}

void progress(const SceneJob& job, const std::string& what) {
  std::fprintf(stderr, "[%d/%d] %s: %s\n", job.index, job.total, job.input.id.c_str(), what.c_str());
  std::fflush(stderr);
  if (!job.stepFile.empty()) std::ofstream(job.stepFile, std::ios::trunc) << what << "\n";  // the last step, kept
}

std::string stepFileOf(const std::string& resultPath) { return resultPath + ".step"; }

std::string lastStep(const std::string& stepFile) {
  std::ifstream in(stepFile);
  std::string line;
  std::getline(in, line);
  return line;
}

namespace {

// One image time of one animation shown (anim -1: the rest pose).
struct Shot {
  int anim;
  float time;
};

// The animations shown (--anim's choice, else the first; none: the rest pose, anim -1) and
// their image times, written into `out` ("animation", "animations", "times").
struct ShownTimes {
  std::vector<int> anims;
  bool chosen = false;  // --anim chose them
  std::vector<Shot> shots;
};
ShownTimes shownTimes(const SceneJob& job, const Scene& scene, json& out) {
  ShownTimes st;
  st.anims = job.animations;
  st.chosen = !st.anims.empty();
  if (st.anims.empty()) st.anims.push_back(scene.animations.empty() ? -1 : 0);
  json animations = json::array();
  for (int a : st.anims) {
    for (float t : imageTimes(scene, a)) st.shots.push_back({a, t});
    if (a < 0) continue;
    const Animation& an = scene.animations[size_t(a)];
    animations.push_back({{"index", a}, {"name", an.name}, {"duration", an.duration}, {"times", imageTimes(scene, a)}});
  }
  out["animation"] = animations.empty() ? json(nullptr) : json{{"index", animations[0]["index"]},
                                                               {"name", animations[0]["name"]},
                                                               {"duration", animations[0]["duration"]}};
  out["animations"] = animations;
  out["times"] = st.anims.front() < 0 ? json::array({0.0}) : animations[0]["times"];
  return st;
}

// What the frames of a scene add up to per pipeline: conversion times, the first error, and
// the renders tried and written.
struct FrameTally {
  std::map<std::string, std::vector<double>> conversion;
  std::map<std::string, std::string> pipelineError;
  int framesOk = 0, framesTried = 0;
};

// A pipeline's records that do not depend on the time (uploads, vertex fetch, fallbacks, stats,
// draws, skin blend, and the scene's GL device), kept from its first frame; then each fallback
// counter raised to its largest over the frames (they may depend on the pose).
void keepPipelineRecords(const Scene& scene, const std::string& p, const Frame& f, json& out) {
  json& pj = out["pipelines"][p];
  if (!pj.contains("memory")) {  // the uploads do not depend on the time; keep the first
    pj["memory"] = memoryJson(f.stats);
    if (scene.curved.space == Space::Euclidean)  // the GPU vertex stage, not timed
      pj["vertexFetch"] = vertexFetchJson(scene, f.stats);
    pj["fallbacks"] = fallbacksJson(f.stats);
    pj["stats"] = toJson(f.stats);
    pj["draws"] = f.stats.draws;
    pj["skinBlend"] = skinBlendOf(p);
    if (!out.contains("gl"))
      out["gl"] = toJson(f.gl);  // the device record (render_frame.h)
  }
  // Fallbacks counted per render may depend on the pose: keep each counter's largest.
  // (a named json: items() of a temporary would iterate a destroyed object)
  const json fallbacks = fallbacksJson(f.stats);
  for (const auto& [k, v] : fallbacks.items())
    if (v.is_number() && v.get<double>() > pj["fallbacks"].value(k, 0.0)) pj["fallbacks"][k] = v;
}

// Frame k drawn by every pipeline in order, each image written to <rel>t<k>_<p>.png and named in
// `frame` (or its error there and in the tally); returns the images drawn, by pipeline.
std::map<std::string, RgbaImage> renderPipelines(const SceneJob& job, Scene& scene, const FrameSettings& settings,
                                                 const std::string& rel, size_t k, const std::string& when,
                                                 json& frame, json& out, FrameTally& tally) {
  std::map<std::string, RgbaImage> images;
  for (const std::string& p : job.pipelines) {
    ++tally.framesTried;
    progress(job, "rendering " + p + " t=" + when);
    auto f = renderFrame(scene, p, settings);
    if (!f) {
      frame["errors"][p] = f.error();
      tally.pipelineError.emplace(p, f.error());
      progress(job, "FAILED " + p + ": " + f.error());
      continue;
    }
    const std::string file = rel + "t" + std::to_string(k) + "_" + p + ".png";
    Status written = writeImage((fs::path(job.outDir) / file).string(), f->image);
    if (!written) {
      frame["errors"][p] = written.error();
      tally.pipelineError.emplace(p, written.error());
      continue;
    }
    ++tally.framesOk;
    frame["images"][p] = file;
    frame["drawnPixels"][p] = drawnPixels(f->image);  // 0: background only
    tally.conversion[p].push_back(f->stats.conversionMs);
    keepPipelineRecords(scene, p, *f, out);
    images.emplace(p, std::move(f->image));
  }
  return images;
}

// Pipeline p's image of frame k against the baseline's: metrics (with FLIP), the diff heat map
// and FLIP map written beside the images, and compare's drawn-pixel check (a skinned frame of
// another skinning method judged against its own method's reference); all into `frame`.
void compareWithBase(const SceneJob& job, const std::string& p, const std::string& rel, size_t k, bool skinned,
                     std::map<std::string, RgbaImage>& images, OwnMethodJudge& own, json& frame) {
  const std::string& base = job.pipelines.front();
  auto m = compareImages(images[base], images[p]);
  if (!m) {
    frame["errors"]["diff_" + p] = m.error();
    return;
  }
  const std::string file = rel + "t" + std::to_string(k) + "_diff_" + p + ".png";
  Status written = writeImage((fs::path(job.outDir) / file).string(),
                              diffHeatmap(images[base], images[p]));
  if (written) frame["diffs"][p] = file;
  else frame["errors"]["diff_" + p] = written.error();
  auto flip = computeFlip(images[base], images[p]);  // the baseline is FLIP's reference
  if (!flip) {
    frame["errors"]["flip_" + p] = flip.error();
    frame["metrics"][p] = toJson(*m);
  } else {
    frame["metrics"][p] = toJson(*m, *flip);  // the compare command's metrics, FLIP beside PSNR
    const std::string flipFile = rel + "t" + std::to_string(k) + "_flip_" + p + ".png";
    if (Status f = writeImage((fs::path(job.outDir) / flipFile).string(), flipErrorImage(*flip)); f)
      frame["flipMaps"][p] = flipFile;  // beside the diff image
    else
      frame["errors"]["flip_" + p] = f.error();
  }
  // compare's drawn-pixel check: an empty image or counts > 1 % apart marks the frame failed.
  // A skinned frame of another skinning method than the baseline's is judged against its
  // own method's reference instead (skin_judgement.h), as compare judges it.
  const bool methods = skinned && skinMethodsDiffer(base, p);
  DrawnCheck check = checkDrawn(base, images[base], p, images[p], skinned, methods);
  const SkinnedFrameJudgement* j = methods ? own.judge(p, frame) : nullptr;
  if (j && j->judged) {
    check = j->vsReference.drawn;
    check.reason = j->reason;
    check.skinningMethodNote = !check.failed;
  }
  json checkJson = toJson(check);
  checkJson["against"] = j && j->judged ? j->reference : base;  // the image the counts were checked against
  frame["drawnCheck"][p] = checkJson;
}

// Frame k of the shots: its settings (a zero-length animation drawn as the rest pose unless
// --anim chose it), every pipeline's image, and each compared pipeline against the baseline.
json measureFrame(const SceneJob& job, Scene& scene, const ShownTimes& st, size_t k, bool skinned,
                  const std::string& rel, json& out, FrameTally& tally) {
  FrameSettings settings;
  settings.width = job.width, settings.height = job.height;
  // A zero-length animation is drawn as the rest pose unless --anim chose it.
  const int a = st.shots[k].anim;
  if (a >= 0 && (st.chosen || scene.animations[size_t(a)].duration > 0.0f)) settings.anim.anim = a;
  settings.anim.time = st.shots[k].time;
  const std::string when = timeText(st.shots[k].time) + (a >= 0 && (st.chosen || st.anims.size() > 1)
                                                           ? " (" + scene.animations[size_t(a)].name + ")" : "");
  json frame = {{"time", st.shots[k].time}, {"animation", a >= 0 ? json(a) : json(nullptr)},
                {"images", json::object()}, {"diffs", json::object()},
                {"metrics", json::object()}, {"drawnPixels", json::object()}, {"drawnCheck", json::object()},
                {"errors", json::object()}};
  std::map<std::string, RgbaImage> images = renderPipelines(job, scene, settings, rel, k, when, frame, out, tally);
  const std::string& base = job.pipelines.front();
  OwnMethodJudge own(scene, settings, images, [&](const std::string& what) { progress(job, what + " t=" + when); });
  for (size_t i = 1; i < job.pipelines.size() && images.count(base); ++i) {
    const std::string& p = job.pipelines[i];
    if (!images.count(p)) continue;
    compareWithBase(job, p, rel, k, skinned, images, own, frame);
  }
  return frame;
}

// Each pipeline's first error (null when none) and its conversion times (median, min, samples).
void pipelineSummaries(const SceneJob& job, FrameTally& tally, json& out) {
  for (const std::string& p : job.pipelines) {
    json& pj = out["pipelines"][p];
    pj["error"] = tally.pipelineError.count(p) ? json(tally.pipelineError[p]) : json(nullptr);
    if (tally.conversion.count(p)) {
      const auto& c = tally.conversion[p];
      pj["conversionMs"] = {{"median", figures::midpointMedian(c)},
                            {"min", *std::min_element(c.begin(), c.end())},
                            {"samples", c}};
    }
  }
}

}  // namespace

json measureScene(const SceneJob& job) {
  json out = {{"id", job.input.id}, {"spec", job.input.spec}, {"origin", sceneOrigin(job.input.spec)}, {"status", "failed"},
              {"error", nullptr}, {"frames", json::array()}, {"pipelines", json::object()}};
  progress(job, "loading " + job.input.spec);
  auto scene = loadScene(job.input.spec);
  if (scene && scene->curved.space == Space::Euclidean) addGridInstances(*scene, job.instances);
  if (!scene) {
    out["error"] = scene.error();
    out["stats"] = toJson(failedFileStats(job.input.spec, scene.error()));
    progress(job, "FAILED: " + scene.error());
    return out;
  }
  out["source"] = scene->source;
  out["stats"] = toJson(computeFileStats(*scene));
  if (std::string why = whyNothingDrawn(*scene); !why.empty()) {  // listed as not drawn, no blank images
    out["error"] = "nothing to draw: " + why;
    out["notDrawn"] = why;
    progress(job, "NOT DRAWN: " + why);
    return out;
  }
  out["vertexMix"] = vertexMix(*scene);
  out["contentKinds"] = contentKindsJson(*scene);  // the answer's split by kind of content
  if (scene->curved.space == Space::Euclidean) out["overdraw"] = overdrawJson(*scene);  // the mesh alone
  const ShownTimes st = shownTimes(job, *scene, out);
  out["space"] = spaceName(scene->curved.space);
  out["pipelineOrder"] = job.pipelines;

  const std::string rel = "images/" + job.input.id + "/";
  std::error_code ec;
  fs::create_directories(fs::path(job.outDir) / rel, ec);
  if (ec) {
    out["error"] = job.outDir + "/" + rel + ": cannot create folder: " + ec.message();
    return out;
  }
  FrameTally tally;
  const bool skinned = drawsSkinned(*scene);
  for (size_t k = 0; k < st.shots.size(); ++k) {
    json frame = measureFrame(job, *scene, st, k, skinned, rel, out, tally);
    out["frames"].push_back(std::move(frame));
  }
  pipelineSummaries(job, tally, out);
  // One loop per animation shown; "animated" keeps the first's (the schema before --anim).
  for (json& an : out["animations"]) an["animated"] = animatedComparisons(*scene, job, rel, an["index"].get<int>());
  out["animated"] = out["animations"].empty() ? json(nullptr) : out["animations"][0]["animated"];
  out["status"] = tally.framesOk == tally.framesTried ? "ok" : tally.framesOk > 0 ? "partial" : "failed";
  if (tally.framesOk < tally.framesTried && !tally.pipelineError.empty())
    out["error"] = tally.pipelineError.begin()->second;
  progress(job, std::string("done (") + out["status"].get<std::string>() + ")");
  return out;
}

}  // namespace mb::report
