// `motorbench report [SCENE|FILE|DIR ...] -o DIR [--jobs N] [--size WxH] [--frames N]
//   [--no-bench | --bench-json FILE] [--anim ITEMS] [...]`: images, diffs, metrics, memory, ops per vertex,
// frame timing, kernel ratios, conversion cost, fallbacks and statistics of every scene and
// pipeline -> DIR/report.json, report.md, report.html, images/, plots/ (harness/report/, harness/document/).
// The same command with --worker measures one scene for the parent run (report_workers.h).
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <tuple>

#include "harness/options/args.h"
#include "harness/cli/command.h"
#include "harness/render/gpu_option.h"
#include "harness/cli/output_paths.h"
#include "harness/cli/report_junit.h"
#include "harness/render/render_frame.h"
#include "harness/render/scene_inputs.h"
#include "harness/document/report_format.h"
#include "harness/report/report_run.h"
#include "harness/report/report_scene.h"
#include "harness/timing/report_timing.h"
#include "pipelines/pipeline.h"
#include "pipelines/scene/instancing.h"
#include "pipelines/scene/loader.h"

namespace mb {
namespace {

using json = nlohmann::json;
using check::JunitCase;
using check::writeJunit;

int fail(const std::string& message) { return commandError("report", message); }

// One scene, timed: every pipeline interleaved in this process.
json timeWorker(const report::SceneJob& job, const report::Options& o) {
  report::progress(job, "timing " + std::to_string(o.frames) + " frames per pipeline");
  auto scene = loadScene(job.input.spec);
  if (scene && scene->curved.space == Space::Euclidean) addGridInstances(*scene, o.instances);
  // Skinned scenes are timed with every pipeline in the same skinning configuration (as the
  // references do it), so the ratio compares like with like; images keep each
  // pipeline's default.
  PipelineOptions options;
  if (scene && !scene->skins.empty()) options.skinSpace = SkinSpace::Reference;
  json result = scene ? timing::timeScene(*scene, job.pipelines, o.frames, o.timeWidth, o.timeHeight, options)
                      : json{{"error", scene.error()}};
  if (scene && !scene->skins.empty()) result["skinSpace"] = "reference (every pipeline)";
  return result;
}

// Worker: one scene, one phase ("render" or "time"); writes --worker-out with "complete": true
// last so the parent can tell a finished result from a crash.
int runWorker(const options::Args& args, const report::Options& o) {
  if (args.positional().size() != 1) return fail("--worker needs exactly one scene");
  const std::string mode = args.get("worker", "");
  if (mode != "render" && mode != "time") return fail("--worker " + mode + ": expected render or time");
  report::SceneJob job;
  job.input = {args.positional()[0], args.get("worker-id", "scene")};
  job.index = std::atoi(args.get("worker-index", "1").c_str());
  job.total = std::atoi(args.get("worker-total", "1").c_str());
  job.outDir = o.outDir;
  job.width = o.width, job.height = o.height;
  job.instances = o.instances;
  // The last progress line beside the result: the parent names it when this worker dies.
  if (const std::string out = args.get("worker-out", ""); !out.empty()) job.stepFile = report::stepFileOf(out);
  job.pipelines = report::scenePipelines(o, job.input.spec);  // the parent passes each scene's
  for (const std::string& a : splitList(args.get("worker-anims", ""))) job.animations.push_back(std::atoi(a.c_str()));
  json result;
  // An exception escaping the measurement (renderFrame already turns a pipeline's own into that
  // pipeline's error) fails this scene with its message, not with a bare "exit status 2".
  try {
    result = mode == "render" ? report::measureScene(job) : timeWorker(job, o);
  } catch (const std::exception& e) {
    const std::string step = report::lastStep(job.stepFile);
    result = {{"error", "internal error (exception)" + (step.empty() ? "" : " while " + step) + ": " + e.what()}};
    if (mode == "render") result.update({{"id", job.input.id}, {"spec", job.input.spec}, {"status", "failed"}});
  }
  result["complete"] = true;
  const Status w = writeTextFile(args.get("worker-out", ""), document::dumpJson(result) + "\n");
  return w ? 0 : fail(w.error());
}

// After the run: the JUnit file (--junit) and, with --quiet, what the run printed kept in
// DIR/report-log.txt and only its failures and summary line shown.
int finishReport(int status, const report::Options& o, const std::string& junitPath, const std::string& log) {
  namespace fs = std::filesystem;
  std::ifstream in(fs::path(o.outDir) / "report.json");
  const json report = json::parse(in, nullptr, false);
  const bool written = status != 2 && report.is_object();
  const std::vector<JunitCase> cases = written ? reportJunitCases(report) : std::vector<JunitCase>{};
  if (!log.empty()) {
    std::error_code ec;
    const fs::path kept = fs::path(o.outDir) / "report-log.txt";
    fs::copy_file(log, kept, fs::copy_options::overwrite_existing, ec);
    std::ifstream lines(log);
    for (std::string line; std::getline(lines, line);)
      if (!written && (line.find("error") != std::string::npos || line.find("INTERRUPTED") != std::string::npos))
        std::fprintf(stderr, "%s\n", line.c_str());  // why no report was written
    fs::remove(log, ec);
    if (written) {
      for (const JunitCase& c : cases)
        if (c.kind == JunitCase::Kind::Fail || c.kind == JunitCase::Kind::Error)
          std::printf("%s  %s %s: %s\n", c.kind == JunitCase::Kind::Fail ? "FAIL " : "ERROR", c.classname.c_str(),
                      c.name.c_str(), c.message.c_str());
      std::printf("%s -> %s (log: %s)\n", reportSummaryLine(report, cases).c_str(),
                  (fs::path(o.outDir) / "report.html").string().c_str(), kept.string().c_str());
    }
  }
  if (!junitPath.empty() && written)
    if (Status w = writeJunit(junitPath, "motorbench report", cases); !w) return fail(w.error());
  return status;
}

int runReportCommand(const std::vector<std::string>& argv) {
  const options::Args args(argv, {{"o", "output", "jobs", "size", "frames", "bench-json", "bench-min-time", "pipelines",
                          "python", "plot-script", "timeout", "time-size", "worker", "worker-out", "worker-id",
                          "worker-index", "worker-total", "shard", "anim", "worker-anims", "instances", "gpu",
                          "isa-json", "morph-json", "junit"},
                         {"no-bench", "bench", "no-isa", "no-plots", "quiet"},
                         {},
                         {"anim"}});
  if (!args.error().empty()) return fail(args.error());
  if (Status gpu = applyGpuOption(args); !gpu) return fail(gpu.error());  // workers inherit MB_GPU
  report::Options o;
  o.scenes = args.positional();
  o.outDir = args.get("o", args.get("output", ""));
  if (o.outDir.empty()) return fail("missing -o DIR");
  // Without --pipelines each scene gets its space's pipelines (curved scenes: s3_* / h3_*).
  o.pipelines = splitList(args.get("pipelines", ""));
  for (const std::string& p : o.pipelines) {
    bool registered = false;
    for (const std::string& n : allPipelineNames()) registered = registered || n == p;
    if (!registered) return fail("--pipelines: unknown pipeline '" + p + "' (registered: " + joinNames(allPipelineNames()) + ")");
  }
  o.anim = args.get("anim", "");
  if (args.has("anim") && o.anim.empty()) return fail("--anim: expected NAME, INDEX, all or SCENE:NAME");
  std::tie(o.width, o.height) = args.size("size", o.width, o.height);
  std::tie(o.timeWidth, o.timeHeight) = args.size("time-size", o.timeWidth, o.timeHeight);
  o.jobs = int(args.integer("jobs", 1, 1, 256));
  o.frames = int(args.integer("frames", o.frames, 0, 100000));
  o.instances = int(args.integer("instances", 1, 1, kMaxInstances));
  o.timeoutS = args.real("timeout", o.timeoutS, 1.0, 1e7, "seconds");
  o.benchMinTime = args.real("bench-min-time", o.benchMinTime, 0.0, 1e4, "seconds");
  if (args.has("no-bench") && args.has("bench-json"))
    return fail("--no-bench and --bench-json: give one (skip the kernel ratios, or read them from a file)");
  if (args.has("no-bench") && args.has("bench"))
    return fail("--no-bench and --bench: give one (skip the kernel ratios, or run them)");
  // The kernels do not depend on the scenes: a report of the built-in scenes runs them (its
  // evidence), a report of files only with --bench (they would cost the same for any input).
  o.bench = args.has("bench") || (!args.has("no-bench") && o.scenes.empty());
  if (!o.bench && !args.has("no-bench"))
    o.benchSkipped = "not run: a report of files runs the kernel benchmark only with --bench or --bench-json FILE "
                     "(it measures the same kernels whatever the files)";
  if (args.has("no-isa") && args.has("isa-json"))
    return fail("--no-isa and --isa-json: give one (skip the ISA statistics, or read them from a file)");
  o.isa = !args.has("no-isa");
  o.benchJson = args.get("bench-json", "");
  o.plots = !args.has("no-plots");
  o.python = args.get("python", o.python);
  o.plotScript = args.get("plot-script", "");
  if (auto text = args.get("shard")) {
    std::string error;
    auto shard = options::parseShard(*text, &error);
    if (!shard) return fail(error);
    o.shard = *shard;
  }
  if (args.has("worker")) return runWorker(args, o);
  // Checked before the run starts: a missing --bench-json would otherwise surface after the
  // whole report as a note.
  if (!o.benchJson.empty()) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(o.benchJson, ec))
      return fail("--bench-json " + o.benchJson + ": no such file (write one with `motorbench bench --out FILE`, "
                  "or drop the option to run the kernels now)");
    std::ifstream in(o.benchJson);
    if (nlohmann::json::parse(in, nullptr, false).is_discarded())
      return fail("--bench-json " + o.benchJson + ": not JSON (expected a `motorbench bench --out` file)");
  }
  // --isa-json / --morph-json: another command's JSON file, checked by its schema before the run.
  for (auto [option, command, into] : {std::tuple{"isa", "isa", &o.isaJson}, std::tuple{"morph", "morph", &o.morphJson}}) {
    const auto path = args.get(std::string(option) + "-json");
    if (!path) continue;
    const std::string flag = "--" + std::string(option) + "-json " + *path, schema = "motorbench-" + std::string(command) + "/1";
    std::ifstream in(*path);
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (!in.is_open()) return fail(flag + ": no such file (write one with `motorbench " + command + " --json FILE`)");
    if (j.is_discarded() || !j.is_object() || j.value("schema", "") != schema)
      return fail(flag + ": not a `motorbench " + command + " --json` file (schema " + schema + ")");
    *into = *path;
  }
  if (Status ok = prepareOutputFolder("-o", o.outDir, "report.json, report.md, report.html, images/, plots/"); !ok)
    return fail(ok.error());
  const std::string junitPath = args.get("junit", "");
  if (!junitPath.empty())
    if (Status ok = prepareOutputFile("--junit", junitPath); !ok) return fail(ok.error());
  if (!args.has("quiet")) {
    for (const std::string& w : emptyInputWarnings(o.scenes)) std::fprintf(stderr, "motorbench report: warning: %s\n", w.c_str());
    return finishReport(report::runReport(o), o, junitPath, "");
  }
  // The report removes its folder's earlier files first: the log waits beside it until the end.
  const std::string log = (std::filesystem::temp_directory_path() /
                           ("motorbench-report-" + std::to_string(::getpid()) + ".log")).string();
  OutputToFile quiet(log);
  if (!quiet.ok()) return fail(log + ": cannot write the log of --quiet");
  const int status = report::runReport(o);
  quiet.restore();
  return finishReport(status, o, junitPath, log);
}

}  // namespace
}  // namespace mb

MB_COMMAND(report, "report",
           "[SCENE|FILE|DIR ...] -o DIR [--jobs N] [--size WxH] [--frames N] [--time-size WxH] [--bench | --no-bench | "
           "--bench-json FILE] [--bench-min-time S] [--pipelines a,b] [--anim [SCENE:]NAME|INDEX|all,...] "
           "[--instances N] [--no-plots] [--python P] [--plot-script FILE] [--timeout S] [--shard I/N] "
           "[--gpu auto|llvmpipe|N] [--isa-json FILE | --no-isa] [--morph-json FILE] [--junit FILE] [--quiet]",
           "measure scenes with every pipeline of their space: images, diffs, memory, ops, timing, kernel "
           "ratios -> report.json/.md/.html",
           mb::runReportCommand);
MB_COMMAND_HELP(report, "report",
               "  SCENE|FILE|DIR...  scenes (default: the built-in ones, then s3_tiling and h3_tiling)\n"
               "  -o, --output DIR   the report folder: report.json/.md/.html, images/, plots/\n"
               "  --jobs N           scenes measured at once (default 1)\n"
               "  --size WxH         image size (default 256x192)\n"
               "  --frames N         timed frames per pipeline and scene (default 30; 0: no timing)\n"
               "  --time-size WxH    the timing viewport (default 512x512, as `time`)\n"
               "  --bench | --no-bench | --bench-json FILE   run the kernel ratios, skip them, or read them from\n"
               "                     `bench --out` (default: run them for the built-in scenes; not for files and\n"
               "                     folders, whose kernels are the same for any input)\n"
               "  --bench-min-time S Google Benchmark min time per kernel (default 0.05)\n"
               "  --pipelines a,b    pipelines (default: every pipeline of each scene's space)\n"
               "  --anim ITEMS       animations shown: NAME, INDEX, all or SCENE:NAME, comma-separated (default: the\n"
               "                     first animation)\n"
               MB_INSTANCES_OPTION_HELP
               "  --no-plots         no plots (default: plots when python3 and matplotlib are there)\n"
               "  --python P         the python with matplotlib (default /usr/bin/python3 when present, else python3)\n"
               "  --plot-script FILE the plot script (default scripts/plot.py of this source tree; env MB_PLOT_SCRIPT)\n"
               "  --timeout S        seconds each scene's worker process may take (default 900)\n"
               "  --shard I/N        only every N-th scene from the I-th (merge puts shards together)\n"
               MB_GPU_OPTION_HELP
               "  --isa-json FILE    `motorbench isa --json` file: the ISA statistics per pipeline (default: measured\n"
               "                     now, each shader variant compiled once, kept in the cache: MB_CACHE_DIR)\n"
               "  --no-isa           no ISA statistics\n"
               "  --morph-json FILE  `motorbench morph --json` file: the morph section (default: none)\n"
               "  --junit FILE       JUnit XML: one test case per scene, frame and pipeline; an error where it could\n"
               "                     not be measured, a failure where the drawn-pixel check failed (one image empty\n"
               "                     or drawn pixels more than 1 % apart; no image thresholds) (default: none)\n"
               "  --quiet            print only failed scenes and frames and the summary line; the whole output\n"
               "                     goes to DIR/report-log.txt\n"
               "  Exit 0 every scene measured, 1 the report written but a scene failed or is partial, 2 an error\n"
               "  (a bad option, the report not written), 130 interrupted (the scenes done written, marked PARTIAL).\n",
                "motorbench report textured_box --frames 0 --no-bench -o out/report", true);
