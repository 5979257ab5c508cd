// `motorbench claims [-o FILE] [--json FILE] [--report report.json] [--bench-json FILE]
//   [--isa FILE] [--corpus DIR] [--scene-graphs FILE|DIR] [--skin-volumes FILE |
//   --skin-volumes-out FILE] [--frames N] [--no-run]`: every
// quantitative claim of the paper with the paper's value, the value measured now, how, and a
// verdict; plus our own rows (baselines, vs the strongest matrix variant, curved space), counted
// apart. Op counts and uploads are always measured here. Speed comes from a report (its kernel
// pairs, frame timings, device, uploads and ISA statistics) or a bench JSON when given, else from
// a short bench run (vertex and compose kernels only) and frame timing of four built-in scenes in
// this process; --no-run skips those runs (and the curved frame timing). Given a report, claims
// opens no GL context, renders and times nothing: a figure the report lacks is "not
// measurable here" with the reason. Scene
// statistics come from the report's scenes (else the built-in scenes) plus --corpus, or from
// the scene-graph corpus of --scene-graphs. The skinned real-file volumes are measured over
// --corpus (and kept in --skin-volumes-out), or read from such a file (--skin-volumes): a clone
// without the corpus judges the row on the figures measured where it was present.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>

#include "harness/options/args.h"
#include "harness/claims/claims_device.h"
#include "harness/claims/claims_layout.h"
#include "harness/claims/claims_morph.h"
#include "harness/claims/claims_quotes.h"
#include "harness/claims/corpus_stats.h"
#include "harness/claims/claims_sources.h"
#include "harness/cli/command.h"
#include "harness/cli/output_paths.h"
#include "harness/bench/report_bench.h"
#include "harness/document/report_answer.h"
#include "harness/document/report_format.h"
#include "harness/report/report_machine.h"
#include "harness/render/gpu_option.h"
#include "harness/render/render_frame.h"
#include "harness/timing/frame_timing.h"
#include "harness/timing/report_timing.h"
#include "pipelines/pipeline.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"

namespace mb {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

int fail(const std::string& message) { return commandError("claims", message); }

void say(const std::string& line) {
  std::fprintf(stderr, "claims: %s\n", line.c_str());
  std::fflush(stderr);
}

// Motor / matrix frame time of one timing configuration (report_timing.h's JSON): the paired
// ratio, which a slow spell of the machine cannot skew (it hits both frames of a pair), else
// the ratio of the medians; null when neither was measured.
json frameRatioOf(const json& config) {
  if (!config.is_object()) return nullptr;
  for (const char* key : {"paired_ratio_motor_matrix", "ratio_motor_matrix"})
    if (config.contains(key) && config[key].is_number()) return config[key];
  return nullptr;
}

// {"scene", "ratio", "vertexBound"} of one scene's timing, or null without a frame ratio.
json frameRow(const std::string& scene, const json& timing) {
  const json ratio = frameRatioOf(timing);
  if (ratio.is_null()) return nullptr;
  json row = {{"scene", scene}, {"ratio", ratio}};
  if (json vb = frameRatioOf(timing.value("vertexBound", json())); !vb.is_null()) row["vertexBound"] = vb;
  return row;
}

// Frame-time ratios of report.json's Euclidean scenes (the curved ones have their
// own pipelines and their own claims rows).
bool euclidean(const json& scene) { return scene.value("space", "Euclidean") == "Euclidean"; }

json frameTimesOf(const json& report) {
  json out = json::array();
  for (const json& s : report.value("scenes", json::array())) {
    if (!euclidean(s)) continue;
    if (json row = frameRow(s.value("id", ""), s.value("timing", json())); !row.is_null()) {
      // A report.json without timing.skinSpace timed each pipeline in its default skinning configuration.
      const json mix = s.value("vertexMix", json::object());
      const bool skinned = mix.is_object() && mix.value("skinned", 0.0) > 0.0;
      const json& timing = s.value("timing", json::object());
      row["skinSpace"] = !skinned ? json("-")
                         : timing.contains("skinSpace") ? timing["skinSpace"]
                                                        : json("pipeline defaults (matrix reference, motor world palette)");
      out.push_back(row);
    }
  }
  return out;
}

// The frame size(s) the report's scenes were timed at ("512x512"), from the timings themselves.
std::string timedSizes(const json& timings) {
  std::set<std::string> sizes;
  for (const auto& [scene, t] : timings.items())
    if (t.value("width", json()).is_number() && t.value("height", json()).is_number())
      sizes.insert(std::to_string(t["width"].get<int>()) + "x" + std::to_string(t["height"].get<int>()));
  std::string out;
  for (const std::string& s : sizes) out += (out.empty() ? "" : ", ") + s;
  return out;
}

// Speed inputs: from --report / --bench-json, else measured now (unless --no-run).
claims::SpeedInputs speedInputs(const Args& args, const json& report, json& sources) {
  claims::SpeedInputs in;
  std::string missing;
  const std::string reportPath = args.get("report", "");
  if (report.is_object()) {
    // value(), not operator[]: on a const json a missing key is undefined behaviour (a report
    // without kernels crashed here).
    const json kernels = report.value("kernels", json::object());
    const json pairs = kernels.is_object() ? kernels.value("pairs", json()) : json();
    if (pairs.is_array() && !pairs.empty()) {
      in.kernelPairs = pairs;
      const json file = kernels.value("file", json());
      in.kernelSource = reportPath + " (kernels from " + (file.is_string() ? file.get<std::string>() : "its bench run") + ")";
      in.kernelMachine = report.value("machine", json());
    }
    in.frameTimes = frameTimesOf(report);
    in.timings = json::object();
    in.sceneStats = json::object();
    for (const json& s : report.value("scenes", json::array())) {
      if (!euclidean(s)) continue;
      if (s.value("timing", json()).is_object()) in.timings[s.value("id", "")] = s["timing"];
      if (s.value("stats", json()).is_object()) in.sceneStats[s.value("id", "")] = s["stats"];
    }
    in.timingMachine = report.value("machine", json());
    const std::string sizes = timedSizes(in.timings);
    in.frameSource = reportPath + " (" + std::to_string(in.frameTimes.size()) + " scenes" +
                     (sizes.empty() ? "" : ", timed at " + sizes) + ")";
    if (report.value("isa", json()).is_object()) in.isa = report["isa"], in.isaSource = reportPath + " (its \"isa\")";
    if (report.value("opsRanking", json()).is_object())
      in.opsRanking = report["opsRanking"], in.opsRankingSource = reportPath + " (its \"opsRanking\")";
  }
  if (auto i = args.get("isa"); i && in.isa.is_null()) {
    std::ifstream f(*i);
    json isa = json::parse(f, nullptr, false);
    if (isa.is_discarded() || !isa.is_object()) missing += *i + ": cannot read the isa JSON; ";
    else in.isa = isa, in.isaSource = *i;
  }
  if (auto b = args.get("bench-json"); b && in.kernelPairs.is_null()) {
    auto j = report::readBenchJson(*b);
    if (j) in.kernelPairs = report::kernelPairs(*j)["pairs"], in.kernelSource = *b;
    else missing += j.error() + "; ";
  }
  // Beside a report nothing is run: its figures are the ones it measured.
  const bool run = !args.has("no-run") && !report.is_object();
  if (in.kernelPairs.is_null() && run) {
    const std::string tmp = (fs::temp_directory_path() / ("motorbench-claims-bench-" + std::to_string(getpid()) + ".json")).string();
    say("running motorbench bench (vertex_frame, skinned_vertex, hierarchy and compose kernels, short)");
    Status s = report::runBench(tmp, tmp + ".txt", 0.1, "^(vertex_frame|skinned_vertex|hierarchy|compose)/");
    auto j = s ? report::readBenchJson(tmp) : Result<json>::fail(s.error());
    if (j) in.kernelPairs = report::kernelPairs(*j)["pairs"], in.kernelSource = "motorbench bench run by claims (min time 0.1 s)";
    else missing += j.error() + "; ";
    std::error_code ec;
    fs::remove(tmp, ec), fs::remove(tmp + ".txt", ec);
  }
  if ((in.frameTimes.is_null() || in.frameTimes.empty()) && run) {
    in.frameTimes = json::array();
    in.timings = json::object();
    in.sceneStats = json::object();
    const int frames = int(args.integer("frames", 20, 1, 100000));
    // dense_torus: the vertex-bound rigid normal-mapped scene; crowd: the vertex-bound skinned
    // one, timed with both pipelines in the same skinning configuration (as the references do).
    for (const char* name : {"normal_torus", "skinned_tube", "crowd", "dense_torus"}) {
      say(std::string("timing ") + name + " (" + std::to_string(frames) + " frames per pipeline)");
      auto scene = loadScene(name);
      if (!scene) continue;
      in.sceneStats[name] = toJson(computeFileStats(*scene));
      PipelineOptions options;
      if (!scene->skins.empty()) options.skinSpace = SkinSpace::Reference;
      const json t = report::timeScene(*scene, pipelineNames(), frames, 512, 512, options);
      in.timings[name] = t;
      json row = frameRow(name, t);
      if (row.is_null()) {
        missing += std::string(name) + " timing: " + (t["error"].is_string() ? t["error"].get<std::string>() : "no ratio") + "; ";
        continue;
      }
      row["skinSpace"] = scene->skins.empty() ? "-" : "reference (both pipelines)";
      in.frameTimes.push_back(row);
    }
    in.timingMachine = report::machineJson();
    in.frameSource = "frame timing run by claims on normal_torus, skinned_tube, crowd and dense_torus at " + timedSizes(in.timings) +
                     ", crowd and dense_torus also vertex-bound (" + std::to_string(timing::kVertexBoundVerticesPerPixel) +
                     " vertices per pixel); skinned scenes with both pipelines in the reference skinning configuration";
  }
  if (in.kernelPairs.is_null())
    missing += std::string("no kernel throughput (") +
               (report.is_object() ? reportPath + " has no kernel pairs" : std::string("no --report")) +
               (args.has("bench-json") ? "" : ", no --bench-json") +
               (run ? "" : report.is_object() ? ", and claims runs nothing beside a report" : ", and --no-run skips the bench run") + "); ";
  if (in.frameTimes.is_null() || in.frameTimes.empty())
    missing += std::string("no frame timing (") + (report.is_object() ? reportPath + " has none" : std::string("no --report")) +
               (run ? "" : report.is_object() ? ", and claims times nothing beside a report" : ", and --no-run skips timing") + "); ";
  // The machine of the kernel figures: the report's (its bench ran there), else this one.
  if (in.kernelMachine.is_null()) in.kernelMachine = report.is_object() ? report.value("machine", json()) : report::machineJson();
  if (!missing.empty()) missing.resize(missing.size() - 2);
  in.missing = missing;
  sources["kernels"] = in.kernelSource.empty() ? "none" : in.kernelSource;
  sources["frameTiming"] = in.frameSource.empty() ? "none" : in.frameSource;
  sources["isa"] = in.isaSource.empty() ? "none" : in.isaSource;
  sources["opsRanking"] = in.opsRankingSource.empty() ? "claims' own op counts and the isa above" : in.opsRankingSource;
  return in;
}

// The skinned real-file volume row: judged on the figures of --skin-volumes FILE, else measured
// over `corpusDir` (and written to --skin-volumes-out FILE when given); an error names the file.
Result<std::vector<claims::Claim>> skinnedFileVolumeRows(const Args& args, const std::string& corpusDir) {
  using Rows = Result<std::vector<claims::Claim>>;
  if (auto in = args.get("skin-volumes")) {
    std::ifstream f(*in);
    if (!f) return Rows::fail("--skin-volumes " + *in + ": cannot read");
    const json v = json::parse(f, nullptr, false);
    if (v.is_discarded() || !v.is_object() || v.value("schema", "") != claims::kSkinVolumesSchema ||
        !v.value("meshes", json()).is_array())
      return Rows::fail("--skin-volumes " + *in + ": not a " + claims::kSkinVolumesSchema + " JSON (claims --skin-volumes-out)");
    return claims::skinnedFileVolumeClaimsFrom(v, *in);
  }
  if (auto out = args.get("skin-volumes-out")) {
    auto v = claims::measureSkinnedFileVolumes(corpusDir);
    if (!v) return Rows::fail("--skin-volumes-out: nothing to write: " + v.error());
    if (Status ok = writeTextFile(*out, report::dumpJson(*v, 1) + "\n"); !ok) return Rows::fail(ok.error());
    return claims::skinnedFileVolumeClaimsFrom(*v, *out);
  }
  return claims::skinnedFileVolumeClaims(corpusDir);
}

// Every row of one family, marked as the paper's claim or one of our own rows.
void add(std::vector<claims::Claim>& all, std::vector<claims::Claim> rows, const char* own = nullptr) {
  for (claims::Claim& c : rows) {
    if (own) c.origin = own;
    all.push_back(std::move(c));
  }
}

int runClaims(const std::vector<std::string>& argv) {
  const Args args(argv, {{"o", "output", "json", "report", "corpus-report", "bench-json", "isa", "corpus", "scene-graphs",
                                "skin-volumes", "skin-volumes-out", "frames", "gpu"},
                               {"no-run"},
                               {}});
  if (!args.error().empty()) return fail(args.error());
  if (!args.positional().empty()) return fail("unexpected argument '" + args.positional()[0] + "'");
  if (Status gpu = applyGpuOption(args); !gpu) return fail(gpu.error());  // the report it runs inherits MB_GPU
  args.integer("frames", 20, 1, 100000);  // checked here; speedInputs reads it
  if (args.get("skin-volumes") && args.get("skin-volumes-out")) return fail("give --skin-volumes or --skin-volumes-out, not both");
  // Every output is checked (folders created) before minutes of measuring.
  for (const char* key : {"json", "o", "output", "skin-volumes-out"})
    if (auto path = args.get(key))
      if (Status ok = prepareOutputFile(std::string(key) == "o" ? "-o" : std::string("--") + key, *path); !ok)
        return fail(ok.error());
  json report;
  if (auto r = args.get("report")) {
    std::ifstream f(*r);
    if (!f) return fail(*r + ": cannot read");
    report = json::parse(f, nullptr, false);
    if (report.is_discarded() || !report.is_object()) return fail(*r + ": not a report.json (JSON object expected)");
  }
  claims::CorpusInputs corpus;
  corpus.corpusDir = args.get("corpus", "../shared/corpus");
  if (report.is_object()) corpus.reportScenes = report.value("scenes", json()), corpus.reportSource = *args.get("report");
  if (auto g = args.get("scene-graphs")) {
    say("scene-graph statistics of " + *g);
    auto files = claims::corpusFiles(*g);
    if (!files) return fail(files.error());
    corpus.sceneGraphs = *files;
    corpus.sceneGraphSource = std::to_string(files->size()) + " scene graphs of " + *g;
  }
  // Given a report, every upload figure is the report's (claims_uploads.h): no GL context here.
  claims::Uploads uploads =
      report.is_object() ? claims::Uploads(report.value("scenes", json()), *args.get("report")) : claims::Uploads();
  if (auto c = args.get("corpus-report"); c && report.is_object()) {  // real files: vertices without a normal map
    std::ifstream f(*c);
    const json corpusReport = json::parse(f, nullptr, false);
    if (corpusReport.is_discarded() || !corpusReport.is_object()) return fail(*c + ": not a report.json");
    uploads.addReport(corpusReport.value("scenes", json()), *c);
  }
  json sources = {{"opCounts", "shaders/pga.glsl, shaders/matrix_transform.glsl, shaders/motor_transform.glsl "
                                "executed on mb::Counted; SPIR-V via glslangValidator + spirv-opt"},
                  {"memory", "PipelineStats of the built-in normal_torus and skinned_tube: " + uploads.source()},
                  {"sceneStatistics", corpus.sceneGraphs.is_array() ? corpus.sceneGraphSource
                                      : (report.is_object() ? "the scenes of " + corpus.reportSource : std::string("built-in scenes")) +
                                            " + " + corpus.corpusDir}};
  std::vector<claims::Claim> all;
  const bool run = !args.has("no-run") && !report.is_object();  // beside a report: nothing timed
  say("counting ops");
  add(all, claims::opClaims());
  say("composition (counted; timed by the bench's compose pair)");
  claims::SpeedInputs speed = speedInputs(args, report, sources);
  add(all, claims::compositionClaims(speed.kernelPairs));
  say("conversions, handedness rule, blending");
  add(all, claims::conversionClaims(uploads));
  add(all, claims::handednessClaims());
  add(all, claims::blendingClaims());
  say("measuring uploads");
  add(all, claims::memoryClaims(uploads));
  add(all, claims::compactClaims(speed.isa, speed.isaSource, report, args.get("report", "")), "compact");
  add(all, claims::morphClaims(report, args.get("report", "")), "morph");
  add(all, claims::speedClaims(speed));
  add(all, claims::sceneGraphClaims(speed.kernelPairs, speed.timings, sources["frameTiming"].get<std::string>(), speed.sceneStats));
  say("scene statistics");
  add(all, claims::corpusClaims(corpus));
  say("baselines (counted and SPIR-V)");
  add(all, claims::skinningClaims());
  auto fileVolumes = skinnedFileVolumeRows(args, corpus.corpusDir);
  if (!fileVolumes) return fail(fileVolumes.error());
  add(all, fileVolumes.take());
  add(all, claims::baselineClaims(), "baseline");
  say("curved space (uploads, ops, frame timing, drift)");
  add(all, claims::curvedClaims(run, int(args.integer("frames", 20, 1, 100000)),
                                report.is_object() ? report.value("scenes", json()) : json(), uploads),
      "curved");  // no --report: null
  say("against the strongest baseline (every pipeline)");
  add(all, claims::strongestBaselineClaims(speed.timings, sources["frameTiming"].get<std::string>(), speed.kernelPairs,
                                           speed.kernelSource, speed.sceneStats, speed.timingMachine, uploads),
      "vs strongest");
  add(all, claims::isaStrongestClaims(speed.isa, speed.isaSource), "vs strongest");

  claims::applyPaperQuotes(all);  // a row quoting the paper is the paper's; the rest are ours
  // The machine the figures were measured on: the report's when given (claims itself measures
  // only deterministic counts), so that the same inputs give the same claims, byte for byte.
  json machine = report.is_object() ? report.value("machine", json()) : report::machineJson();
  json scope = {{"cpu", claims::cpuScope(speed.kernelMachine)},
                {"frameTimeDevice", claims::timingDevice(speed.timingMachine).label()}};
  json j = claims::claimsJson(all, machine, sources, scope);
  const std::string mdPath = args.get("o", args.get("output", ""));
  report::Document doc = claims::claimsDocument(j);
  if (report.is_object()) {
    // The answer first, the same lines as report.md's: read from the report's figures, measured here never.
    j["answer"] = report::answerJson(report);
    const fs::path reportMd = fs::path(*args.get("report")).parent_path() / "report.md";
    const fs::path mdDir = mdPath.empty() ? fs::current_path() : fs::absolute(mdPath).parent_path();
    doc = report::withAnswerFirst(doc, report, fs::absolute(reportMd).lexically_relative(mdDir).generic_string());
  } else {
    doc.blocks.insert(doc.blocks.begin(), {report::Block::Kind::Paragraph, 0,
                                           "No answer block: it quotes a report's figures (claims --report report.json)."});
  }
  const std::string md = report::toMarkdown(doc);
  if (auto path = args.get("json")) {
    if (Status ok = writeTextFile(*path, report::dumpJson(j, 2) + "\n"); !ok) return fail(ok.error());
  }
  if (mdPath.empty()) {
    std::fputs(md.c_str(), stdout);
  } else {
    if (Status ok = writeTextFile(mdPath, md); !ok) return fail(ok.error());
  }
  auto tally = [](const json& c) {
    return c["reproduced"].dump() + " reproduced, " + c["differs"].dump() + " differ, " + c["inconclusive"].dump() +
           " inconclusive, " + c["not measurable here"].dump() + " not measurable";
  };
  say(std::to_string(all.size()) + " rows; the paper's claims: " + tally(j["paperCounts"]) + "; our own rows: " +
      tally(j["ownCounts"]) + ", " + j["ownCounts"]["baseline"].dump() + " baselines");
  return 0;
}

}  // namespace
}  // namespace mb

MB_COMMAND(claims, "claims",
           "[-o FILE] [--json FILE] [--report report.json] [--corpus-report FILE] [--bench-json FILE] [--isa FILE] [--corpus DIR] "
           "[--scene-graphs FILE|DIR] [--skin-volumes FILE | --skin-volumes-out FILE] [--frames N] [--no-run] [--gpu auto|llvmpipe|N]",
           "every quantitative claim of the paper: paper value, measured value, method, verdict (Markdown/JSON)",
           mb::runClaims);
MB_COMMAND_HELP(claims, "claims",
               "  -o FILE            claims.md (default: stdout);  --json FILE  claims.json\n"
               "                     (missing folders are created; both checked before the work)\n"
               "  --report FILE      kernel ratios, frame timings, uploads and image figures from a report.json;\n"
               "                     with it claims opens no GL context, renders and times nothing\n"
               "  --corpus-report F  a report.json of real files: the uploads of vertices without a normal map\n"
               "                     (with --report)\n"
               "  --bench-json FILE  kernel ratios from a `motorbench bench --out` file\n"
               "  --isa FILE         ISA statistics (a `motorbench isa --json` file; else the report's \"isa\")\n"
               "  --scene-graphs F   scale statistics of a corpus: an inspect --json file or a folder, e.g.\n"
               "                     ../shared/corpus-graph\n"
               "  --corpus DIR       the real glTF files for the statistics and skinning rows (default ../shared/corpus)\n"
               "  --skin-volumes-out F  write the skinned-file volumes measured over --corpus to F (the row names F)\n"
               "  --skin-volumes F   judge the skinned-file volume row on F (written by --skin-volumes-out where the\n"
               "                     corpus was present) instead of measuring --corpus\n"
               "  --frames N         frames per pipeline when claims times scenes itself (default 20)\n"
               MB_GPU_OPTION_HELP
               "  --no-run           run no benchmark and time no frame (no curved-space\n"
               "                     frame timing): speed rows come only from --report or\n"
               "                     --bench-json (else \"not measurable here\"). Everything else is still measured:\n"
               "                     op counts (shim and SPIR-V, glslangValidator + spirv-opt per shader variant),\n"
               "                     uploads of the built-in scenes, conversions, the handedness rule over every\n"
               "                     built-in frame, blending, the corpus statistics and the curved-space rows;\n"
               "                     this takes minutes (3 min on a 2-core machine), printed step by step on stderr.\n",
                "motorbench claims --no-run --json out/claims.json -o out/claims.md", false);
