#include "harness/render/counter_glossary.h"
#include "harness/render/image_metrics.h"
#include "harness/report/report_run.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>

#include "harness/bench/report_bench.h"
#include "harness/document/ops_ranking.h"
#include "harness/document/report_answer.h"
#include "harness/document/report_answer_figures.h"
#include "harness/document/report_document.h"
#include "harness/report/report_sources.h"
#include "harness/document/report_format.h"
#include "harness/report/report_inputs.h"
#include "harness/report/report_machine.h"
#include "harness/document/report_layout.h"
#include "harness/document/report_marks.h"
#include "harness/options/shard.h"
#include "harness/report/report_ops.h"
#include "harness/document/report_plots.h"
#include "harness/process/interrupt.h"
#include "harness/process/report_workers.h"
#include "harness/report/report_anim_select.h"
#include "harness/report/report_drift.h"
#include "harness/report/report_folder.h"
#include "harness/report/report_isa_run.h"
#include "harness/report/report_scene.h"
#include "pipelines/pipeline.h"
#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/curved_space.h"

namespace mb::report {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

void say(const std::string& line) {
  std::fprintf(stderr, "report: %s\n", line.c_str());
  std::fflush(stderr);
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "" : ",") + x;
  return s;
}

// The worker command line shared by the render and time phases. `anims`: the scene's resolved
// --anim indices (empty: the default).
std::vector<std::string> workerArgs(const Options& o, const Input& in, int index, int total,
                                    const std::string& mode, const std::string& resultPath,
                                    const std::vector<int>& anims) {
  std::vector<std::string> args = {
      "report", "--worker", mode, "--worker-out", resultPath, "--worker-id", in.id,
      "--worker-index", std::to_string(index), "--worker-total", std::to_string(total),
      "-o", o.outDir, "--size", std::to_string(o.width) + "x" + std::to_string(o.height),
      "--frames", std::to_string(o.frames), "--time-size",
      std::to_string(o.timeWidth) + "x" + std::to_string(o.timeHeight), "--pipelines",
      joined(scenePipelines(o, in.spec))};
  std::string a;
  for (int i : anims) a += (a.empty() ? "" : ",") + std::to_string(i);
  if (!a.empty()) args.insert(args.end(), {"--worker-anims", a});
  if (o.instances > 1) args.insert(args.end(), {"--instances", std::to_string(o.instances)});
  args.push_back(in.spec);
  return args;
}

Status writeText(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out.flush()) return Status::fail(path.string() + ": write failed");
  return Status();
}

// Kernel throughput: a bench JSON named on the command line, else one run now into the
// report folder (short min time), else nothing (--no-bench).
json kernels(const Options& o) {
  json k = {{"source", "skipped"}, {"error", nullptr}, {"file", nullptr}};
  std::string path;
  if (!o.benchJson.empty()) {
    k["source"] = "file";
    path = o.benchJson;
  } else if (o.bench) {
    path = (fs::path(o.outDir) / "bench.json").string();
    char mt[32];
    std::snprintf(mt, sizeof mt, "%g", o.benchMinTime);
    say(std::string("running motorbench bench (--benchmark_min_time=") + mt +
        "; console output in bench.txt)");
    Status s = bench::runBench(path, (fs::path(o.outDir) / "bench.txt").string(), o.benchMinTime);
    k["source"] = "run";
    k["minTime"] = o.benchMinTime;
    if (!s) {
      k["error"] = s.error();
      return k;
    }
  } else {
    k["error"] = o.benchSkipped.empty() ? "not measured (--no-bench)" : o.benchSkipped;
    return k;
  }
  auto j = bench::readBenchJson(path);
  if (!j) {
    k["error"] = j.error();
    return k;
  }
  k["file"] = fs::path(path).parent_path() == fs::path(o.outDir) ? fs::path(path).filename().string() : path;
  json pairs = bench::kernelPairs(*j);
  k["context"] = pairs["context"];
  k["pairs"] = pairs["pairs"];
  k["probe"] = pairs["probe"];
  return k;
}

// A worker that died before writing its result left only "worker exit status 2" (or a signal):
// add the step it was on, from the line it kept beside the result (report_scene.h).
void addLastStep(json& scene, const std::string& resultPath) {
  const std::string step = lastStep(stepFileOf(resultPath));
  std::error_code ec;
  std::filesystem::remove(stepFileOf(resultPath), ec);
  const json error = scene.contains("error") ? scene["error"] : json();
  if (!error.is_string() || error.get<std::string>().rfind("worker ", 0) != 0 ||
      error.get<std::string>() == "worker could not be started")
    return;
  scene["error"] = error.get<std::string>() + (step.empty() ? " before its first step (while starting up)"
                                                            : " while " + step + " (its message is on the run's stderr)");
}

// The AMD ISA statistics: the --isa-json file, else measured now (cached, report_isa_run.h),
// else why not (--no-isa, no RADV).
void attachIsa(json& report, const Options& o) {
  if (!o.isaJson.empty()) {  // checked by the command before the run (schema motorbench-isa/1)
    std::ifstream in(o.isaJson);
    report["isa"] = json::parse(in, nullptr, false);
    report["isaSource"] = {{"source", "file"}, {"file", o.isaJson}};
    return;
  }
  if (!o.isa) {
    report["isa"] = {{"error", "not measured (--no-isa)"}};
    report["isaSource"] = {{"source", "skipped"}};
    return;
  }
  say("measuring the AMD ISA of every shader variant (motorbench isa on RADV's null device; cached)");
  IsaEvidence e = measureIsa(o.outDir, o.timeoutS);
  char took[32];
  std::snprintf(took, sizeof took, "%.1f", e.seconds);
  say(std::string("AMD ISA: ") + (e.isa.contains("error") ? e.isa["error"].get<std::string>()
                                                           : e.source == "cache" ? "read from the cache" : "measured") +
      " in " + took + " s");
  report["isaSource"] = {{"source", e.source}, {"seconds", e.seconds},
                         {"file", e.isa.contains("error") ? json(nullptr) : json("isa.json")}};
  report["isa"] = std::move(e.isa);
}

// How many of the run's scenes have a result (not marked interrupted).
int scenesMeasured(const std::vector<json>& scenes) {
  int n = 0;
  for (const json& s : scenes) n += !s.value("interrupted", false);
  return n;
}

}  // namespace

std::vector<std::string> scenePipelines(const Options& o, const std::string& spec) {
  return o.pipelines.empty() ? pipelineNames(curvedSceneSpace(spec)) : o.pipelines;
}

std::vector<std::string> runPipelines(const Options& o) {
  return o.pipelines.empty() ? pipelineNames() : o.pipelines;
}

namespace {

// The report folder cleared of an older report, created and marked partial, and a temporary
// folder for the workers' results; nullopt (the error printed) when one of them fails.
std::optional<fs::path> prepareFolders(const Options& o) {
  std::error_code ec;
  if (Status clear = clearOldReport(o.outDir, {o.benchJson, o.isaJson, o.morphJson}); !clear) {
    std::fprintf(stderr, "motorbench report: error: %s\n", clear.error().c_str());
    return std::nullopt;
  }
  fs::create_directories(o.outDir, ec);
  if (ec) {
    std::fprintf(stderr, "motorbench report: error: %s: cannot create folder: %s\n", o.outDir.c_str(),
                 ec.message().c_str());
    return std::nullopt;
  }
  if (Status m = markPartial(o.outDir, "motorbench report: this folder holds no complete report: the run is still "
                                       "going, or was stopped before it finished (this file goes when it completes)");
      !m) {
    std::fprintf(stderr, "motorbench report: error: %s\n", m.error().c_str());
    return std::nullopt;
  }
  std::string tmpl = (fs::temp_directory_path() / "motorbench-report-XXXXXX").string();
  if (!mkdtemp(tmpl.data())) {
    std::fprintf(stderr, "motorbench report: error: cannot create a temporary folder\n");
    return std::nullopt;
  }
  return fs::path(tmpl);
}

// The scenes of the run: the whole list named (ids made over all of it, so every shard names a
// scene and its image folder alike), this shard's part of it with each scene's --anim indices,
// and the shard's record.
struct RunInputs {
  std::vector<Input> all, inputs;
  std::vector<std::vector<int>> anims;
  json shard;
};

// The run's scenes (no scene named: every built-in scene, the curved ones last), --anim
// checked against the whole list (so every shard decides alike) before anything is measured;
// an error (a typo in --anim) stops the run.
Result<RunInputs> runInputs(const Options& o) {
  RunInputs r;
  std::vector<std::string> named = o.scenes;
  if (named.empty()) {
    named = builtinSceneNames();
    named.insert(named.end(), curvedSceneNames().begin(), curvedSceneNames().end());
  }
  r.all = expandInputs(named);
  std::vector<std::string> specs;
  for (const Input& in : r.all) specs.push_back(in.spec);
  r.shard = {{"index", o.shard.index}, {"count", o.shard.count}, {"inputs", json::array()}};
  for (const Input& in : r.all) r.shard["inputs"].push_back({{"spec", in.spec}, {"id", in.id}});
  std::vector<std::vector<int>> allAnims(r.all.size());
  if (!o.anim.empty()) {
    auto resolved = resolveAnimations(o.anim, r.all);
    if (!resolved) return Result<RunInputs>::fail(resolved.error());
    allAnims = *resolved;
  }
  for (size_t k : options::shardPositions(specs, o.shard)) {
    r.inputs.push_back(r.all[k]);
    r.anims.push_back(allAnims[k]);
  }
  return r;
}

// The run's opening lines on stderr: the shard's part, a warning for an empty shard, and what
// is measured with what.
void announceRun(const Options& o, const RunInputs& in) {
  const int total = int(in.inputs.size());
  if (o.shard.count > 1)
    say("shard " + std::to_string(o.shard.index) + "/" + std::to_string(o.shard.count) + ": " +
        std::to_string(total) + " of " + std::to_string(in.all.size()) + " scene(s)");
  if (const std::string note = options::emptyShardNote(o.shard, in.all.size(), in.inputs.size()); !note.empty())
    say("warning: " + note);
  say(std::to_string(total) + " scene(s), pipelines " + joined(runPipelines(o)) + ", " +
      std::to_string(o.jobs) + " job(s), images " + std::to_string(o.width) + "x" +
      std::to_string(o.height) + " -> " + o.outDir);
}

// Phase 1: images, metrics, memory, statistics, --jobs workers side by side; one result per
// scene, a dead worker's with the step it was on.
std::vector<json> renderPhase(const Options& o, const RunInputs& in, const fs::path& work) {
  const int total = int(in.inputs.size());
  std::vector<process::WorkerTask> tasks;
  for (int i = 0; i < total; ++i) {
    const std::string result = (work / (in.inputs[size_t(i)].id + ".render.json")).string();
    tasks.push_back({workerArgs(o, in.inputs[size_t(i)], i + 1, total, "render", result, in.anims[size_t(i)]), result,
                     {{"id", in.inputs[size_t(i)].id}, {"spec", in.inputs[size_t(i)].spec}}});
  }
  std::vector<json> scenes = process::runWorkers(tasks, o.jobs, o.timeoutS, "measured");
  for (size_t i = 0; i < scenes.size(); ++i) addLastStep(scenes[i], tasks[i].resultPath);
  return scenes;
}

// Phase 2: frame timing, one scene at a time (the scenes not failed), into each scene's
// "timing"; skipped with --frames 0 or once interrupted.
void timingPhase(const Options& o, const RunInputs& in, const fs::path& work, std::vector<json>& scenes) {
  if (o.frames <= 0 || process::interruptSignal() != 0) return;
  const int total = int(in.inputs.size());
  std::vector<process::WorkerTask> timing;
  std::vector<size_t> which;
  for (int i = 0; i < total; ++i) {
    if (scenes[size_t(i)].value("status", "failed") == "failed") continue;
    const std::string result = (work / (in.inputs[size_t(i)].id + ".time.json")).string();
    timing.push_back({workerArgs(o, in.inputs[size_t(i)], i + 1, total, "time", result, in.anims[size_t(i)]), result,
                      {{"id", in.inputs[size_t(i)].id}}});
    which.push_back(size_t(i));
  }
  std::vector<json> times = process::runWorkers(timing, 1, o.timeoutS, "timed");
  for (size_t t = 0; t < times.size(); ++t) addLastStep(times[t], timing[t].resultPath);
  for (size_t t = 0; t < times.size(); ++t) scenes[which[t]]["timing"] = times[t];
}

// The report's settings record: pipelines (the curved scenes' per space, over the whole list:
// alike in every shard), sizes, frames, instances, jobs, arguments and the shard.
json settingsJson(const Options& o, const RunInputs& in) {
  json curved = json::object();
  if (o.pipelines.empty())
    for (const Input& i : in.all)
      if (Space sp = curvedSceneSpace(i.spec); sp != Space::Euclidean) curved[spaceName(sp)] = pipelineNames(sp);
  const std::vector<std::string> pipelines = runPipelines(o);
  return {{"pipelines", pipelines}, {"baseline", pipelines.front()}, {"curvedPipelines", curved},
          {"anim", o.anim.empty() ? json(nullptr) : json(o.anim)},
          {"width", o.width}, {"height", o.height}, {"frames", o.frames},
          {"timeWidth", o.timeWidth}, {"timeHeight", o.timeHeight},
          {"instances", o.instances}, {"jobs", o.jobs}, {"arguments", o.scenes}, {"shard", in.shard}};
}

// An interrupted run: the report marked partial (before its documents are written, and kept),
// written without plots; exit 130.
int finishInterrupted(json report, const Options& o, const fs::path& work, int total) {
  std::error_code ec;
  const int measured = scenesMeasured(report["scenes"].get<std::vector<json>>());
  report["interrupted"] = {{"signal", process::interruptName()}, {"measured", measured}, {"scenes", total}};
  const std::string line = "INTERRUPTED (" + std::string(process::interruptName()) + "): " + std::to_string(measured) +
                           " of " + std::to_string(total) + " scenes measured; this report is partial";
  // The marker says it before the documents are written, and stays.
  markPartial(o.outDir, line);
  Options partial = o;
  partial.plots = false;
  writeReportFolder(std::move(report), partial);
  fs::remove_all(work, ec);
  std::fprintf(stderr, "motorbench report: %s (folder %s, marked %s); exit 130\n", line.c_str(), o.outDir.c_str(),
               kPartialMarker);
  return 130;
}

// A complete run: the folder written, its partial mark cleared and the answer printed; exit 0,
// 1 when a scene was not measured fully (listed on stderr), or the writer's error status.
int finishComplete(json report, const Options& o, const fs::path& work) {
  std::error_code ec;
  const std::vector<std::string> failures = document::failedSceneLines(report);  // as report.md lists them
  std::vector<std::string> answer;
  const int status = writeReportFolder(std::move(report), o, &answer);
  fs::remove_all(work, ec);
  if (status == 0) {
    clearPartialMark(o.outDir);
    // The answer on stdout as well (the lines of report.md's answer block), then where it is.
    for (const std::string& l : answer) std::printf("%s\n", l.c_str());
    std::printf("report: %s (report.md, report.json beside it)\n", (fs::path(o.outDir) / "report.html").string().c_str());
    std::fflush(stdout);
  }
  if (status != 0 || failures.empty()) return status;
  // As inspect: the report is written, but a scene that failed is not a success (exit 1).
  say(std::to_string(failures.size()) + " scene(s) not measured fully (exit 1):");
  for (const std::string& f : failures) say("  " + f);
  return 1;
}

}  // namespace

int runReport(const Options& o) {
  process::catchInterrupts();  // Ctrl-C / kill: the workers are stopped and the folder says it is partial
  std::error_code ec;
  const std::optional<fs::path> folder = prepareFolders(o);
  if (!folder) return 2;
  const fs::path work = *folder;
  auto in = runInputs(o);
  if (!in) {
    std::fprintf(stderr, "motorbench report: error: %s\n", in.error().c_str());
    fs::remove_all(work, ec);
    return 2;
  }
  announceRun(o, *in);
  std::vector<json> scenes = renderPhase(o, *in, work);
  timingPhase(o, *in, work, scenes);

  // Phase 3: ops per vertex (shared by every scene, weighted by each scene's vertices).
  say("counting ops per vertex (shim and SPIR-V)");
  json ops = measureOpsPerVertex();
  for (json& s : scenes)
    s["opsPerVertex"] = sceneOpsPerVertex(ops, s.value("vertexMix", json()), s.value("pipelines", json()));

  // Phase 3b: the curved spaces' camera drift (about a second), when the run has a curved scene.
  json curvedExtra = json::object();
  bool anyCurved = false;
  for (const Input& i : in->inputs) anyCurved = anyCurved || curvedSceneSpace(i.spec) != Space::Euclidean;
  if (anyCurved && process::interruptSignal() == 0) {
    say("measuring the curved camera drift (" + std::to_string(kReportDriftSteps) + " steps per space)");
    curvedExtra["drift"] = driftJson(kReportDriftSteps);
  }

  // Phase 4: kernel throughput.
  json kernelJson = process::interruptSignal() == 0 ? kernels(o)
                                            : json{{"source", "skipped"}, {"error", "not measured (interrupted)"}, {"file", nullptr}};
  json report = document::assembleReport(machineJson(), settingsJson(o, *in), std::move(scenes), std::move(ops),
                               std::move(kernelJson));
  report["summary"]["statistics"] = statisticsByOrigin(report["scenes"]);  // built-ins apart from files
  if (anyCurved) report["curved"] = curvedExtra;
  if (process::interruptSignal() == 0) attachIsa(report, o);
  else report["isa"] = {{"error", "not measured (interrupted)"}};
  if (!o.morphJson.empty()) {  // checked by the command before the run (schema motorbench-morph/1)
    std::ifstream morph(o.morphJson);
    report["morph"] = json::parse(morph, nullptr, false);
  }
  if (process::interruptSignal() != 0) return finishInterrupted(std::move(report), o, work, int(in->inputs.size()));
  return finishComplete(std::move(report), o, work);
}

int writeReportFolder(json report, const Options& o, std::vector<std::string>* answer) {
  document::addAnswerFigures(report);  // the answer block's figures: fetch, ISA, images (after isa is attached)
  document::addOpsRanking(report);     // where counted ops, SPIR-V and ISA order the pipelines differently (ops and isa)
  report["glossary"] = glossaryJson();    // what every counter means (shown in the documents)
  report["diffLegend"] = heatLegendJson();  // the heat maps' colour scale
  const fs::path jsonPath = fs::path(o.outDir) / "report.json";
  if (Status s = writeText(jsonPath, document::dumpJson(report, 2) + "\n"); !s) {
    std::fprintf(stderr, "motorbench report: error: %s\n", s.error().c_str());
    return 2;
  }
  // Phase 5: plots from report.json, then the final report.json and the documents.
  if (o.plots) {
    say("plotting (" + (o.python.empty() ? document::defaultPython() : o.python) + " scripts/plot.py)");
    report["plots"] = document::makePlots(o.python, o.plotScript, jsonPath.string(), o.outDir);
  } else {
    report["plots"] = {{"available", false}, {"error", "not made (--no-plots)"}, {"files", json::array()}};
  }
  document::Document doc = document::reportDocument(report);
  if (const json& stop = report.contains("interrupted") ? report["interrupted"] : json(); stop.is_object()) {
    // A partial report says so on its first line, before anything that could read as complete.
    document::Document top;
    top.paragraph("INTERRUPTED: " + std::to_string(stop.value("measured", 0)) + " of " +
                  std::to_string(stop.value("scenes", 0)) + " scenes measured (stopped by " +
                  stop.value("signal", std::string("a signal")) +
                  "); the figures below are of those scenes only, and the timing, kernel and ISA phases did not run.");
    doc.blocks.insert(doc.blocks.begin(), top.blocks.begin(), top.blocks.end());
  }
  if (answer) {
    answer->push_back("The answer: " + document::answerQuestion());
    for (const document::AnswerLine& l : document::answerLines(report)) answer->push_back("  " + l.evidence + ": " + l.text + " -> " + l.verdict);
  }
  for (const auto& [path, text] : {std::pair{jsonPath, document::dumpJson(report, 2) + "\n"},
                                   std::pair{fs::path(o.outDir) / "report.md", document::toMarkdown(doc)},
                                   std::pair{fs::path(o.outDir) / "report.html", document::toHtml(doc)}}) {
    if (Status s = writeText(path, text); !s) {
      std::fprintf(stderr, "motorbench report: error: %s\n", s.error().c_str());
      return 2;
    }
  }
  if (report.contains("interrupted")) return 0;  // the caller says what it is
  const json& sum = report["summary"];
  say("done: " + std::to_string(sum.value("scenes", 0)) + " scene(s), " +
      std::to_string(sum.value("ok", 0)) + " ok, " + std::to_string(sum.value("partial", 0)) +
      " partial, " + std::to_string(sum.value("failed", 0)) + " failed -> " +
      (fs::path(o.outDir) / "report.html").string());
  return 0;
}

}  // namespace mb::report
