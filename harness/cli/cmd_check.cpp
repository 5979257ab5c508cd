// motorbench check [--golden DIR] [--scenes a,b] [--pipelines p,q] [--out DIR]
//   [--shader-dir DIR] [--update]
// Re-renders every golden image (built-in scene x pose x registered pipeline, golden.h) and
// compares it with the committed one under the scene's thresholds; writes actual, expected and
// diff images of every failure and warning plus summary.html and check.json into --out.
// Exit 0 pass (warnings allowed), 1 a threshold exceeded, 2 error (a missing golden names the
// file). --update re-renders the selection into --golden and rewrites golden.json (keeping its
// thresholds). --shader-dir runs against a modified copy of shaders/ (sets MB_SHADER_DIR).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <set>

#include "harness/options/args.h"
#include "harness/options/shard.h"
#include "harness/process/progress.h"
#include "harness/check/check_report.h"
#include "harness/cli/command.h"
#include "harness/cli/output_paths.h"
#include "harness/check/golden.h"
#include "harness/check/golden_device.h"
#include "harness/render/flip.h"
#include "harness/render/gpu_option.h"
#include "harness/render/render_frame.h"
#include "pipelines/gl/context.h"
#include "pipelines/gl/shader_source.h"
#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/curved_space.h"
#include "pipelines/scene/loader.h"

namespace mb {
namespace {

namespace fs = std::filesystem;
using Outcome = CheckItem::Outcome;

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

struct Selection {
  std::vector<std::string> scenes, pipelines;
  std::string goldenDir, outDir;
  // The device's goldens (golden_device.h): which folder goldenDir is, and the llvmpipe one.
  golden::GoldenChoice goldens;
  std::string llvmpipeGoldenDir;
  std::string renderer, drawnOn;  // GL_RENDERER; the same with the device (describeGl)
  Shard shard;  // --shard I/N: this run checks its part of `scenes` only
};

// The selected pipelines that draw `scene`'s space (glTF pipelines for glTF scenes, s3_* for
// s3_tiling, ...): a curved pipeline has no golden of a glTF scene and the other way round.
std::vector<std::string> pipelinesFor(const Scene& scene, const Selection& sel) {
  const std::vector<std::string> own = pipelineNames(scene.curved.space);
  std::vector<std::string> out;
  for (const std::string& p : sel.pipelines)
    if (std::find(own.begin(), own.end(), p) != own.end()) out.push_back(p);
  return out;
}

// Compares one planned golden; fills `item` (and writes its images into outDir unless clean).
void checkOne(const Scene& scene, const golden::Manifest& manifest,
              const golden::SceneThresholds& thresholds, const Selection& sel, CheckRun& run,
              std::set<std::string>& rendererNotes, CheckItem& item) {
  auto error = [&](const std::string& why) { item.outcome = Outcome::Error; item.reason = why; };
  const std::string goldenPath = (fs::path(sel.goldenDir) / item.file).string();
  const golden::Entry* entry = manifest.find(item.file);
  if (!entry) return error(goldenPath + ": not in " + golden::kManifest + " (missing golden; run check --update)");
  if (!fs::exists(goldenPath)) return error(goldenPath + ": missing golden image (run check --update)");
  auto expected = readImage(goldenPath);
  if (!expected) return error(expected.error());
  if (expected->width != entry->settings.width || expected->height != entry->settings.height)
    return error(goldenPath + ": size differs from the one golden.json records");
  auto frame = renderFrame(scene, item.pipeline, entry->settings);
  if (!frame) return error(frame.error());
  if (run.glRenderer.empty()) {
    run.glRenderer = frame->glRenderer;
    run.glVersion = frame->glVersion;
  }
  // A device compared with llvmpipe's goldens is never judged by the exact thresholds.
  const bool exact = sel.goldens.source != golden::GoldenSource::LlvmpipeForDevice &&
                     golden::rendererMatches(*entry, frame->glRenderer, frame->glVersion);
  const golden::Level& level = exact ? thresholds.exact : thresholds.portable;
  item.level = exact ? "exact" : "portable";
  if (!exact) {
    std::string note = "GL differs from the goldens' (recorded '" + entry->glRenderer + "' / '" +
                       entry->glVersion + "', running '" + frame->glRenderer + "' / '" +
                       frame->glVersion + "'): portable thresholds apply";
    if (rendererNotes.insert(note).second) run.notes.push_back(note);
  }
  auto metrics = compareImages(*expected, frame->image);
  if (!metrics) return error(metrics.error());
  item.compared = true;
  item.metrics = *metrics;
  auto flip = computeFlip(*expected, frame->image);  // the golden is the reference
  if (!flip) return error(flip.error());
  item.flip = *flip;
  item.flip.error.clear();  // the summary is kept; the map is written below for a failure
  Verdict failed = judge(*expected, frame->image, level.fail);
  Thresholds warnAt{level.warn, level.warnPercent, std::numeric_limits<double>::infinity()};
  Verdict warned = judge(*expected, frame->image, warnAt);
  if (failed.failed) {
    item.outcome = Outcome::Fail;
    item.reason = failed.reason;
  } else if (warned.failed) {
    item.outcome = Outcome::Warn;
    item.reason = "within thresholds, but " + warned.reason;
  }
  if (item.outcome == Outcome::Pass) return;
  const std::string stem = item.file.substr(0, item.file.size() - 4);
  item.expected = stem + ".expected.png";
  item.actual = stem + ".actual.png";
  item.diff = stem + ".diff.png";
  for (auto [name, img] : {std::pair{&item.expected, &*expected}, std::pair{&item.actual, &frame->image}}) {
    Status s = writeImage((fs::path(sel.outDir) / *name).string(), *img);
    if (!s) return error(s.error());
  }
  Status d = writeImage((fs::path(sel.outDir) / item.diff).string(), diffHeatmap(*expected, frame->image));
  if (!d) return error(d.error());
  item.flipMap = stem + ".flip.png";
  if (Status f = writeImage((fs::path(sel.outDir) / item.flipMap).string(), flipErrorImage(*flip)); !f)
    return error(f.error());
}

int check(const Selection& sel) {
  const std::string manifestPath = (fs::path(sel.goldenDir) / golden::kManifest).string();
  auto manifest = golden::readManifest(manifestPath);
  if (!manifest) return commandError("check", manifest.error());
  std::error_code ec;
  fs::create_directories(sel.outDir, ec);
  if (ec) return commandError("check", sel.outDir + ": cannot create folder: " + ec.message());
  // Images of an earlier run would pass for this run's failures: remove them (only ours).
  for (const auto& f : fs::directory_iterator(sel.outDir, ec)) {
    const std::string n = f.path().filename().string();
    for (const char* suffix : {".actual.png", ".expected.png", ".diff.png", ".flip.png"})
      if (n.size() > std::strlen(suffix) && n.ends_with(suffix)) fs::remove(f.path(), ec);
  }
  CheckRun run;
  run.goldenDir = sel.goldenDir;
  const bool againstLlvmpipe = sel.goldens.source == golden::GoldenSource::LlvmpipeForDevice;
  if (againstLlvmpipe)
    run.notes.push_back(golden::describeChoice(sel.goldens, sel.llvmpipeGoldenDir, sel.renderer, sel.drawnOn));
  run.shaderDir = gl::shaderDir();
  run.shard = {{"index", sel.shard.index}, {"count", sel.shard.count}, {"inputs", sel.scenes}};
  std::vector<std::string> mine;
  for (size_t k : shardPositions(sel.scenes, sel.shard)) mine.push_back(sel.scenes[k]);
  if (const std::string note = emptyShardNote(sel.shard, sel.scenes.size(), mine.size()); !note.empty())
    commandNotes("check", {note});
  std::set<std::string> rendererNotes, planned;
  Progress progress("check", "scenes checked", mine.size(), false);
  for (const std::string& name : mine) {
    auto scene = loadScene(name);
    golden::SceneThresholds thresholds = golden::defaultThresholds(name);
    if (auto t = manifest->thresholds.find(name); t != manifest->thresholds.end()) thresholds = t->second;
    else run.notes.push_back(name + ": no thresholds in golden.json, using the defaults");
    if (!scene) {
      run.items.push_back({name, name, "", "", Outcome::Error, "", false, {}, scene.error(), "", "", ""});
      std::printf("%s\n", consoleLine(run.items.back()).c_str());
      progress.done(name + ": error");
      continue;
    }
    for (const golden::Pose& pose : golden::posesFor(*scene)) {
      for (const std::string& pipeline : pipelinesFor(*scene, sel)) {
        CheckItem item;
        item.file = golden::fileName(name, pose.name, pipeline);
        item.scene = name;
        item.pipeline = pipeline;
        item.pose = pose.name;
        planned.insert(item.file);
        checkOne(*scene, *manifest, thresholds, sel, run, rendererNotes, item);
        std::printf("%s\n", consoleLine(item).c_str());
        std::fflush(stdout);
        run.items.push_back(std::move(item));
      }
    }
    progress.done(name);
  }
  std::set<std::string> scenes(mine.begin(), mine.end());
  std::set<std::string> pipelines(sel.pipelines.begin(), sel.pipelines.end());
  for (const golden::Entry& e : manifest->entries)
    if (scenes.count(e.scene) && pipelines.count(e.pipeline) && !planned.count(e.file))
      run.notes.push_back(e.file + ": in golden.json but no longer planned (stale; --update removes it)");

  Status written = writeCheckReport(sel.outDir, run);
  int counts[4] = {0, 0, 0, 0};
  for (const CheckItem& it : run.items) ++counts[int(it.outcome)];
  for (const std::string& n : run.notes) std::printf("warning: %s\n", n.c_str());
  std::printf("check: %zu images: %d passed, %d warned, %d failed, %d errors\n", run.items.size(),
              counts[0], counts[1], counts[2], counts[3]);
  if (againstLlvmpipe && counts[2] > 0)
    std::printf("note: %d of %zu images exceed the device-tolerant thresholds against llvmpipe's goldens: a device "
                "difference or a real regression; look at the diffs in summary.html, and where this device is right "
                "keep its own goldens with `check --update` on it\n",
                counts[2], run.items.size());
  if (!written) return commandError("check", written.error());
  std::printf("report: %s\n", (fs::path(sel.outDir) / "summary.html").string().c_str());
  if (counts[3] > 0) return 2;
  return counts[2] > 0 ? 1 : 0;
}

int update(const Selection& sel) {
  auto fail = [](const std::string& message) { return commandError("check --update", message); };
  const std::string manifestPath = (fs::path(sel.goldenDir) / golden::kManifest).string();
  golden::Manifest old;
  // Keep its thresholds and the images outside the selection; a device's first goldens start
  // from the thresholds of llvmpipe's.
  const std::string thresholdsFrom = fs::exists(manifestPath) || sel.llvmpipeGoldenDir.empty()
                                         ? manifestPath
                                         : (fs::path(sel.llvmpipeGoldenDir) / golden::kManifest).string();
  if (fs::exists(thresholdsFrom)) {
    auto m = golden::readManifest(thresholdsFrom);
    if (!m) return fail(m.error() + " (fix or delete it; --update does not discard thresholds silently)");
    old = m.take();
    if (thresholdsFrom != manifestPath) old.entries.clear();
  }
  std::error_code ec;
  fs::create_directories(sel.goldenDir, ec);
  if (ec) return fail(sel.goldenDir + ": cannot create folder: " + ec.message());
  std::set<std::string> scenes(sel.scenes.begin(), sel.scenes.end());
  std::set<std::string> pipelines(sel.pipelines.begin(), sel.pipelines.end());
  golden::Manifest next;
  next.thresholds = old.thresholds;
  for (const golden::Entry& e : old.entries)
    if (!scenes.count(e.scene) || !pipelines.count(e.pipeline)) next.entries.push_back(e);
  int changed = 0, same = 0;
  for (const std::string& name : sel.scenes) {
    auto scene = loadScene(name);
    if (!scene) return fail(scene.error());
    if (!next.thresholds.count(name)) next.thresholds[name] = golden::defaultThresholds(name);
    for (const golden::Pose& pose : golden::posesFor(*scene)) {
      for (const std::string& pipeline : pipelinesFor(*scene, sel)) {
        golden::Entry e;
        e.file = golden::fileName(name, pose.name, pipeline);
        e.scene = name;
        e.pipeline = pipeline;
        e.pose = pose.name;
        e.settings.anim = pose.anim;
        e.settings.width = golden::kWidth;
        e.settings.height = golden::kHeight;
        auto frame = renderFrame(*scene, pipeline, e.settings);
        if (!frame) return fail(frame.error());
        e.glRenderer = frame->glRenderer;
        e.glVersion = frame->glVersion;
        e.glBackend = frame->glBackend;
        e.view = toJson(frame->view);
        const std::string path = (fs::path(sel.goldenDir) / e.file).string();
        auto before = fs::exists(path) ? readImage(path) : Result<RgbaImage>::fail("");
        bool unchanged = before && before->width == frame->image.width &&
                         before->height == frame->image.height && before->rgba == frame->image.rgba;
        Status s = writeImage(path, frame->image);
        if (!s) return fail(s.error());
        std::printf("%s  %s\n", unchanged ? "same   " : "written", path.c_str());
        (unchanged ? same : changed)++;
        next.entries.push_back(std::move(e));
      }
    }
  }
  // Images of the selection that the plan no longer makes are stale: remove them.
  for (const golden::Entry& e : old.entries)
    if (scenes.count(e.scene) && pipelines.count(e.pipeline) && !next.find(e.file)) {
      fs::remove(fs::path(sel.goldenDir) / e.file, ec);
      std::printf("removed  %s (no longer planned)\n", (fs::path(sel.goldenDir) / e.file).string().c_str());
    }
  std::sort(next.entries.begin(), next.entries.end(),
            [](const golden::Entry& a, const golden::Entry& b) { return a.file < b.file; });
  Status w = golden::writeManifest(manifestPath, next);
  if (!w) return fail(w.error());
  std::printf("update: %d images changed, %d unchanged; %s rewritten\n", changed, same, manifestPath.c_str());
  return 0;
}

int runCheck(const std::vector<std::string>& argv) {
  Args args(argv, {{"golden", "scenes", "pipelines", "out", "o", "shader-dir", "shard", "gpu"}, {"update"}, {}});
  auto fail = [](const std::string& message) { return commandError("check", message); };
  if (!args.error().empty()) return fail(args.error());
  if (!args.positional().empty()) return fail("unexpected argument '" + args.positional()[0] + "'");
  if (Status gpu = applyGpuOption(args); !gpu) return fail(gpu.error());
  Selection sel;
  sel.goldenDir = args.get("golden", "tests/golden");
  sel.outDir = args.get("out", args.get("o", "out/check"));
  if (auto dir = args.get("shader-dir")) {
    if (!fs::is_directory(*dir)) return fail("--shader-dir " + *dir + ": not a folder");
    // shaderDir() reads MB_SHADER_DIR on every load, so this redirects every pipeline.
    ::setenv("MB_SHADER_DIR", fs::absolute(*dir).string().c_str(), 1);
  }
  std::vector<std::string> builtins = builtinSceneNames();  // glTF built-ins, golden-only ones, curved ones
  for (const std::string& g : goldenOnlySceneNames()) builtins.push_back(g);
  for (const std::string& c : curvedSceneNames()) builtins.push_back(c);
  sel.scenes = args.has("scenes") ? splitList(args.get("scenes", "")) : builtins;
  for (const std::string& s : sel.scenes)
    if (!isBuiltinScene(s))
      return fail("--scenes: '" + s + "' is not a built-in scene (" + joined(builtins) + ")");
  // Each scene is drawn by the selected pipelines of its space (pipelinesFor).
  std::vector<std::string> requested =
      args.has("pipelines") ? splitList(args.get("pipelines", "")) : allPipelineNames();
  const std::vector<std::string> registered = allPipelineNames();
  for (const std::string& p : requested) {
    if (std::find(registered.begin(), registered.end(), p) == registered.end())
      return fail("--pipelines: unknown pipeline '" + p + "' (registered: " + joined(registered) + ")");
    if (!createPipeline(p)) {  // registered placeholder: nothing to render yet
      std::printf("note: pipeline '%s' is a placeholder; skipped\n", p.c_str());
      continue;
    }
    sel.pipelines.push_back(p);
  }
  if (sel.scenes.empty() || sel.pipelines.empty()) return fail("nothing selected (no scenes or pipelines)");
  if (auto text = args.get("shard")) {
    if (args.has("update")) return fail("--shard checks; --update writes every golden in one run");
    std::string error;
    auto shard = parseShard(*text, &error);
    if (!shard) return fail(error);
    sel.shard = *shard;
  }
  // The default --golden is relative to the repository root. Elsewhere, point to --golden
  // instead of letting --update create goldens in the wrong place (or suggesting it).
  if (!args.has("golden") && !fs::exists(fs::path("tests/golden") / golden::kManifest))
    return fail("tests/golden/" + std::string(golden::kManifest) + " not found under " + fs::current_path().string() +
                ": run check from the repository root, or pass --golden DIR (the folder holding " +
                golden::kManifest + ", e.g. --golden /path/to/motorbench/tests/golden)");
  // A --golden folder without golden.json is the wrong folder: --update there would make a golden
  // set of this renderer's own images, so the check would compare the renderer with itself.
  if (args.has("golden") && !args.has("update") && !fs::exists(fs::path(sel.goldenDir) / golden::kManifest))
    return fail("--golden " + sel.goldenDir + ": not a golden folder (no " + golden::kManifest +
                " there). A golden folder holds " + golden::kManifest +
                " (the thresholds and the list of images with the GL renderer that made them) and one PNG per "
                "scene, pose and pipeline, e.g. tests/golden of the motorbench repository; pass that folder. "
                "Do not make one here with --update: goldens rendered by the renderer under test would "
                "compare it with itself");
  // The output folder before the first render (checking writes there; --update does not).
  if (!args.has("update"))
    if (Status ok = prepareOutputFolder("--out", sel.outDir, "images of failures and warnings, summary.html, check.json"); !ok)
      return fail(ok.error());
  // Which goldens this device is checked against (or, updating, writes): golden_device.h.
  auto ctx = gl::sharedContext();
  if (!ctx) return fail(ctx.error());
  sel.renderer = (*ctx)->info().renderer;
  sel.drawnOn = describeGl((*ctx)->info());
  sel.llvmpipeGoldenDir = sel.goldenDir;
  const bool devicePresent =
      fs::exists(fs::path(golden::deviceGoldenDir(sel.goldenDir, sel.renderer)) / golden::kManifest);
  sel.goldens = golden::chooseGoldens(sel.goldenDir, sel.renderer, devicePresent, args.has("update"));
  sel.goldenDir = sel.goldens.dir;
  std::printf("%s\n", golden::describeChoice(sel.goldens, sel.llvmpipeGoldenDir, sel.renderer, sel.drawnOn).c_str());
  return args.has("update") ? update(sel) : check(sel);
}

}  // namespace
}  // namespace mb

MB_COMMAND(check, "check",
           "[--golden DIR] [--scenes a,b] [--pipelines p,q] [--out DIR] [--shader-dir DIR] [--update] [--shard I/N] "
           "[--gpu auto|llvmpipe|N]",
           "compare renders with the golden images (exit 1 on a threshold, 2 on a missing golden)",
           mb::runCheck);
MB_COMMAND_HELP(check, "check",
               "  --golden DIR       the golden folder: golden.json + one PNG per scene, pose and pipeline\n"
               "                     (default tests/golden from the repository root)\n"
               "  --scenes a,b       only these scenes;  --pipelines p,q  only these pipelines\n"
               "  --out DIR          actual, expected and diff images of failures, summary.html, check.json\n"
               "  --update           re-render the selection into --golden and rewrite golden.json\n"
               "  --shader-dir DIR   run against a modified copy of shaders/\n"
               "  --shard I/N        only every N-th golden from the I-th\n"
               MB_GPU_OPTION_HELP,
                "motorbench check --scenes normal_torus --out out/check", true);
