// `motorbench inspect FILE|DIR|BUILTIN... [--summary] [--json FILE] [--shard I/N]`: per-file
// statistics of glTF files (geometry, materials, skins, animations, scale classes, unsupported
// features, fallbacks) and, for several files, their aggregate, plus each file's animations
// (name, duration, channels) and cameras (type, name); --summary prints the aggregate alone (and
// the files that failed, on stderr). Several files: progress on stderr with the time left. A file
// that fails to load is listed with its error and the run goes on; exit 0 when every input
// loaded, 1 when any failed (or nothing was found to inspect: an empty folder is warned about),
// 2 on bad usage or an unwritable --json.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "harness/options/args.h"
#include "harness/options/shard.h"
#include "harness/process/progress.h"
#include "harness/report/corpus_models.h"
#include "harness/report/corpus_stats.h"
#include "harness/report/report_inputs.h"
#include "harness/cli/command.h"
#include "harness/cli/output_paths.h"
#include "harness/render/frame_options.h"
#include "harness/render/scene_inputs.h"
#include "pipelines/motor/fallback_census.h"
#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"
#include "pipelines/scene/similarity_tolerance.h"

namespace {

namespace fs = std::filesystem;

// Files named on the command line, folders expanded (recursively, sorted): the report's rule.
std::vector<std::string> expand(const std::vector<std::string>& inputs) {
  std::vector<std::string> out;
  for (const mb::report::Input& in : mb::report::expandInputs(inputs)) out.push_back(in.spec);
  return out;
}

void printFallbacks(const nlohmann::json& fb) {
  std::string line;
  for (const auto& [k, v] : fb.items())
    if (v.get<int>() != 0) line += (line.empty() ? "" : ", ") + k + " " + std::to_string(v.get<int>());
  std::printf("  fallbacks   %s\n", line.empty() ? "none" : line.c_str());
}

void printFile(const mb::FileStats& f) {
  std::printf("%s\n", f.file.c_str());
  if (!f.loaded) {
    std::printf("  FAILED      %s\n", f.error.c_str());
    return;
  }
  const auto& r = f.scale;
  std::printf("  geometry    %d meshes, %d primitives, %d vertices, %d triangles; %d nodes (%d matrix), "
              "%d mesh nodes drawing %d vertices\n",
              f.meshes, f.primitives, f.vertices, f.triangles, f.nodes, f.matrixNodes, f.meshNodes, f.drawnVertices);
  if (f.patches > 0)
    std::printf("  patches     %d bicubic Bezier patches (drawn vertices at the default tessellation level)\n", f.patches);
  std::printf("  materials   %d materials, %d textures, %d images; %d normal-mapped primitives "
              "(%d with authored TANGENT)\n",
              f.materials, f.textures, f.images, f.normalMappedPrimitives, f.authoredTangentPrimitives);
  std::printf("  skinning    %d skins, %d joints (max %d per skin), %d skinned primitives\n", f.skins, f.joints,
              f.maxJointsPerSkin, f.skinnedPrimitives);
  std::printf("  animation   %d animations, %d channels (T %d, R %d, S %d, weights %d; LINEAR %d, STEP %d, "
              "CUBICSPLINE %d)\n",
              f.animations, f.channels, f.translationChannels, f.rotationChannels, f.scaleChannels,
              f.weightsChannels, f.linearChannels, f.stepChannels, f.cubicChannels);
  std::printf("  morph       %d targets on %d meshes (max %d per mesh, %d primitives); %d animated weights channels\n",
              f.morphTargets, f.morphMeshes, f.maxMorphTargets, f.morphPrimitives, f.weightsChannels);
  std::printf("  scale       nodes: %d uniform, %d non-uniform, %d negative, %d sheared (tolerance %g relative); "
              "animated on %d nodes (%d non-uniform keys); non-uniform only on leaves: %s\n",
              r.uniformNodes, r.nonUniformNodes, r.negativeNodes, r.shearNodes, mb::kSimilarityTolerance, r.animatedScaleNodes,
              r.animatedNonUniformNodes, r.nonUniformScale ? (r.nonUniformOnlyOnLeaves ? "yes" : "no") : "n/a");
  std::printf("  compression %s\n", mb::describeCompression(f.compression).c_str());
  if (!f.notDrawn.empty()) std::printf("  NOT DRAWN   %s (render, compare and time refuse it)\n", f.notDrawn.c_str());
  printFallbacks(mb::toJson(f.fallbacks));
  if (f.unsupported.empty()) std::printf("  unsupported none\n");
  for (const auto& u : f.unsupported) std::printf("  unsupported %s\n", u.c_str());
}

// The motor family's exact fallback at rest (pipelines/motor/fallback_census.h): a line (unless
// `quiet`), and "motorFallbacks" in the file's JSON.
void describeMotorFallbacks(const mb::Scene& scene, nlohmann::json& file, bool quiet) {
  if (scene.curved.space != mb::Space::Euclidean) return;
  const mb::motor::FallbackCensus c = mb::motor::restFallbackCensus(scene);
  file["motorFallbacks"] = {{"generalNodes", c.generalNodes}, {"linearFallbackDraws", c.linearDraws},
                            {"skinFallbackDraws", c.skinPalettes}, {"skinFallbackJoints", c.skinJoints},
                            {"fallbackVertices", c.vertices}};
  if (quiet) return;
  if (c.linearDraws + c.skinPalettes == 0 && c.generalNodes == 0)
    std::printf("  motor exact fallback none (every draw a similarity)\n");
  else
    std::printf("  motor exact fallback %d nodes not similarities; at rest %d rigid draws, %d skins (%d joints), "
                "%llu vertices\n",
                c.generalNodes, c.linearDraws, c.skinPalettes, c.skinJoints, (unsigned long long)c.vertices);
}

// The animations (name, duration, channels) and cameras (type, name) of a loaded scene, as
// text lines (unless `quiet`) and as JSON ("animationList", "cameraList" of the file's entry).
void describeViews(const mb::Scene& scene, nlohmann::json& file, bool quiet) {
  nlohmann::json anims = nlohmann::json::array(), cams = nlohmann::json::array();
  for (size_t i = 0; i < scene.animations.size(); ++i) {
    const mb::Animation& a = scene.animations[i];
    if (!quiet) std::printf("  animation %zu '%s': %.3f s, %zu channels\n", i, a.name.c_str(), double(a.duration), a.channels.size());
    anims.push_back({{"index", i}, {"name", a.name}, {"duration", a.duration}, {"channels", a.channels.size()}});
  }
  for (size_t i = 0; i < scene.cameras.size(); ++i) {
    const mb::Camera& c = scene.cameras[i];
    const char* type = c.perspective ? "perspective" : "orthographic";
    if (!quiet) std::printf("  camera %zu '%s': %s\n", i, c.name.c_str(), type);
    cams.push_back({{"index", i}, {"name", c.name}, {"type", type}});
  }
  if (scene.cameras.empty() && !quiet) std::printf("  cameras     none (render/compare frame the scene automatically)\n");
  file["animationList"] = anims;
  file["cameraList"] = cams;
}

void printAggregate(const nlohmann::json& a) {
  int loaded = a["loaded"];
  auto pct = [&](const char* count) {
    int n = a[count];
    char buf[64];
    if (loaded == 0) return std::string("- (no file loaded)");
    std::snprintf(buf, sizeof buf, "%d/%d files (%.1f %%)", n, loaded, 100.0 * n / loaded);
    return std::string(buf);
  };
  std::printf("\naggregate over %d files: %d loaded, %d failed\n", int(a["files"]), loaded, int(a["failed"]));
  std::printf("  totals      %ld vertices, %ld triangles, %ld primitives, %ld joints, %ld channels\n",
              long(a["vertices"]), long(a["triangles"]), long(a["primitives"]), long(a["joints"]), long(a["channels"]));
  std::printf("  scale channel             %s\n", pct("filesWithAnimatedScale").c_str());
  std::printf("  keys changing the scale   %s   (beyond %g relative; paper: < 0.5 %% of ~400 files)\n",
              pct("filesWithChangingScale").c_str(), mb::kSimilarityTolerance);
  std::printf("  inner non-uniform scale   %s   (beyond %g relative, the paper's rule; paper: none)\n",
              pct("filesWithInnerNonUniformScale").c_str(), mb::kSimilarityTolerance);
  std::printf("  animated non-uniform      %s\n", pct("filesWithAnimatedNonUniformScale").c_str());
  std::printf("  non-uniform scale         %s (beyond %g relative), of which only on leaves: %d\n",
              pct("filesWithNonUniformScale").c_str(), mb::kSimilarityTolerance,
              int(a["filesWithNonUniformOnlyOnLeaves"]));
  std::printf("  negative scale (det < 0)  %s\n", pct("filesWithNegativeScale").c_str());
  std::printf("  skinned %d, normal-mapped %d, with unsupported features %d, with fallbacks %d\n",
              int(a["filesSkinned"]), int(a["filesNormalMapped"]), int(a["filesWithUnsupported"]),
              int(a["filesWithFallbacks"]));
}

int runInspect(const std::vector<std::string>& argv) {
  mb::options::Args args(argv, {{"json", "shard"}, {"summary"}, {}});
  if (!args.error().empty() || args.positional().empty()) {
    std::fprintf(stderr, "usage: motorbench inspect FILE|DIR|BUILTIN... [--summary] [--json FILE] [--shard I/N]\n  %s\n",
                 args.error().empty() ? "expected at least one FILE, DIR or built-in scene name" : args.error().c_str());
    return 2;
  }
  mb::options::Shard shard;
  if (auto text = args.get("shard")) {
    std::string error;
    auto parsed = mb::options::parseShard(*text, &error);
    if (!parsed) {
      std::fprintf(stderr, "motorbench inspect: error: %s\n", error.c_str());
      return 2;
    }
    shard = *parsed;
  }
  if (auto path = args.get("json"))
    if (mb::Status ok = mb::prepareOutputFile("--json", *path); !ok) {
      std::fprintf(stderr, "motorbench inspect: error: %s\n", ok.error().c_str());
      return 2;
    }
  for (const std::string& w : mb::emptyInputWarnings(args.positional()))
    std::fprintf(stderr, "motorbench inspect: warning: %s\n", w.c_str());
  const std::vector<std::string> all = expand(args.positional());
  std::vector<mb::FileStats> stats;
  nlohmann::json files = nlohmann::json::array();
  int failed = 0;
  const std::vector<size_t> mine = mb::options::shardPositions(all, shard);
  if (const std::string note = mb::options::emptyShardNote(shard, all.size(), mine.size()); !note.empty())
    std::fprintf(stderr, "motorbench inspect: %s\n", note.c_str());
  const bool summary = args.has("summary");
  // Per-file lines go to stdout (unless --summary): the progress is plain lines there, at most
  // one a second; with --summary it may rewrite one line on a terminal.
  std::optional<mb::process::Progress> progress;
  if (mine.size() > 1) progress.emplace("inspect", "files inspected", mine.size(), summary, 1.0);
  for (size_t k : mine) {
    const std::string& file = all[k];
    mb::Status spec = mb::checkSceneSpec(file);  // "no such file, and not a built-in (built-in: ...)"
    auto scene = spec ? mb::loadScene(file) : mb::Result<mb::Scene>::fail(spec.error());
    stats.push_back(scene ? mb::computeFileStats(*scene) : mb::failedFileStats(file, scene.error()));
    if (!summary) printFile(stats.back());
    if (summary && !scene) std::fprintf(stderr, "motorbench inspect: FAILED %s\n", scene.error().c_str());  // names the file
    files.push_back(mb::toJson(stats.back()));
    files.back()["input"] = file;  // the argument (a built-in's "file" is its generated name)
    if (scene) files.back()["contentHash"] = mb::report::contentHash(*scene);  // duplicate models
    if (scene) describeMotorFallbacks(*scene, files.back(), summary);
    if (scene) describeViews(*scene, files.back(), summary);
    failed += !scene;
    if (progress) progress->done(file);
  }
  progress.reset();  // its last line before the aggregate
  nlohmann::json aggregate = mb::aggregateJson(stats);
  // By source kind when the files' folder has a MANIFEST.tsv (../shared/corpus-graph), and files
  // of the same content (harness/report/corpus_models.h): the figures count each model once.
  mb::report::addCorpusAggregates(files, aggregate);
  if (stats.size() > 1 || summary) printAggregate(aggregate);
  if (stats.size() > 1 || summary)
    std::printf("  models      %s (%zu duplicate groups; the same content hash: see \"models\" in --json)\n",
                mb::report::filesAndModels(mb::report::distinctModels(files)).c_str(),
                aggregate["models"]["duplicateGroups"].get<size_t>());
  if (auto path = args.get("json")) {
    // replace: error messages may quote file bytes or paths that are not UTF-8.
    const nlohmann::json shardJson = {{"index", shard.index}, {"count", shard.count}, {"inputs", all}};
    const nlohmann::json doc = {{"files", files}, {"aggregate", aggregate}, {"shard", shardJson},
                                {"figures", mb::report::scaleFigures(files)}};
    const std::string text = doc.dump(
                                 2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
    if (mb::Status w = mb::writeTextFile(*path, text); !w) {
      std::fprintf(stderr, "motorbench inspect: %s\n", w.error().c_str());
      return 2;
    }
  }
  if (all.empty()) {  // (an empty shard of a non-empty list is fine)
    std::fprintf(stderr, "motorbench inspect: warning: nothing to inspect (no .gltf or .glb files found)\n");
    return 1;
  }
  if (failed > 0) {
    std::fprintf(stderr, "motorbench inspect: %d of %zu input(s) failed to load (listed as FAILED above)\n", failed,
                 mine.size());  // (--summary: on stderr)
    return 1;
  }
  return 0;
}

}  // namespace

MB_COMMAND(inspect, "inspect", "FILE|DIR|BUILTIN... [--summary] [--json FILE] [--shard I/N]",
           "glTF statistics: geometry, skins, animations (name, duration, channels), cameras, scale "
           "classes, unsupported features, fallbacks; exit 1 when any input failed to load",
           runInspect);
MB_COMMAND_HELP(inspect, "inspect",
               "  FILE|DIR|BUILTIN...  files, folders (searched for .gltf/.glb) or built-in scene names\n"
               "  --summary          only the aggregate over the files (the files that failed on stderr; default: every\n"
               "                     file's statistics, then the aggregate); several files: progress on stderr either way\n"
               "  --json FILE        everything as JSON (missing folders are created; checked before the work)\n"
               "  --shard I/N        only every N-th input from the I-th (merge puts shards together)\n",
                "motorbench inspect skinned_tube crowd --json out/inspect.json", false);
