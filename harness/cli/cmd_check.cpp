// motorbench check [--golden DIR] [--scenes a,b] [--pipelines p,q] [--out DIR]
//   [--shader-dir DIR] [--update]
// Re-renders every golden image (built-in scene x pose x registered pipeline, golden.h) and
// compares it with the committed one under the scene's thresholds; writes actual, expected and
// diff images of every failure and warning plus summary.html and check.json into --out.
// Exit 0 pass (warnings allowed), 1 a threshold exceeded, 2 error (a missing golden names the
// file). --update re-renders the selection into --golden and rewrites golden.json (keeping its
// thresholds). --shader-dir runs against a modified copy of shaders/ (sets MB_SHADER_DIR).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>
#include <set>

#include "harness/options/args.h"
#include "harness/options/shard.h"
#include "harness/process/progress.h"
#include "harness/check/check_report.h"
#include "harness/cli/command.h"
#include "harness/cli/output_paths.h"
#include "harness/check/check_inputs.h"
#include "harness/check/content_hash.h"
#include "harness/check/corpus_rules.h"
#include "harness/check/golden.h"
#include "harness/check/golden_device.h"
#include "harness/check/junit.h"
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
using check::ChangedSource;
using check::CheckItem;
using check::CheckRun;
using Outcome = CheckItem::Outcome;

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

struct Selection {
  std::vector<check::CheckInput> inputs;  // built-in scenes and users' files (check_inputs.h)
  std::vector<std::string> pipelines;
  std::string goldenDir, outDir, junitPath;
  bool quiet = false;  // only failures, errors, changed files and the summary line
  // The device's goldens (golden_device.h): which folder goldenDir is, and the llvmpipe one.
  check::GoldenChoice goldens;
  std::string llvmpipeGoldenDir;
  std::string renderer, drawnOn;  // GL_RENDERER; the same with the device (describeGl)
  options::Shard shard;  // --shard I/N: this run checks its part of `inputs` only
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

// Built-ins keep every animation (each shows a case); a user's file its first one.
std::vector<check::Pose> posesOf(const Scene& scene, const check::CheckInput& input) {
  return check::posesFor(scene, input.file ? check::kMaxFileAnimations : check::kMaxAnimations);
}

// Compares one planned golden; fills `item` (and writes its images into outDir unless clean).
void checkOne(const Scene& scene, const check::Manifest& manifest,
              const check::SceneThresholds& thresholds, const Selection& sel, CheckRun& run,
              std::set<std::string>& rendererNotes, CheckItem& item) {
  auto error = [&](const std::string& why) { item.outcome = Outcome::Error; item.reason = why; };
  const std::string goldenPath = (fs::path(sel.goldenDir) / item.file).string();
  const check::Entry* entry = manifest.find(item.file);
  if (!entry) return error(goldenPath + ": not in " + check::kManifest + " (missing golden; run check --update)");
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
  const bool exact = sel.goldens.source != check::GoldenSource::LlvmpipeForDevice &&
                     check::rendererMatches(*entry, frame->glRenderer, frame->glVersion);
  const check::Level& level = exact ? thresholds.exact : thresholds.portable;
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

// A console line of the run: everything, or with --quiet only what fails the run.
void printItem(const Selection& sel, const CheckItem& item) {
  if (sel.quiet && (item.outcome == Outcome::Pass || item.outcome == Outcome::Warn)) return;
  std::printf("%s\n", check::consoleLine(item).c_str());
  std::fflush(stdout);
}

CheckItem planned(const check::CheckInput& input, const std::string& pose, const std::string& pipeline) {
  CheckItem item;
  item.file = check::fileName(input.scene, pose, pipeline);
  item.scene = input.scene;
  item.source = input.shown;
  item.pipeline = pipeline;
  item.pose = pose;
  return item;
}

// A user's file whose bytes differ from those its goldens were made from: each of its goldens
// (golden.json's, for the selected pipelines) is recorded as not judged. False when the file
// is unchanged (or has no recorded hash: a folder of goldens made before hashes were kept).
bool recordIfChanged(const check::CheckInput& input, const check::ContentHash& now, const check::Manifest& manifest,
                     const Selection& sel, CheckRun& run) {
  const auto recorded = manifest.sources.find(input.scene);
  if (recorded == manifest.sources.end() || recorded->second.sha256 == now.sha256) return false;
  ChangedSource changed{input.scene, input.shown, recorded->second.sha256, now.sha256, 0};
  for (const check::Entry& e : manifest.entries) {
    if (e.scene != input.scene || std::find(sel.pipelines.begin(), sel.pipelines.end(), e.pipeline) == sel.pipelines.end())
      continue;
    CheckItem item = planned(input, e.pose, e.pipeline);
    item.outcome = Outcome::Changed;
    item.reason = input.shown + " changed since its goldens were recorded: not judged (run check --update)";
    run.items.push_back(std::move(item));
    ++changed.images;
  }
  std::printf("%s\n", check::changedLine(changed).c_str());
  run.changed.push_back(std::move(changed));
  return true;
}

// Checks every planned golden of one input into `run`.
void checkInput(const check::CheckInput& input, const check::Manifest& manifest, const Selection& sel, CheckRun& run,
                std::set<std::string>& rendererNotes, std::set<std::string>& plannedFiles) {
  check::SceneThresholds thresholds = check::defaultThresholds(input.scene);
  if (auto t = manifest.thresholds.find(input.scene); t != manifest.thresholds.end()) thresholds = t->second;
  else if (!input.file) run.notes.push_back(input.scene + ": no thresholds in golden.json, using the defaults");
  auto errorItem = [&](const std::string& why) {
    CheckItem item = planned(input, "", "");
    item.file = input.scene;
    item.outcome = Outcome::Error;
    item.reason = why;
    printItem(sel, item);
    run.items.push_back(std::move(item));
  };
  if (input.file) {
    auto hash = check::contentHash(input.spec);
    if (!hash) return errorItem(hash.error());
    if (recordIfChanged(input, *hash, manifest, sel, run)) return;
  }
  auto scene = loadScene(input.spec);
  if (!scene) return errorItem(scene.error());
  for (const check::Pose& pose : posesOf(*scene, input)) {
    for (const std::string& pipeline : pipelinesFor(*scene, sel)) {
      CheckItem item = planned(input, pose.name, pipeline);
      plannedFiles.insert(item.file);
      const auto start = std::chrono::steady_clock::now();
      checkOne(*scene, manifest, thresholds, sel, run, rendererNotes, item);
      item.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      printItem(sel, item);
      run.items.push_back(std::move(item));
    }
  }
}

// Run-wide notes on what golden.json holds but this run did not plan.
void noteUnplanned(const check::Manifest& manifest, const std::vector<check::CheckInput>& mine,
                   const Selection& sel, const std::set<std::string>& plannedFiles, CheckRun& run) {
  std::set<std::string> scenes, changed;
  for (const check::CheckInput& in : mine) scenes.insert(in.scene);
  for (const ChangedSource& c : run.changed) changed.insert(c.scene);
  std::set<std::string> pipelines(sel.pipelines.begin(), sel.pipelines.end());
  for (const check::Entry& e : manifest.entries)
    if (scenes.count(e.scene) && !changed.count(e.scene) && pipelines.count(e.pipeline) && !plannedFiles.count(e.file))
      run.notes.push_back(e.file + ": in golden.json but no longer planned (stale; --update removes it)");
  const bool anyFile = std::any_of(sel.inputs.begin(), sel.inputs.end(), [](const auto& in) { return in.file; });
  std::vector<std::string> absent;
  std::set<std::string> selected;
  for (const check::CheckInput& in : sel.inputs) selected.insert(in.scene);
  for (const auto& [scene, source] : manifest.sources)
    if (!selected.count(scene)) absent.push_back(source.path);
  if (anyFile && !absent.empty())
    run.notes.push_back(std::to_string(absent.size()) + " file(s) with goldens in golden.json are not among the inputs "
                        "(first: " + absent.front() + "); a file removed from the folder keeps its goldens until its "
                        "entries are deleted or the folder is recorded into a fresh --golden folder");
}

int check(const Selection& sel) {
  const std::string manifestPath = (fs::path(sel.goldenDir) / check::kManifest).string();
  auto manifest = check::readManifest(manifestPath);
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
  const bool againstLlvmpipe = sel.goldens.source == check::GoldenSource::LlvmpipeForDevice;
  if (againstLlvmpipe)
    run.notes.push_back(check::describeChoice(sel.goldens, sel.llvmpipeGoldenDir, sel.renderer, sel.drawnOn));
  run.shaderDir = gl::shaderDir();
  std::vector<std::string> names;
  for (const check::CheckInput& in : sel.inputs) names.push_back(in.scene);
  run.shard = {{"index", sel.shard.index}, {"count", sel.shard.count}, {"inputs", names}};
  std::vector<check::CheckInput> mine;
  for (size_t k : options::shardPositions(names, sel.shard)) mine.push_back(sel.inputs[k]);
  if (const std::string note = options::emptyShardNote(sel.shard, names.size(), mine.size()); !note.empty())
    commandNotes("check", {note});
  std::set<std::string> rendererNotes, plannedFiles;
  std::optional<process::Progress> progress;
  if (!sel.quiet) progress.emplace("check", "scenes checked", mine.size(), false);
  for (const check::CheckInput& input : mine) {
    checkInput(input, *manifest, sel, run, rendererNotes, plannedFiles);
    if (progress) progress->done(input.shown);
  }
  noteUnplanned(*manifest, mine, sel, plannedFiles, run);

  Status written = check::writeCheckReport(sel.outDir, run);
  Status junit =
      sel.junitPath.empty() ? Status{} : check::writeJunit(sel.junitPath, "motorbench check", check::junitCases(run));
  if (!sel.quiet)
    for (const std::string& n : run.notes) std::printf("warning: %s\n", n.c_str());
  std::printf("%s\n", check::summaryLine(run).c_str());
  const int failedImages = int(std::count_if(run.items.begin(), run.items.end(),
                                             [](const CheckItem& it) { return it.outcome == Outcome::Fail; }));
  if (againstLlvmpipe && failedImages > 0 && !sel.quiet)
    std::printf("note: %d of %zu images exceed the device-tolerant thresholds against llvmpipe's goldens: a device "
                "difference or a real regression; look at the diffs in summary.html, and where this device is right "
                "keep its own goldens with `check --update` on it\n",
                failedImages, run.items.size());
  if (!written) return commandError("check", written.error());
  if (!junit) return commandError("check", junit.error());
  if (!sel.quiet) std::printf("report: %s\n", (fs::path(sel.outDir) / "summary.html").string().c_str());
  return check::exitCode(run);
}

// Renders one input's goldens into `next` (and its source's hash, for a file).
Status updateInput(const check::CheckInput& input, const Selection& sel, check::Manifest& next, int& changed,
                   int& same) {
  if (input.file) {
    auto hash = check::contentHash(input.spec);
    if (!hash) return Status::fail(hash.error());
    next.sources[input.scene] = {input.shown, hash->sha256, hash->resources};
  }
  auto scene = loadScene(input.spec);
  if (!scene) return Status::fail(scene.error());
  if (!next.thresholds.count(input.scene)) next.thresholds[input.scene] = check::defaultThresholds(input.scene);
  for (const check::Pose& pose : posesOf(*scene, input)) {
    for (const std::string& pipeline : pipelinesFor(*scene, sel)) {
      check::Entry e;
      e.file = check::fileName(input.scene, pose.name, pipeline);
      e.scene = input.scene;
      e.pipeline = pipeline;
      e.pose = pose.name;
      e.settings.anim = pose.anim;
      e.settings.width = check::kWidth;
      e.settings.height = check::kHeight;
      auto frame = renderFrame(*scene, pipeline, e.settings);
      if (!frame) return Status::fail(frame.error());
      e.glRenderer = frame->glRenderer;
      e.glVersion = frame->glVersion;
      e.glBackend = frame->glBackend;
      e.view = toJson(frame->view);
      const std::string path = (fs::path(sel.goldenDir) / e.file).string();
      auto before = fs::exists(path) ? readImage(path) : Result<RgbaImage>::fail("");
      bool unchanged = before && before->width == frame->image.width &&
                       before->height == frame->image.height && before->rgba == frame->image.rgba;
      Status s = writeImage(path, frame->image);
      if (!s) return s;
      if (!sel.quiet) std::printf("%s  %s\n", unchanged ? "same   " : "written", path.c_str());
      (unchanged ? same : changed)++;
      next.entries.push_back(std::move(e));
    }
  }
  return {};
}

int update(const Selection& sel) {
  auto fail = [](const std::string& message) { return commandError("check --update", message); };
  const std::string manifestPath = (fs::path(sel.goldenDir) / check::kManifest).string();
  check::Manifest old;
  // Keep its thresholds and the images outside the selection; a device's first goldens start
  // from the thresholds of llvmpipe's.
  const std::string thresholdsFrom = fs::exists(manifestPath) || sel.llvmpipeGoldenDir.empty()
                                         ? manifestPath
                                         : (fs::path(sel.llvmpipeGoldenDir) / check::kManifest).string();
  if (fs::exists(thresholdsFrom)) {
    auto m = check::readManifest(thresholdsFrom);
    if (!m) return fail(m.error() + " (fix or delete it; --update does not discard thresholds silently)");
    old = m.take();
    if (thresholdsFrom != manifestPath) old.entries.clear(), old.sources.clear();
  }
  std::error_code ec;
  fs::create_directories(sel.goldenDir, ec);
  if (ec) return fail(sel.goldenDir + ": cannot create folder: " + ec.message());
  std::set<std::string> scenes;
  for (const check::CheckInput& in : sel.inputs) scenes.insert(in.scene);
  std::set<std::string> pipelines(sel.pipelines.begin(), sel.pipelines.end());
  check::Manifest next;
  next.thresholds = old.thresholds;
  next.sources = old.sources;
  for (const check::Entry& e : old.entries)
    if (!scenes.count(e.scene) || !pipelines.count(e.pipeline)) next.entries.push_back(e);
  int changed = 0, same = 0;
  std::optional<process::Progress> progress;
  if (!sel.quiet) progress.emplace("check --update", "scenes recorded", sel.inputs.size(), false);
  for (const check::CheckInput& input : sel.inputs) {
    if (Status s = updateInput(input, sel, next, changed, same); !s) return fail(s.error());
    if (progress) progress->done(input.shown);
  }
  // Images of the selection that the plan no longer makes are stale: remove them.
  for (const check::Entry& e : old.entries)
    if (scenes.count(e.scene) && pipelines.count(e.pipeline) && !next.find(e.file)) {
      fs::remove(fs::path(sel.goldenDir) / e.file, ec);
      if (!sel.quiet) std::printf("removed  %s (no longer planned)\n", (fs::path(sel.goldenDir) / e.file).string().c_str());
    }
  std::sort(next.entries.begin(), next.entries.end(),
            [](const check::Entry& a, const check::Entry& b) { return a.file < b.file; });
  Status w = check::writeManifest(manifestPath, next);
  if (!w) return fail(w.error());
  std::printf("update: %d images changed, %d unchanged; %s rewritten\n", changed, same, manifestPath.c_str());
  return 0;
}

// The built-in scenes `check` runs without arguments: glTF built-ins, golden-only ones, curved ones.
std::vector<std::string> defaultScenes() {
  std::vector<std::string> builtins = builtinSceneNames();
  for (const std::string& g : goldenOnlySceneNames()) builtins.push_back(g);
  for (const std::string& c : curvedSceneNames()) builtins.push_back(c);
  return builtins;
}

// The registered, drawable pipelines of --pipelines (default: all); "" or the error.
std::string selectPipelines(const options::Args& args, Selection& sel) {
  std::vector<std::string> requested =
      args.has("pipelines") ? splitList(args.get("pipelines", "")) : allPipelineNames();
  const std::vector<std::string> registered = allPipelineNames();
  for (const std::string& p : requested) {
    if (std::find(registered.begin(), registered.end(), p) == registered.end())
      return "--pipelines: unknown pipeline '" + p + "' (registered: " + joined(registered) + ")";
    if (!createPipeline(p)) {  // registered placeholder: nothing to render yet
      if (!sel.quiet) std::printf("note: pipeline '%s' is a placeholder; skipped\n", p.c_str());
      continue;
    }
    sel.pipelines.push_back(p);
  }
  return "";
}

// Where the goldens are, and whether that folder can be used: "" or the error.
std::string goldenFolderError(const options::Args& args, const Selection& sel) {
  const bool anyFile = std::any_of(sel.inputs.begin(), sel.inputs.end(), [](const auto& in) { return in.file; });
  // A user's files never fall back to the project's own goldens: they are not there, and
  // --update would write the user's images into motorbench's tests/golden.
  if (anyFile && !args.has("golden"))
    return "files and folders need --golden DIR: the folder that keeps their goldens (e.g. goldens/ in your "
           "repository; record it once with --update). The default, tests/golden, holds motorbench's own scenes only";
  // The default --golden is relative to the repository root. Elsewhere, point to --golden
  // instead of letting --update create goldens in the wrong place (or suggesting it).
  if (!args.has("golden") && !fs::exists(fs::path("tests/golden") / check::kManifest))
    return "tests/golden/" + std::string(check::kManifest) + " not found under " + fs::current_path().string() +
           ": run check from the repository root, or pass --golden DIR (the folder holding " + check::kManifest +
           ", e.g. --golden /path/to/motorbench/tests/golden)";
  if (!args.has("golden") || args.has("update") || fs::exists(fs::path(sel.goldenDir) / check::kManifest)) return "";
  if (anyFile)
    return "--golden " + sel.goldenDir + ": no " + check::kManifest + " there: record the goldens of these files "
           "first, with a build you trust: motorbench check FILE|DIR... --golden " + sel.goldenDir + " --update";
  // A --golden folder without golden.json is the wrong folder: --update there would make a golden
  // set of this renderer's own images, so the check would compare the renderer with itself.
  return "--golden " + sel.goldenDir + ": not a golden folder (no " + check::kManifest + " there). A golden folder holds " +
         check::kManifest + " (the thresholds and the list of images with the GL renderer that made them) and one PNG "
         "per scene, pose and pipeline, e.g. tests/golden of the motorbench repository; pass that folder. Do not make "
         "one here with --update: goldens rendered by the renderer under test would compare it with itself";
}

int runCheck(const std::vector<std::string>& argv) {
  if (std::find(argv.begin(), argv.end(), "--rules") != argv.end()) return check::runCheckRules(argv);
  options::Args args(argv, {{"golden", "scenes", "pipelines", "out", "o", "shader-dir", "shard", "gpu", "junit"},
                   {"update", "quiet"},
                   {}});
  auto fail = [](const std::string& message) { return commandError("check", message); };
  if (!args.error().empty()) return fail(args.error());
  if (Status gpu = applyGpuOption(args); !gpu) return fail(gpu.error());
  Selection sel;
  sel.quiet = args.has("quiet");
  sel.goldenDir = args.get("golden", "tests/golden");
  sel.outDir = args.get("out", args.get("o", "out/check"));
  sel.junitPath = args.get("junit", "");
  if (auto dir = args.get("shader-dir")) {
    if (!fs::is_directory(*dir)) return fail("--shader-dir " + *dir + ": not a folder");
    // shaderDir() reads MB_SHADER_DIR on every load, so this redirects every pipeline.
    ::setenv("MB_SHADER_DIR", fs::absolute(*dir).string().c_str(), 1);
  }
  const std::vector<std::string> builtins = defaultScenes();
  std::vector<std::string> named = args.positional();
  for (const std::string& s : splitList(args.get("scenes", ""))) {
    if (!isBuiltinScene(s))
      return fail("--scenes: '" + s + "' is not a built-in scene (" + joined(builtins) +
                  "); a file or folder goes without --scenes: motorbench check FILE|DIR --golden DIR");
    named.push_back(s);
  }
  if (!args.has("scenes") && args.positional().empty()) named = builtins;
  auto inputs = check::checkInputs(named);
  if (!inputs) return fail(inputs.error());
  sel.inputs = inputs.take();
  if (std::string e = selectPipelines(args, sel); !e.empty()) return fail(e);
  if (sel.inputs.empty() || sel.pipelines.empty()) return fail("nothing selected (no scenes or pipelines)");
  if (auto text = args.get("shard")) {
    if (args.has("update")) return fail("--shard checks; --update writes every golden in one run");
    std::string error;
    auto shard = options::parseShard(*text, &error);
    if (!shard) return fail(error);
    sel.shard = *shard;
  }
  if (std::string e = goldenFolderError(args, sel); !e.empty()) return fail(e);
  // The outputs before the first render (checking writes there; --update does not).
  if (!args.has("update"))
    if (Status ok = prepareOutputFolder("--out", sel.outDir, "images of failures and warnings, summary.html, check.json"); !ok)
      return fail(ok.error());
  if (args.has("junit") && args.has("update")) return fail("--junit reports a check; --update records goldens");
  if (!sel.junitPath.empty())
    if (Status ok = prepareOutputFile("--junit", sel.junitPath); !ok) return fail(ok.error());
  // Which goldens this device is checked against (or, updating, writes): golden_device.h.
  auto ctx = gl::sharedContext();
  if (!ctx) return fail(ctx.error());
  sel.renderer = (*ctx)->info().renderer;
  sel.drawnOn = describeGl((*ctx)->info());
  sel.llvmpipeGoldenDir = sel.goldenDir;
  const bool devicePresent =
      fs::exists(fs::path(check::deviceGoldenDir(sel.goldenDir, sel.renderer)) / check::kManifest);
  sel.goldens = check::chooseGoldens(sel.goldenDir, sel.renderer, devicePresent, args.has("update"));
  sel.goldenDir = sel.goldens.dir;
  if (!sel.quiet)
    std::printf("%s\n", check::describeChoice(sel.goldens, sel.llvmpipeGoldenDir, sel.renderer, sel.drawnOn).c_str());
  return args.has("update") ? update(sel) : check(sel);
}

}  // namespace
}  // namespace mb

MB_COMMAND(check, "check",
           "[FILE|DIR|SCENE ...] [--golden DIR] [--scenes a,b] [--pipelines p,q] [--out DIR] [--shader-dir DIR] "
           "[--update] [--shard I/N] [--junit FILE] [--quiet] [--gpu auto|llvmpipe|N]" MB_CHECK_RULES_USAGE,
           "compare renders of built-in scenes or your own glTF files with their golden images (exit 0 pass, 1 a "
           "threshold exceeded or a file changed, 2 an error)",
           mb::runCheck);
MB_COMMAND_HELP(check, "check",
               "  FILE|DIR|SCENE...  what to check: .gltf/.glb files, folders (their .gltf/.glb files, recursively,\n"
               "                     sorted) and built-in scene names (default: every built-in scene). A file's\n"
               "                     goldens are named by its path relative to the folder given (a file given\n"
               "                     alone: its name), [A-Za-z0-9_-] kept and the rest as '_' (props/Fox.glb ->\n"
               "                     props_Fox_glb.rest.motor.png); poses: rest, and the file's first animation at\n"
               "                     35 % and 70 % of its duration (built-ins: their first 4 animations), each\n"
               "                     pose's animation and time in golden.json; size 160x120\n"
               "  --golden DIR       the golden folder: golden.json + one PNG per scene, pose and pipeline (default\n"
               "                     tests/golden from the repository root, motorbench's own scenes; required for\n"
               "                     files and folders: your goldens live in your folder). Per device: its\n"
               "                     devices/<GL_RENDERER slug>/ subfolder when there is one\n"
               "  --scenes a,b       built-in scenes, as the arguments (default: all of them when no argument)\n"
               "  --pipelines p,q    only these pipelines (default: every pipeline of each scene's space)\n"
               "  --out DIR          actual, expected, diff and FLIP images of failures and warnings, summary.html,\n"
               "                     check.json (default out/check)\n"
               "  --update           render the selection into --golden and rewrite golden.json (keeping its\n"
               "                     thresholds; a file's content hash, SHA-256 of its bytes and its external\n"
               "                     .bin/images, recorded with it)\n"
               "  --shader-dir DIR   run against a modified copy of shaders/ (default: the build's shaders)\n"
               "  --shard I/N        only every N-th scene from the I-th (default 1/1)\n"
               "  --junit FILE       JUnit XML: one test case per scene, pose and pipeline; failures and errors\n"
               "                     with their reason (default: none written)\n"
               "  --quiet            print only failures, errors, changed files and the summary line\n"
               MB_CHECK_RULES_HELP
               MB_GPU_OPTION_HELP
               "  Thresholds: golden.json's per scene; a file's default as a built-in's (exact: one 8-bit step;\n"
               "  portable, on another GL: 0.02 on up to 1 % of pixels). A file whose content hash differs from\n"
               "  the recorded one is named CHANGED and its images not judged.\n"
               "  Exit 0 every image passed (warnings allowed), 1 an image exceeded its thresholds or a file changed\n"
               "  since its goldens were recorded, 2 an error (a missing golden, a file that does not load, a bad\n"
               "  option).\n",
                "motorbench check assets/ --golden goldens/ --junit out/junit.xml --quiet", true);
