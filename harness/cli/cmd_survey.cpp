// motorbench survey FILE [--size WxH] [--pipelines A,B,...] [--gpu ...] [-o out.json]: one file,
// loaded once, drawn by every pipeline of its space on one GL context, at rest and (animated
// files) at 1/3 and 2/3 of animation 0; one JSON document with per pipeline and frame the drawn
// pixels, the image metrics against the space's matrix baseline (rigid files: also outside the
// frame's tie pixels, those the baseline itself draws differently from vertex positions jittered
// by ~1e-6 of their magnitude: survey_probe.h), the fallback counters, the 16-byte pipelines'
// position bound and their envelope test (in the geometry view, outside the pixels the baseline
// draws differently with its positions moved within their int16 cells), skinned frames' figures
// against their own skinning method's reference (skin_judgement.h: "skinJudgement", and the
// motor-blend pipelines' "motorBlend"), and seconds. The worker of `motorbench check --rules`
// (harness/check/corpus_rules.h): it decides nothing (check applies the rules); exit 0 drawn or
// nothing to draw, 2 an error.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <optional>
#include <tuple>

#include <glm/glm.hpp>

#include "harness/cli/command.h"
#include "harness/cli/output_paths.h"
#include "harness/cli/survey_probe.h"
#include "harness/options/args.h"
#include "harness/render/counter_glossary.h"
#include "harness/render/gpu_option.h"
#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "harness/render/skin_judgement.h"
#include "pipelines/gl/context.h"
#include "pipelines/gl/framebuffer.h"
#include "pipelines/pipeline.h"
#include "pipelines/registry.h"
#include "pipelines/scene/animation.h"
#include "pipelines/scene/camera_rule.h"
#include "pipelines/scene/drawable.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"
#include "pipelines/scene/transform.h"

namespace mb {
namespace {

using namespace survey;

using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }


json fallbackJson(const PipelineStats& s) {
  return {{"nonUniformScaleNodes", s.nonUniformScaleNodes}, {"negativeScaleNodes", s.negativeScaleNodes},
          {"shearMatrixNodes", s.shearMatrixNodes}, {"zeroScalarFrames", s.zeroScalarFrames},
          {"biasedFrames", s.biasedFrames}, {"scaleFallbackInstances", s.scaleFallbackInstances},
          {"rotorSplitVertices", s.rotorSplitVertices}, {"rotorUnresolvedTriangles", s.rotorUnresolvedTriangles},
          {"linearFallbackDraws", s.linearFallbackDraws}, {"skinFallbackDraws", s.skinFallbackDraws},
          {"skinFallbackJoints", s.skinFallbackJoints}, {"fallbackVertices", s.fallbackVertices},
          {"morphNotDrawnNodes", s.morphNotDrawnNodes}};
}

// Per counter, the largest value over the frames (each counts "the last render()").
void keepMax(json& into, const json& from) {
  for (auto it = from.begin(); it != from.end(); ++it)
    if (!into.contains(it.key()) || into[it.key()].get<double>() < it.value().get<double>()) into[it.key()] = it.value();
}

// A tie mask as JSON: its pixel count, the probe's renders and the set (pixel indices
// y * width + x, row 0 the top).
json tieJson(const std::vector<uint8_t>& mask, TieProbe probe) {
  std::vector<int64_t> set;
  for (size_t i = 0; i < mask.size(); ++i)
    if (mask[i]) set.push_back(int64_t(i));
  return {{"pixels", set.size()}, {"renders", tieRenders(probe)}, {"set", set}};
}

int surveyError(const std::string& message) { return commandError("survey", message); }

// The command line, checked in this order before the scene is loaded.
struct SurveyOptions {
  std::string spec, out;  // the SCENE; -o (empty: stdout)
  int width = 0, height = 0;
  std::optional<std::vector<std::string>> pipelines;  // --pipelines, when given
  std::optional<std::string> images;                  // --images DIR, when given
};

Result<SurveyOptions> readSurveyOptions(const std::vector<std::string>& argv) {
  auto fail = [](const std::string& message) { return Result<SurveyOptions>::fail(message); };
  options::Args args(argv, options::OptionSpec{{"size", "pipelines", "gpu", "o", "output", "images"}, {}, {}, {}});
  if (!args.error().empty()) return fail(args.error());
  if (args.positional().size() != 1) return fail("expected one SCENE (a .gltf/.glb file or a built-in name)");
  SurveyOptions o;
  o.spec = args.positional()[0];
  o.out = args.get("o", args.get("output", ""));
  std::tie(o.width, o.height) = args.size("size", 128, 128);
  if (Status ok = applyGpuOption(args); !ok) return fail(ok.error());
  if (args.has("pipelines")) {
    o.pipelines = splitList(args.get("pipelines", ""));
    if (Status ok = checkPipelineNames("--pipelines", *o.pipelines); !ok) return fail(ok.error());
  }
  if (Status ok = checkSceneSpec(o.spec); !ok) return fail(ok.error());
  // The outputs before the first render: -o's folder writable, --images created and writable.
  if (!o.out.empty())
    if (Status ok = prepareOutputFile("-o", o.out); !ok) return fail(ok.error());
  o.images = args.get("images");
  if (o.images)
    if (Status ok = prepareOutputFolder("--images", *o.images, "<pipeline>_<frame>.png"); !ok) return fail(ok.error());
  return o;
}

// Writes the document (stdout or -o) and returns `code`: every outcome is written before the
// exit code says it.
int finishSurvey(const json& doc, const std::string& out, int code) {
  const std::string text = doc.dump(1) + "\n";
  if (out.empty()) std::fwrite(text.data(), 1, text.size(), stdout);
  else if (Status w = writeTextFile(out, text); !w) return surveyError(w.error());
  return code;
}

// What the loaded file holds: the loader's fallbacks and its mesh, primitive and animation counts.
void describeScene(json& doc, const Scene& scene) {
  doc["loaderFallbacks"] = loaderFallbackJson(scene);
  const FileStats fs = computeFileStats(scene);
  doc["scene"] = {{"meshes", scene.meshes.size()}, {"primitives", fs.primitives}, {"skinnedPrimitives", fs.skinnedPrimitives},
                  {"animations", scene.animations.size()}};
}

// The pipelines drawn: --pipelines or every one of the scene's space, with the space's matrix
// baseline always among them (put first when it was not asked for).
std::vector<std::string> surveyPipelines(const Scene& scene, const std::optional<std::vector<std::string>>& requested,
                                         const std::string& baseline) {
  std::vector<std::string> pipelines = requested ? *requested : pipelineNames(scene.curved.space);
  if (std::find(pipelines.begin(), pipelines.end(), baseline) == pipelines.end()) pipelines.insert(pipelines.begin(), baseline);
  return pipelines;
}

struct Shot {
  int anim;
  float time;
};

// Rest pose, then animation 0 at 1/3 and 2/3 of its duration (its end often equals its start).
std::vector<Shot> surveyShots(const Scene& scene) {
  std::vector<Shot> shots = {{-1, 0.0f}};
  if (!scene.animations.empty() && scene.animations[0].duration > 0.0f)
    for (float f : {1.0f / 3.0f, 2.0f / 3.0f}) shots.push_back({0, f * scene.animations[0].duration});
  return shots;
}

// Every shot's frame settings and its entry of the document's "frames".
struct FramePlan {
  std::vector<FrameSettings> settings;
  json frames = json::array();
};

FramePlan planFrames(const Scene& scene, int width, int height, bool skinned) {
  FramePlan plan;
  for (const Shot& s : surveyShots(scene)) {
    FrameSettings f;
    f.width = width, f.height = height;
    f.anim.anim = s.anim, f.anim.time = s.time;
    plan.settings.push_back(f);
    json fr = {{"animation", s.anim < 0 ? json(nullptr) : json(s.anim)}, {"time", s.time}, {"kind", skinned ? "skinned" : "rigid"}};
    if (!skinned) {  // the bound is judged on rigid frames only (skinned frames: drawn pixels)
      const View view = frameScene(scene, f.anim, float(width) / float(height));
      const PositionBound b = positionBound(scene, f.anim, view, width, height);
      fr["positionBound"] = {{"worldUnits", b.world}, {"pixels", b.pixels}, {"envelopeRadius", b.radius},
                             {"shadeTolerance", kShadeTolerance}};
      fr["view"] = toJson(view);  // the framing the pixel bound was projected with
    }
    plan.frames.push_back(fr);
  }
  return plan;
}

// One file's survey: what every frame is drawn with and judged against, the references filled
// as the pipelines are drawn.
struct Survey {
  Scene& scene;  // the tie probes jitter its positions and restore them
  std::string baseline;
  bool skinned = false;
  FramePlan plan;
  std::optional<std::string> images;  // --images DIR
  json& doc;
  std::vector<RgbaImage> base;             // the baseline's images, one per shot
  std::vector<std::vector<uint8_t>> ties;  // and their tie masks (tieMasks; rigid files)
  // The skinned rule's reference for the motor-blend pipelines (skinned files): the pose skinned
  // on the CPU by the motor blend, drawn by matrix (skin_judgement.h), one image per shot.
  MotorBlendFrames motorBlendBase;
  // The 16-byte rule's references (rigid files, made at the first 16-byte pipeline): the
  // baseline's frames in the geometry view and their int16-cell tie masks.
  std::vector<RgbaImage> geometryBase;
  std::vector<std::vector<uint8_t>> int16Ties;
};

// Skinned files: the motor-blend reference frames, and in the document whether they could be
// made and the pixels each drew.
void addMotorBlendReference(Survey& s) {
  s.motorBlendBase = motorBlendReferenceFrames(s.scene, s.plan.settings);
  s.doc["motorBlendReference"] = {{"available", s.motorBlendBase.available()},
                                  {"why", s.motorBlendBase.available() ? json(nullptr) : json(s.motorBlendBase.why)}};
  for (size_t k = 0; k < s.motorBlendBase.images.size(); ++k)
    s.doc["frames"][k]["motorBlendReference"] = {{"drawnPixels", drawnPixels(s.motorBlendBase.images[k])}};
}

// The 16-byte rule's references, made once: the baseline's frames in the geometry view and
// their int16-cell tie masks (written to the document's frames).
Status makeGeometryBaseline(Survey& s) {
  if (!s.geometryBase.empty()) return {};
  GeometryView view;
  auto images = drawFromViews(s.scene, s.baseline, s.plan.settings, framings(s.scene, s.plan.settings));  // one prepare for every shot
  if (!images) return Status::fail(images.error());
  s.geometryBase = std::move(*images);
  auto masks = tieMasks(s.scene, s.baseline, s.plan.settings, s.geometryBase, kInt16Ties);
  if (!masks) return Status::fail(masks.error());
  for (size_t k = 0; k < masks->size(); ++k) s.doc["frames"][k]["int16Ties"] = tieJson((*masks)[k], kInt16Ties);
  s.int16Ties = std::move(*masks);
  return {};
}

// A frame against the baseline's: identical, PSNR (null when identical), largest channel error.
void addBaselineMetrics(json& f, const RgbaImage& base, const RgbaImage& image) {
  if (auto m = compareImages(base, image)) {
    f["identical"] = m->rmse == 0.0;
    f["psnr"] = m->rmse == 0.0 ? json(nullptr) : json(m->psnr);
    f["maxError"] = m->maxError;
  }
}

// A skinned frame judged by its own skinning method (skin_judgement.h); check --rules applies the rule.
void addSkinnedFigures(json& f, const Survey& s, const std::string& name, size_t k, const RgbaImage& image) {
  const RgbaImage* own = k < s.motorBlendBase.images.size() ? &s.motorBlendBase.images[k] : nullptr;
  if (auto j = judgeSkinnedFrame(name, image, s.base[k], own, s.motorBlendBase.why, nullptr)) f["skinJudgement"] = toJson(*j);
  // Every pipeline against the motor-blend reference, the figure corpus-check reads (the
  // linear-blend ones' too: they show the reference is not matrix's method again).
  if (own)
    if (auto mb = compareImages(*own, image))
      f["motorBlend"] = {{"identical", mb->rmse == 0.0}, {"psnr", mb->rmse == 0.0 ? json(nullptr) : json(mb->psnr)}};
}

// The frame judged outside the tie pixels: those set to the baseline's value.
void addTieFigures(json& f, const RgbaImage& base, const RgbaImage& image, const std::vector<uint8_t>& tie) {
  const std::vector<uint8_t> diff = differingMask(base, image);
  RgbaImage masked = image;
  int64_t differing = 0, outside = 0;
  for (size_t i = 0; i < diff.size(); ++i) {
    differing += diff[i];
    if (diff[i] && !tie[i]) ++outside;
    if (tie[i]) std::copy_n(base.rgba.begin() + std::ptrdiff_t(i * 4), 4, masked.rgba.begin() + std::ptrdiff_t(i * 4));
  }
  f["differingPixels"] = differing;
  f["differingNotTies"] = outside;  // differing pixels outside the tie set
  if (auto mt = compareImages(base, masked)) {
    f["identicalNotTies"] = mt->rmse == 0.0;
    f["psnrNotTies"] = mt->rmse == 0.0 ? json(nullptr) : json(mt->psnr);
  }
}

// A 16-byte (int16 positions) pipeline's frame judged in the geometry view (positions and uv
// alone), outside the int16-cell ties: the envelope test both ways and the geometry PSNR.
Status addEnvelopeFigures(json& f, Survey& s, const std::string& name, size_t k) {
  auto geometry = [&]() -> Result<RgbaImage> {
    if (Status ok = makeGeometryBaseline(s); !ok) return Result<RgbaImage>::fail(ok.error());
    GeometryView view;
    auto g = renderFrame(s.scene, name, s.plan.settings[k]);
    if (!g) return Result<RgbaImage>::fail(g.error());
    return g->image;
  }();
  if (!geometry) return Status::fail(geometry.error());
  const int radius = s.plan.frames[k]["positionBound"]["envelopeRadius"].get<int>();
  const std::vector<uint8_t>* tie16 = &s.int16Ties[k];
  // Both ways: a pixel of either image its counterpart's neighbourhood cannot explain.
  const Envelope e1 = envelope(*geometry, s.geometryBase[k], radius, kShadeTolerance, tie16),
                 e2 = envelope(s.geometryBase[k], *geometry, radius, kShadeTolerance, tie16);
  f["outsideEnvelope"] = std::max(e1.over, e2.over);
  f["envelopeExcess"] = std::max(e1.worst, e2.worst);  // bytes beyond the neighbourhood
  f["outsideEnvelopeNotTies"] = std::max(e1.overNotTies, e2.overNotTies);  // outside the int16-cell ties
  f["envelopeExcessNotTies"] = std::max(e1.worstNotTies, e2.worstNotTies);
  if (auto gm = compareImages(s.geometryBase[k], *geometry)) f["geometryPsnr"] = gm->rmse == 0.0 ? json(nullptr) : json(gm->psnr);
  return {};
}

// Every figure of a non-baseline pipeline's frame k against the baseline's frame k.
Status judgeAgainstBaseline(json& f, Survey& s, const std::string& name, size_t k, const RgbaImage& image) {
  addBaselineMetrics(f, s.base[k], image);
  if (s.skinned) addSkinnedFigures(f, s, name, k, image);
  if (k < s.ties.size()) addTieFigures(f, s.base[k], image, s.ties[k]);  // rigid files only
  if (hasSixteenByteVertex(name) && s.plan.frames[k].contains("positionBound"))
    if (Status ok = addEnvelopeFigures(f, s, name, k); !ok) return ok;
  return {};
}

// One drawn frame's figures and all its fallback counters (the pipeline keeps their maxima).
struct FrameFigures {
  json figures;
  json fallbacks;
};

Result<FrameFigures> surveyFrame(Survey& s, const std::string& name, size_t k) {
  auto frame = renderFrame(s.scene, name, s.plan.settings[k]);
  if (!frame) return Result<FrameFigures>::fail(frame.error());
  if (name == s.baseline) s.base.push_back(frame->image);
  if (s.images) {  // for a person looking into a row: DIR/<pipeline>_<frame>.png
    const std::string png = *s.images + "/" + name + "_" + std::to_string(k) + ".png";
    if (Status w = writeImage(png, frame->image); !w) commandNotes("survey", {"error: " + w.error()});
  }
  json f = {{"drawnPixels", drawnPixels(frame->image)}};
  if (k < s.base.size() && name != s.baseline)
    if (Status ok = judgeAgainstBaseline(f, s, name, k, frame->image); !ok) return Result<FrameFigures>::fail(ok.error());
  json fb = fallbackJson(frame->stats), nonzero = json::object();
  for (auto it = fb.begin(); it != fb.end(); ++it)
    if (it.value().get<double>() != 0) nonzero[it.key()] = it.value();
  f["fallbacks"] = nonzero;  // per frame the non-zero counters; the pipeline's maxima list all
  f["draws"] = frame->stats.draws;
  if (k == 0) s.doc["gl"] = describeGl(frame->gl);
  return FrameFigures{f, fb};
}

// An error of a pipeline: in its JSON and on stderr.
void recordError(json& r, const std::string& message) {
  r["error"] = message;
  commandNotes("survey", {"error: " + message});
}

// The baseline of a rigid file, every frame drawn: the float tie masks the other pipelines'
// frames are judged outside of (the rules that use ties judge rigid frames only).
void addFloatTies(Survey& s, json& r) {
  auto masks = tieMasks(s.scene, s.baseline, s.plan.settings, s.base, kFloatTies);  // jitters and restores the positions
  if (!masks) return recordError(r, masks.error());
  for (size_t k = 0; k < masks->size(); ++k) s.doc["frames"][k]["ties"] = tieJson((*masks)[k], kFloatTies);
  s.ties = std::move(*masks);
}

// One pipeline's JSON: its frames (the first error ends them), its fallback maxima, its seconds.
json surveyPipeline(Survey& s, const std::string& name) {
  const auto tp = Clock::now();
  json r = {{"error", nullptr}, {"frames", json::array()}, {"fallbacks", json::object()}};
  for (size_t k = 0; k < s.plan.settings.size(); ++k) {
    auto frame = surveyFrame(s, name, k);
    if (!frame) {
      recordError(r, frame.error());
      break;
    }
    keepMax(r["fallbacks"], frame->fallbacks);
    r["frames"].push_back(frame->figures);
  }
  if (name == s.baseline && !s.skinned && s.base.size() == s.plan.settings.size()) addFloatTies(s, r);
  r["seconds"] = secondsSince(tp);
  return r;
}

int runSurvey(const std::vector<std::string>& argv) {
  auto options = readSurveyOptions(argv);
  if (!options) return surveyError(options.error());
  const SurveyOptions& o = *options;
  json doc = {{"file", o.spec}, {"status", "error"}, {"error", nullptr}, {"size", {o.width, o.height}}};
  const auto t0 = Clock::now();
  auto loaded = loadScene(o.spec);
  doc["loadSeconds"] = secondsSince(t0);
  if (!loaded) {
    doc["status"] = "load-failed";
    doc["error"] = loaded.error();
    commandNotes("survey", {"error: " + loaded.error()});
    return finishSurvey(doc, o.out, 2);
  }
  Scene& scene = *loaded;
  describeScene(doc, scene);
  if (std::string why = whyNothingDrawn(scene); !why.empty()) {
    doc["status"] = "no-data";
    doc["error"] = "nothing to draw: " + why;
    return finishSurvey(doc, o.out, 0);
  }
  const std::string baseline = pipelineNames(scene.curved.space).front();
  const std::vector<std::string> pipelines = surveyPipelines(scene, o.pipelines, baseline);
  doc["baseline"] = baseline;
  doc["pipelineOrder"] = pipelines;
  const bool skinned = drawsSkinned(scene);
  Survey s{scene, baseline, skinned, planFrames(scene, o.width, o.height, skinned), o.images, doc};
  doc["frames"] = s.plan.frames;
  if (skinned) addMotorBlendReference(s);

  json results = json::object();
  bool anyError = false;
  for (const std::string& name : pipelines) {
    json r = surveyPipeline(s, name);
    anyError = anyError || !r["error"].is_null();
    results[name] = r;
  }
  doc["pipelines"] = results;
  doc["status"] = anyError ? "error" : "ok";
  doc["seconds"] = secondsSince(t0);
  return finishSurvey(doc, o.out, anyError ? 2 : 0);
}

}  // namespace
}  // namespace mb

MB_COMMAND(survey, "survey",
           "SCENE [--size WxH (default 128x128)] [--pipelines A,B,...] [--gpu auto|llvmpipe|N] [--images DIR] [-o out.json]",
           "draw one file with every pipeline of its space at rest and two animation times; print one JSON "
           "document (drawn pixels, metrics against matrix, tie pixels, fallbacks, the 16-byte position bound, seconds): "
           "the worker of check --rules",
           mb::runSurvey);
MB_COMMAND_HELP(survey, "survey",
               "  SCENE              a .gltf/.glb file or a built-in scene name\n"
               "  --size WxH         image size (default 128x128)\n"
               "  --pipelines A,...  the pipelines (default: every one of the scene's space; its matrix baseline is always drawn)\n"
               "  -o, --output FILE  the JSON document (default: stdout)\n"
               "  --images DIR       also write every frame as DIR/<pipeline>_<frame>.png (created; default: none)\n"
               MB_GPU_OPTION_HELP
               "  Exit 0: drawn (or nothing to draw: status no-data), 2: the file did not load or a pipeline failed (reasons in the JSON).\n",
               "motorbench survey skinned_tube --size 96x96 -o out/tube.json", true);
