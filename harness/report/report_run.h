// The phases of `motorbench report`: scenes measured by worker processes (in parallel with
// --jobs), frame timing scene by scene, ops per vertex, kernel throughput (bench), then
// report.json, the plots (scripts/plot.py) and report.md / report.html.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/options/shard.h"

namespace mb::report {

struct Options {
  std::vector<std::string> scenes;  // SCENE|FILE|DIR arguments; empty: the built-in scenes, then
                                    // the curved ones (s3_tiling, h3_tiling)
  std::string outDir;
  std::vector<std::string> pipelines;  // first = baseline of the diffs; empty: each scene's space's
                                       // pipelines (pipelineNames(Space), matrix side first)
  std::string anim;                    // --anim items (report_anim_select.h); "": first animation
  int jobs = 1;
  int width = 256, height = 192;
  int frames = 30;                   // timed frames per pipeline and scene; 0: no timing
  int timeWidth = 512, timeHeight = 512;  // viewport of the normal timing configuration (as `time`)
  bool bench = true;                 // run the kernels (the command: with no scene named, or --bench)
  std::string benchJson;             // read this instead of running `motorbench bench`
  std::string benchSkipped;          // why the kernels were not run, as report.json says it ("": --no-bench)
  std::string morphJson;             // `motorbench morph --json` file embedded as report.json "morph"
  std::string isaJson;               // `motorbench isa --json` file embedded as report.json "isa"
  bool isa = true;                   // without isaJson: measure the ISA now (cached); false: --no-isa
  double benchMinTime = 0.05;        // --benchmark_min_time when the report runs the bench
  bool plots = true;
  std::string python;                // "" = defaultPython() (report_plots.h)
  std::string plotScript;            // "" = scripts/plot.py of this source tree
  double timeoutS = 900;             // per worker process
  options::Shard shard;                       // --shard I/N: this run's part of the input list
  int instances = 1;                 // --instances N: every mesh node drawn N times (frame_options.h)
};

// Camera steps of the curved-space drift the report measures when it has a curved scene (the
// issue's 10^6, as `motorbench drift`).
inline constexpr int64_t kReportDriftSteps = 1000000;

// The pipelines scene `spec` is measured with: options.pipelines when given, else those of the
// scene's space (a curved built-in: its s3_/h3_ pair; anything else: the Euclidean ones).
std::vector<std::string> scenePipelines(const Options& options, const std::string& spec);
// The Euclidean (glTF) pipelines of the run: options.pipelines, else pipelineNames().
std::vector<std::string> runPipelines(const Options& options);

// Runs every phase; a failing scene is recorded and the run goes on. Returns 0 when every scene
// was measured ("ok"), 1 when the report was written but some scene failed or is partial (each
// named with its reason on stderr, as in report.md), 2 when the output could not be written,
// 130 when SIGINT / SIGTERM stopped it (the scenes done written, the folder marked PARTIAL).
// The folder's earlier report is removed first (report_folder.h); the answer goes to stdout.
int runReport(const Options& options);

// The last phase, shared with `motorbench merge`: writes report.json, the plots (when
// options.plots) and report.md / report.html into options.outDir. 0, or 2 when a file could not
// be written (the message is printed).
// `answer`: filled with the answer block's lines as printed on stdout (the question, then one
// "evidence: figures -> verdict" line each). A report.json with "interrupted" gets a first line
// saying so in report.md and report.html.
int writeReportFolder(nlohmann::json report, const Options& options, std::vector<std::string>* answer = nullptr);

}  // namespace mb::report
