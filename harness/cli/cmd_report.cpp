// `motorbench report [SCENE|FILE|DIR ...] -o DIR [--jobs N] [--size WxH] [--frames N]
//   [--no-bench | --bench-json FILE] [...]`: images, diffs, metrics, memory, ops per vertex,
// frame timing, kernel ratios, conversion cost, fallbacks and statistics of every scene and
// pipeline -> DIR/report.json, report.md, report.html, images/, plots/ (harness/report/, harness/document/).
// The same command with --worker measures one scene for the parent run (report_workers.h).
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "harness/options/args.h"
#include "harness/cli/command.h"
#include "harness/render/render_frame.h"
#include "harness/document/report_format.h"
#include "harness/report/report_run.h"
#include "harness/report/report_scene.h"
#include "harness/report/report_timing.h"
#include "pipelines/pipeline.h"
#include "pipelines/scene/loader.h"

namespace mb {
namespace {

using json = nlohmann::json;

bool parseSize(const std::string& s, int* w, int* h) {
  char x = 0, extra = 0;
  const int n = std::sscanf(s.c_str(), "%d%c%d%c", w, &x, h, &extra);
  if (n == 1) *h = *w;
  else if (n != 3 || (x != 'x' && x != 'X')) return false;
  return *w >= 1 && *h >= 1 && *w <= 8192 && *h <= 8192;
}

int fail(const std::string& message) { return commandError("report", message); }

// Worker: one scene, one phase ("render" or "time"); writes --worker-out with "complete": true
// last so the parent can tell a finished result from a crash.
int runWorker(const Args& args, const report::Options& o) {
  if (args.positional().size() != 1) return fail("--worker needs exactly one scene");
  report::SceneJob job;
  job.input = {args.positional()[0], args.get("worker-id", "scene")};
  job.index = std::atoi(args.get("worker-index", "1").c_str());
  job.total = std::atoi(args.get("worker-total", "1").c_str());
  job.outDir = o.outDir;
  job.width = o.width, job.height = o.height;
  job.pipelines = o.pipelines;
  json result;
  const std::string mode = args.get("worker", "");
  if (mode == "render") {
    result = report::measureScene(job);
  } else if (mode == "time") {
    report::progress(job, "timing " + std::to_string(o.frames) + " frames per pipeline");
    auto scene = loadScene(job.input.spec);
    // Skinned scenes are timed with every pipeline in the same skinning configuration (as the
    // references do it), so the ratio compares like with like (issue 18); images keep each
    // pipeline's default.
    PipelineOptions options;
    if (scene && !scene->skins.empty()) options.skinSpace = SkinSpace::Reference;
    result = scene ? report::timeScene(*scene, o.pipelines, o.frames, o.timeWidth, o.timeHeight, options)
                   : json{{"error", scene.error()}};
    if (scene && !scene->skins.empty()) result["skinSpace"] = "reference (every pipeline)";
  } else {
    return fail("--worker " + mode + ": expected render or time");
  }
  result["complete"] = true;
  std::ofstream out(args.get("worker-out", ""));
  out << report::dumpJson(result) << "\n";
  return out.flush() ? 0 : fail(args.get("worker-out", "") + ": write failed");
}

int runReportCommand(const std::vector<std::string>& argv) {
  const Args args(argv, {"no-bench", "no-plots"});
  if (!args.error().empty()) return fail(args.error());
  const std::set<std::string> known = {"o", "output", "jobs", "size", "frames", "no-bench", "bench-json",
                                       "bench-min-time", "pipelines", "no-plots", "python", "plot-script",
                                       "timeout", "time-size", "worker", "worker-out", "worker-id",
                                       "worker-index", "worker-total", "shard"};
  if (auto unknown = args.unknown(known); !unknown.empty()) return fail("unknown option " + unknown[0]);
  report::Options o;
  o.scenes = args.positional();
  o.outDir = args.get("o", args.get("output", ""));
  if (o.outDir.empty()) return fail("missing -o DIR");
  o.pipelines = splitList(args.get("pipelines", ""));
  if (o.pipelines.empty()) o.pipelines = pipelineNames();
  for (const std::string& p : o.pipelines) {
    bool registered = false;
    for (const std::string& n : pipelineNames()) registered = registered || n == p;
    if (!registered) return fail("--pipelines: unknown pipeline '" + p + "'");
  }
  if (args.has("size") && !parseSize(args.get("size", ""), &o.width, &o.height))
    return fail("--size " + args.get("size", "") + ": expected WxH, e.g. 256x192");
  if (args.has("time-size") && !parseSize(args.get("time-size", ""), &o.timeWidth, &o.timeHeight))
    return fail("--time-size " + args.get("time-size", "") + ": expected WxH, e.g. 512x512");
  auto jobs = numberOption(args, "jobs", 1), frames = numberOption(args, "frames", o.frames),
       timeout = numberOption(args, "timeout", o.timeoutS), minTime = numberOption(args, "bench-min-time", o.benchMinTime);
  for (const auto* r : {&jobs, &frames, &timeout, &minTime})
    if (!*r) return fail(r->error());
  o.jobs = int(*jobs), o.frames = int(*frames), o.timeoutS = *timeout, o.benchMinTime = *minTime;
  if (o.jobs < 1 || o.jobs > 256) return fail("--jobs: expected 1..256");
  if (o.frames < 0) return fail("--frames: expected 0 or more");
  o.bench = !args.has("no-bench");
  o.benchJson = args.get("bench-json", "");
  o.plots = !args.has("no-plots");
  o.python = args.get("python", o.python);
  o.plotScript = args.get("plot-script", "");
  if (auto text = args.get("shard")) {
    std::string error;
    auto shard = parseShard(*text, &error);
    if (!shard) return fail(error);
    o.shard = *shard;
  }
  if (args.has("worker")) return runWorker(args, o);
  return report::runReport(o);
}

}  // namespace
}  // namespace mb

MB_COMMAND(report, "report",
           "[SCENE|FILE|DIR ...] -o DIR [--jobs N] [--size WxH] [--frames N] [--no-bench | "
           "--bench-json FILE] [--bench-min-time S] [--pipelines a,b] [--time-size WxH] [--no-plots] [--shard I/N]",
           "measure scenes with every pipeline: images, diffs, memory, ops, timing, kernel ratios "
           "-> report.json/.md/.html",
           mb::runReportCommand);
