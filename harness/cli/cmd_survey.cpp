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

struct Shot {
  int anim;
  float time;
};

int runSurvey(const std::vector<std::string>& argv) {
  auto fail = [](const std::string& message) { return commandError("survey", message); };
  Args args(argv, OptionSpec{{"size", "pipelines", "gpu", "o", "output", "images"}, {}, {}, {}});
  if (!args.error().empty()) return fail(args.error());
  if (args.positional().size() != 1) return fail("expected one SCENE (a .gltf/.glb file or a built-in name)");
  const std::string spec = args.positional()[0];
  const std::string out = args.get("o", args.get("output", ""));
  const auto [width, height] = args.size("size", 128, 128);
  if (Status ok = applyGpuOption(args); !ok) return fail(ok.error());
  if (args.has("pipelines"))
    if (Status ok = checkPipelineNames("--pipelines", splitList(args.get("pipelines", ""))); !ok) return fail(ok.error());
  if (Status ok = checkSceneSpec(spec); !ok) return fail(ok.error());
  // The outputs before the first render: -o's folder writable, --images created and writable.
  if (!out.empty())
    if (Status ok = prepareOutputFile("-o", out); !ok) return fail(ok.error());
  if (auto images = args.get("images"))
    if (Status ok = prepareOutputFolder("--images", *images, "<pipeline>_<frame>.png"); !ok) return fail(ok.error());

  json doc = {{"file", spec}, {"status", "error"}, {"error", nullptr}, {"size", {width, height}}};
  // Every outcome is written (stdout or -o) before the exit code says it.
  auto finish = [&](int code) {
    const std::string text = doc.dump(1) + "\n";
    if (out.empty()) std::fwrite(text.data(), 1, text.size(), stdout);
    else if (Status w = writeTextFile(out, text); !w) return fail(w.error());
    return code;
  };
  const auto t0 = Clock::now();
  auto loaded = loadScene(spec);
  doc["loadSeconds"] = secondsSince(t0);
  if (!loaded) {
    doc["status"] = "load-failed";
    doc["error"] = loaded.error();
    commandNotes("survey", {"error: " + loaded.error()});
    return finish(2);
  }
  const Scene& scene = *loaded;
  doc["loaderFallbacks"] = loaderFallbackJson(scene);
  const FileStats fs = computeFileStats(scene);
  doc["scene"] = {{"meshes", scene.meshes.size()}, {"primitives", fs.primitives}, {"skinnedPrimitives", fs.skinnedPrimitives},
                  {"animations", scene.animations.size()}};
  if (std::string why = whyNothingDrawn(scene); !why.empty()) {
    doc["status"] = "no-data";
    doc["error"] = "nothing to draw: " + why;
    return finish(0);
  }
  std::vector<std::string> pipelines =
      args.has("pipelines") ? splitList(args.get("pipelines", "")) : pipelineNames(scene.curved.space);
  const std::string baseline = pipelineNames(scene.curved.space).front();
  if (std::find(pipelines.begin(), pipelines.end(), baseline) == pipelines.end()) pipelines.insert(pipelines.begin(), baseline);
  doc["baseline"] = baseline;
  doc["pipelineOrder"] = pipelines;

  // Rest pose, then animation 0 at 1/3 and 2/3 of its duration (its end often equals its start).
  std::vector<Shot> shots = {{-1, 0.0f}};
  if (!scene.animations.empty() && scene.animations[0].duration > 0.0f)
    for (float f : {1.0f / 3.0f, 2.0f / 3.0f}) shots.push_back({0, f * scene.animations[0].duration});
  const bool skinned = drawsSkinned(scene);
  json frames = json::array();
  std::vector<FrameSettings> settings;
  for (const Shot& s : shots) {
    FrameSettings f;
    f.width = width, f.height = height;
    f.anim.anim = s.anim, f.anim.time = s.time;
    settings.push_back(f);
    json fr = {{"animation", s.anim < 0 ? json(nullptr) : json(s.anim)}, {"time", s.time}, {"kind", skinned ? "skinned" : "rigid"}};
    if (!skinned) {  // the bound is judged on rigid frames only (skinned frames: drawn pixels)
      const View view = frameScene(scene, f.anim, float(width) / float(height));
      const PositionBound b = positionBound(scene, f.anim, view, width, height);
      fr["positionBound"] = {{"worldUnits", b.world}, {"pixels", b.pixels}, {"envelopeRadius", b.radius},
                             {"shadeTolerance", kShadeTolerance}};
      fr["view"] = toJson(view);  // the framing the pixel bound was projected with
    }
    frames.push_back(fr);
  }
  doc["frames"] = frames;

  std::vector<RgbaImage> base;  // the baseline's images, one per shot
  std::vector<std::vector<uint8_t>> ties;  // and their tie masks (tieMasks; rigid files)
  // The skinned rule's reference for the motor-blend pipelines (skinned files): the pose skinned
  // on the CPU by the motor blend, drawn by matrix (skin_judgement.h), one image per shot.
  MotorBlendFrames motorBlendBase;
  if (skinned) {
    motorBlendBase = motorBlendReferenceFrames(*loaded, settings);
    doc["motorBlendReference"] = {{"available", motorBlendBase.available()},
                                  {"why", motorBlendBase.available() ? json(nullptr) : json(motorBlendBase.why)}};
    for (size_t k = 0; k < motorBlendBase.images.size(); ++k)
      doc["frames"][k]["motorBlendReference"] = {{"drawnPixels", drawnPixels(motorBlendBase.images[k])}};
  }
  // The 16-byte rule's references (rigid files, made at the first 16-byte pipeline): the
  // baseline's frames in the geometry view and their int16-cell tie masks.
  std::vector<RgbaImage> geometryBase;
  std::vector<std::vector<uint8_t>> int16Ties;
  auto geometryBaseline = [&]() -> Status {
    if (!geometryBase.empty()) return {};
    GeometryView view;
    auto images = drawFromViews(scene, baseline, settings, framings(scene, settings));  // one prepare for every shot
    if (!images) return Status::fail(images.error());
    geometryBase = std::move(*images);
    auto masks = tieMasks(*loaded, baseline, settings, geometryBase, kInt16Ties);
    if (!masks) return Status::fail(masks.error());
    for (size_t k = 0; k < masks->size(); ++k) doc["frames"][k]["int16Ties"] = tieJson((*masks)[k], kInt16Ties);
    int16Ties = std::move(*masks);
    return {};
  };
  json results = json::object();
  bool anyError = false;
  for (const std::string& name : pipelines) {
    const auto tp = Clock::now();
    json r = {{"error", nullptr}, {"frames", json::array()}, {"fallbacks", json::object()}};
    for (size_t k = 0; k < settings.size(); ++k) {
      auto frame = renderFrame(scene, name, settings[k]);
      if (!frame) {
        r["error"] = frame.error();
        commandNotes("survey", {"error: " + frame.error()});
        anyError = true;
        break;
      }
      if (name == baseline) base.push_back(frame->image);
      if (args.has("images")) {  // for a person looking into a row: DIR/<pipeline>_<frame>.png
        const std::string png = args.get("images", ".") + "/" + name + "_" + std::to_string(k) + ".png";
        if (Status w = writeImage(png, frame->image); !w) commandNotes("survey", {"error: " + w.error()});
      }
      json f = {{"drawnPixels", drawnPixels(frame->image)}};
      if (k < base.size() && name != baseline) {
        const std::vector<uint8_t>* tie = k < ties.size() ? &ties[k] : nullptr;  // rigid files only
        auto m = compareImages(base[k], frame->image);
        if (m) {
          f["identical"] = m->rmse == 0.0;
          f["psnr"] = m->rmse == 0.0 ? json(nullptr) : json(m->psnr);
          f["maxError"] = m->maxError;
        }
        if (skinned) {  // judged by its own skinning method (skin_judgement.h); check --rules applies the rule
          const RgbaImage* own = k < motorBlendBase.images.size() ? &motorBlendBase.images[k] : nullptr;
          if (auto j = judgeSkinnedFrame(name, frame->image, base[k], own, motorBlendBase.why, nullptr))
            f["skinJudgement"] = toJson(*j);
          // Every pipeline against the motor-blend reference, the figure corpus-check reads (the
          // linear-blend ones' too: they show the reference is not matrix's method again).
          if (own)
            if (auto mb = compareImages(*own, frame->image))
              f["motorBlend"] = {{"identical", mb->rmse == 0.0}, {"psnr", mb->rmse == 0.0 ? json(nullptr) : json(mb->psnr)}};
        }
        // The same judged outside the tie pixels: those set to the baseline's value.
        if (tie) {
          const std::vector<uint8_t> diff = differingMask(base[k], frame->image);
          RgbaImage masked = frame->image;
          int64_t differing = 0, outside = 0;
          for (size_t i = 0; i < diff.size(); ++i) {
            differing += diff[i];
            if (diff[i] && !(*tie)[i]) ++outside;
            if ((*tie)[i]) std::copy_n(base[k].rgba.begin() + std::ptrdiff_t(i * 4), 4, masked.rgba.begin() + std::ptrdiff_t(i * 4));
          }
          f["differingPixels"] = differing;
          f["differingNotTies"] = outside;  // differing pixels outside the tie set
          if (auto mt = compareImages(base[k], masked)) {
            f["identicalNotTies"] = mt->rmse == 0.0;
            f["psnrNotTies"] = mt->rmse == 0.0 ? json(nullptr) : json(mt->psnr);
          }
        }
        if (hasSixteenByteVertex(name) && frames[k].contains("positionBound")) {  // int16 positions
          // Judged in the geometry view (positions and uv alone), outside the int16-cell ties.
          auto geometry = [&]() -> Result<RgbaImage> {
            if (Status ok = geometryBaseline(); !ok) return Result<RgbaImage>::fail(ok.error());
            GeometryView view;
            auto g = renderFrame(scene, name, settings[k]);
            if (!g) return Result<RgbaImage>::fail(g.error());
            return g->image;
          }();
          if (!geometry) {
            r["error"] = geometry.error();
            commandNotes("survey", {"error: " + geometry.error()});
            anyError = true;
            break;
          }
          const int radius = frames[k]["positionBound"]["envelopeRadius"].get<int>();
          const std::vector<uint8_t>* tie16 = &int16Ties[k];
          // Both ways: a pixel of either image its counterpart's neighbourhood cannot explain.
          const Envelope e1 = envelope(*geometry, geometryBase[k], radius, kShadeTolerance, tie16),
                         e2 = envelope(geometryBase[k], *geometry, radius, kShadeTolerance, tie16);
          f["outsideEnvelope"] = std::max(e1.over, e2.over);
          f["envelopeExcess"] = std::max(e1.worst, e2.worst);  // bytes beyond the neighbourhood
          f["outsideEnvelopeNotTies"] = std::max(e1.overNotTies, e2.overNotTies);  // outside the int16-cell ties
          f["envelopeExcessNotTies"] = std::max(e1.worstNotTies, e2.worstNotTies);
          if (auto gm = compareImages(geometryBase[k], *geometry))
            f["geometryPsnr"] = gm->rmse == 0.0 ? json(nullptr) : json(gm->psnr);
        }
      }
      json fb = fallbackJson(frame->stats), nonzero = json::object();
      for (auto it = fb.begin(); it != fb.end(); ++it)
        if (it.value().get<double>() != 0) nonzero[it.key()] = it.value();
      f["fallbacks"] = nonzero;  // per frame the non-zero counters; the pipeline's maxima list all
      f["draws"] = frame->stats.draws;
      keepMax(r["fallbacks"], fb);
      r["frames"].push_back(f);
      if (k == 0) doc["gl"] = describeGl(frame->gl);
    }
    // The rules that use ties judge rigid frames only: skinned files are not probed.
    if (name == baseline && !skinned && base.size() == settings.size()) {
      auto masks = tieMasks(*loaded, name, settings, base, kFloatTies);  // jitters and restores the positions
      if (!masks) {
        r["error"] = masks.error();
        commandNotes("survey", {"error: " + masks.error()});
        anyError = true;
      } else {
        for (size_t k = 0; k < masks->size(); ++k) doc["frames"][k]["ties"] = tieJson((*masks)[k], kFloatTies);
        ties = std::move(*masks);
      }
    }
    r["seconds"] = secondsSince(tp);
    results[name] = r;
  }
  doc["pipelines"] = results;
  doc["status"] = anyError ? "error" : "ok";
  doc["seconds"] = secondsSince(t0);
  return finish(anyError ? 2 : 0);
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
