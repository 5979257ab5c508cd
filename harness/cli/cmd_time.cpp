// `motorbench time [SCENE|DIR...] [--pipelines A,B...] [--anim A] [--frames N] [--warmup W] [--size WxH]
//  [--tiny WxH] [--best-of K] [--level N[,M...]] [--instances N] [--lp-threads N] [--json FILE]`: frame time
// of every registered pipeline (or those --pipelines names) on each scene, playing one animation
// (--anim, default 0; said per scene, never a blend of two)
// (harness/timing/frame_timing.h), printed as medians with quartiles and as motor/matrix ratios
// measured in the same run. No SCENE: every built-in scene. A scene that draws at least
// timing::kVertexBoundVerticesPerPixel vertices per pixel of a tiny viewport (--tiny, default
// 64x64; of the built-in scenes the crowd) also runs there: the vertex-bound configuration.
// Each scene is timed in a child process of its own (`time SCENE --worker FILE`), one after
// the other: in one long-lived process a scene timed after another one inherited its heap
// layout, and textured_box's ratio then swung between 0.64 and 1.00 from run to run (alone:
// 0.98..1.01); a scene that crashes the driver is also reported while the others go on.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "harness/options/args.h"
#include "harness/process/progress.h"
#include "harness/cli/command.h"
#include "harness/cli/output_paths.h"
#include "harness/ops/patch_memory.h"
#include "harness/timing/frame_timing.h"
#include "harness/timing/timing_text.h"
#include "harness/process/report_workers.h"
#include "harness/render/frame_options.h"
#include "harness/render/gpu_option.h"
#include "harness/render/scene_inputs.h"
#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/gl/patch_geometry.h"
#include "pipelines/scene/drawable.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"

namespace mb {
namespace {

// A worker (one scene) that runs longer than this is killed and reported as an error.
constexpr double kWorkerTimeoutS = 3600;

// One block per scene and configuration: every pipeline with its ratios to matrix and their
// spread (harness/timing/timing_text.h).
void printRow(const timing::ConfigTiming& c) {
  std::printf("%s\n", timing::timingBlock(c).c_str());
  std::fflush(stdout);
}

// Child side: loads and times one scene (also at the tiny viewport when the scene draws enough
// vertices to be vertex-bound there: timing::drawsVertexBoundAt), prints its rows and writes
// {"rows": [...], "patchMemory": [...] or null} to `resultPath` (patchMemory: the bytes table of
// a Bezier patch scene timed with --level). Exit 0, or 2 when anything failed.
int timeOneScene(const std::string& name, const timing::Settings& normal, const timing::Settings& tiny,
                 const std::vector<int>& levels, const options::Args& args, const std::string& resultPath) {
  nlohmann::json rows = nlohmann::json::array(), patchMemory = nullptr;
  int status = 0;
  const Status spec = checkSceneSpec(name);  // a misspelt name lists the built-ins
  auto scene = spec ? loadScene(name) : Result<Scene>::fail(spec.error());
  if (scene)  // a blank frame is no timing
    if (std::string why = whyNothingDrawn(*scene); !why.empty())
      scene = Result<Scene>::fail(scene->source + ": nothing to draw: " + why);
  if (scene) {  // --instances N: every mesh node drawn N times (frame_options.h)
    std::vector<std::string> notes;
    auto instances = applyInstancesOption(args, *scene, &notes);
    if (!instances) scene = Result<Scene>::fail(instances.error());
    for (const std::string& note : notes) std::fprintf(stderr, "motorbench time: %s\n", note.c_str());
  }
  if (!scene) {
    std::fprintf(stderr, "motorbench time: error: %s\n", scene.error().c_str());
    rows.push_back({{"scene", name}, {"error", scene.error()}});
    status = 2;
  }
  // The one animation played, said before the rows (a file with several would otherwise leave
  // the reader guessing which pose was timed).
  Result<ChosenAnimation> anim = scene ? chooseAnimation(args, *scene) : Result<ChosenAnimation>::fail("");
  if (scene && !anim) {
    std::fprintf(stderr, "motorbench time: error: %s\n", anim.error().c_str());
    rows.push_back({{"scene", name}, {"error", anim.error()}});
    status = 2;
  } else if (scene) {
    std::printf("%s: timing %s\n", name.c_str(), anim->text.c_str());
    // Bezier patch scenes: one pass per refinement level asked for (--level), all in this run.
    std::vector<int> passes = {scene->patchLevel};
    if (!levels.empty() && computeFileStats(*scene).patches > 0) passes = levels;
    for (int level : passes) {
      scene->patchLevel = level;
      std::vector<timing::Settings> configs = {normal};
      if (timing::drawsVertexBoundAt(*scene, tiny.width, tiny.height)) configs.push_back(tiny);
      for (timing::Settings& cfg : configs) {
        cfg.animation = anim->index;
        if (auto list = args.get("pipelines")) cfg.pipelines = splitList(*list);
        auto r = timing::timeScene(*scene, name, cfg);
        if (!r) {
          std::fprintf(stderr, "motorbench time: error: %s\n", r.error().c_str());
          rows.push_back({{"scene", name}, {"config", cfg.config}, {"error", r.error()}});
          status = 2;
          continue;
        }
        printRow(*r);
        for (const auto& t : r->pipelines) status = t.error.empty() ? status : 2;
        rows.push_back(timing::toJson(*r));
        rows.back()["animation"] = {{"index", anim->index < 0 ? nlohmann::json(nullptr) : nlohmann::json(anim->index)},
                                    {"text", anim->text}};
      }
    }
    // The bytes each level costs, instanced vs pre-tessellated (measured uploads).
    if (!levels.empty() && computeFileStats(*scene).patches > 0) {
      auto memory = opsv::measurePatchMemory(*scene, levels);
      if (!memory) {
        std::fprintf(stderr, "motorbench time: error: %s\n", memory.error().c_str());
        status = 2;
      } else {
        std::printf("\n%s\n", opsv::formatPatchMemory(*memory).c_str());
        patchMemory = opsv::toJson(*memory);
      }
    }
  }
  if (Status w = writeTextFile(resultPath, nlohmann::json{{"rows", rows}, {"patchMemory", patchMemory}}.dump() + "\n"); !w) {
    std::fprintf(stderr, "motorbench time: error: %s\n", w.error().c_str());
    return 2;
  }
  return status;
}

int timeError(const std::string& m) {
  std::fprintf(stderr, "motorbench time: error: %s\n", m.c_str());
  return 2;
}

// The normal and the vertex-bound (tiny viewport) configurations from --frames, --warmup,
// --best-of, --size and --tiny. A malformed value throws OptionError.
struct TimeConfigs {
  timing::Settings normal, tiny;
};

TimeConfigs readTimeConfigs(const options::Args& args) {
  TimeConfigs c;
  c.normal.frames = int(args.integer("frames", 30, 1, 100000));
  c.normal.warmup = int(args.integer("warmup", 5, 0, 100000));
  c.normal.bestOf = int(args.integer("best-of", c.normal.bestOf, 1, 100));
  std::tie(c.normal.width, c.normal.height) = args.size("size", 512, 512);
  c.tiny = c.normal;
  c.tiny.config = "vertex-bound";
  std::tie(c.tiny.width, c.tiny.height) = args.size("tiny", 64, 64);
  return c;
}

// --pipelines, checked before any scene is timed: at least one name, every one registered.
Status checkTimePipelines(const options::Args& args) {
  auto list = args.get("pipelines");
  if (!list) return {};
  if (splitList(*list).empty()) return Status::fail("--pipelines " + *list + ": expected pipeline names, e.g. matrix,motor");
  return checkPipelineNames("--pipelines", splitList(*list));
}

// --level N[,M...]: refinement levels of Bezier patch scenes (others ignore it), each timed
// in the same worker, one after the other. Empty when not given.
Result<std::vector<int>> readLevels(const options::Args& args) {
  using R = Result<std::vector<int>>;
  std::vector<int> levels;
  auto list = args.get("level");
  if (!list) return levels;
  std::string item;
  std::istringstream in(*list);
  while (std::getline(in, item, ',')) {
    if (item.empty() || item.find_first_not_of("0123456789") != std::string::npos || item.size() > 3 ||
        std::stoi(item) < 1 || std::stoi(item) > gl::kMaxPatchLevel)
      return R::fail("--level " + *list + ": expected whole numbers in 1.." + std::to_string(gl::kMaxPatchLevel) +
                     ", comma-separated");
    levels.push_back(std::stoi(item));
  }
  if (levels.empty()) return R::fail("--level: expected at least one level");
  return levels;
}

// The scenes named (folders expanded, their warnings printed), or every built-in scene.
Result<std::vector<std::string>> timedSceneNames(const options::Args& args) {
  std::vector<std::string> warnings;
  std::vector<std::string> names = expandSceneInputs(args.positional(), &warnings);
  for (const std::string& w : warnings) std::fprintf(stderr, "motorbench time: warning: %s\n", w.c_str());
  if (args.positional().empty()) names = builtinSceneNames();
  if (names.empty())
    return Result<std::vector<std::string>>::fail("no scenes to time (the folders given hold no .gltf or .glb files)");
  return names;
}

// How the frames are timed, the machine and the table legend, before the first scene's rows.
void printTimeHeader(const timing::Settings& normal, const timing::MachineInfo& machine) {
  std::printf("motorbench time: %d frames per pipeline after %d warm-up, pipelines interleaved "
              "frame by frame (alternating order); frame = clear + render (%s, fastest of %d "
              "back-to-back renders); update = Pipeline::update (hierarchy, "
              "animation, skin palette; matrix forms: + the drawn nodes' normal matrices) timed apart, per call (fastest block, same count); median "
              "[first-third quartile]\n",
              normal.frames, normal.warmup,
              machine.realGpu ? "GL_TIME_ELAPSED timer query; wall clock to glFinish beside it in --json"
                              : "wall clock to glFinish",
              normal.bestOf);
  std::printf("machine: %s, %u cores; GL_RENDERER %s; GL_VERSION %s; device %s; LP_NUM_THREADS %s; "
              "frame time from: %s\n\n",
              machine.cpuModel.c_str(), machine.cores, machine.glRenderer.c_str(),
              machine.glVersion.c_str(), machine.gl.deviceText().c_str(), machine.lpNumThreads.c_str(),
              machine.realGpu ? "GPU timer queries (a real GPU)"
                              : "the wall clock (a CPU rasterizer: its timer queries time no GPU)");
  std::printf("%s\n", timing::timingLegend().c_str());
}

// What the ratios printed mean, after the last scene.
void printRatioNote() {
  std::printf("frame/matrix and motor/matrix: paired per-frame ratios (both pipelines render the same frame "
              "back to back); of the medians: ratio of the two medians; CPU time: the paired ratio of process CPU "
              "time per frame (llvmpipe threads included); update/matrix: paired, per update call; update phases: "
              "medians per call of a separate block of updates timed with the phase clock on "
              "(pipelines/update_phases.h). < 1: motor (or the pipeline) faster; noise: q1 <= 1 <= q3.\n");
}

// Every scene's rows and patch memory tables, and the exit status (2 when a scene failed).
struct TimedScenes {
  nlohmann::json results = nlohmann::json::array(), patchMemory = nlohmann::json::array();
  int status = 0;
};

// One scene timed in a child process (`time SCENE --worker scratch`, the timing options passed
// on), its rows and patch memory added to `into`.
void timeSceneInWorker(const std::string& name, const options::Args& args, const std::string& scratch, process::Progress& progress,
                       TimedScenes& into) {
  std::vector<std::string> child = {"time", name, "--worker", scratch};
  for (const char* key : {"frames", "warmup", "best-of", "size", "tiny", "level", "instances", "pipelines", "anim"})
    if (auto v = args.get(key)) child.insert(child.end(), {std::string("--") + key, *v});
  std::filesystem::remove(scratch);
  std::fflush(stdout);  // the child prints its rows to the same stdout
  const std::string how = process::runSelf(child, "", kWorkerTimeoutS);
  std::ifstream in(scratch);
  const nlohmann::json worker = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
  nlohmann::json rows = worker.is_object() ? worker.value("rows", nlohmann::json()) : nlohmann::json();
  if (!rows.is_array()) {
    const std::string why = how.empty() ? "the worker wrote no result" : "the worker ended: " + how;
    std::fprintf(stderr, "motorbench time: error: %s: %s\n", name.c_str(), why.c_str());
    into.results.push_back({{"scene", name}, {"error", why}});
    into.status = 2;
    progress.done(name + ": failed");
    return;
  }
  // A scene that failed (it could not load, or a pipeline could not run) is not "timed".
  bool failed = !how.empty();
  for (const auto& r : rows) failed = failed || r.contains("error");
  progress.done(name + (failed ? ": failed, see the error above" : ": timed"));
  if (failed) into.status = 2;
  for (auto& r : rows) into.results.push_back(std::move(r));
  if (const nlohmann::json m = worker.value("patchMemory", nlohmann::json()); m.is_array())
    into.patchMemory.push_back({{"scene", name}, {"rows", m}});
}

// The --json document: the machine, the settings and method, every scene's rows.
nlohmann::json timeJson(const timing::MachineInfo& machine, const TimeConfigs& c, const TimedScenes& timed) {
  return {{"tool", "motorbench time"},
          {"machine", timing::toJson(machine)},
          {"settings",
           {{"frames", c.normal.frames}, {"warmup", c.normal.warmup}, {"best_of", c.normal.bestOf},
            {"size", {c.normal.width, c.normal.height}},
            {"vertex_bound_size", {c.tiny.width, c.tiny.height}},
            {"method", "pipelines interleaved frame by frame in alternating order; frame = clear + "
                       "render, timed as each result's frameTimeSource says (gpu-timer: GL_TIME_ELAPSED, "
                       "read after glFinish, wall_ms beside it; wall-clock: steady_clock to glFinish), "
                       "fastest of best_of renders; also process "
                       "CPU time; update = Pipeline::update per call; update_phases_ms = a further "
                       "block of update calls with the phase clock on, per call"}}},
          {"results", timed.results},
          // Bezier patch scenes timed with --level: bytes uploaded per pipeline and level, instanced
          // (control points + one refinement pattern) vs the same surface pre-tessellated.
          {"patchMemory", timed.patchMemory}};
}

int runTime(const std::vector<std::string>& argv) {
  const options::Args args(argv, {{"frames", "warmup", "best-of", "size", "tiny", "lp-threads", "json", "worker", "level",
                          "instances", "gpu", "pipelines", "anim"},
                         {},
                         {}});
  if (!args.error().empty()) return timeError(args.error());
  if (Status gpu = applyGpuOption(args); !gpu) return timeError(gpu.error());  // workers inherit MB_GPU
  const TimeConfigs configs = readTimeConfigs(args);
  args.integer("instances", 1, 1, kMaxInstances);  // checked here; each worker applies it
  if (Status ok = checkTimePipelines(args); !ok) return timeError(ok.error());
  // llvmpipe reads LP_NUM_THREADS when the context is created, which has not happened yet.
  if (args.has("lp-threads"))
    setenv("LP_NUM_THREADS", std::to_string(args.integer("lp-threads", 0, 0, 1024)).c_str(), 1);
  const auto levels = readLevels(args);
  if (!levels) return timeError(levels.error());
  const auto names = timedSceneNames(args);
  if (!names) return timeError(names.error());
  // The --json file's folder is created and checked now, not after every scene was timed.
  if (auto path = args.get("json"); path && !args.has("worker"))
    if (Status ok = prepareOutputFile("--json", *path); !ok) return timeError(ok.error());
  if (auto file = args.get("worker")) {
    if (names->size() != 1) return timeError("--worker times exactly one scene");
    return timeOneScene((*names)[0], configs.normal, configs.tiny, *levels, args, *file);
  }

  auto machine = timing::machineInfo();
  if (!machine) return timeError(machine.error());
  printTimeHeader(configs.normal, *machine);
  TimedScenes timed;
  const std::string scratch = (std::filesystem::temp_directory_path() /
                               ("motorbench-time-" + std::to_string(::getpid()) + ".json")).string();
  process::Progress progress("time", "scenes done", names->size(), false);
  for (const std::string& name : *names) timeSceneInWorker(name, args, scratch, progress, timed);
  std::filesystem::remove(scratch);
  printRatioNote();
  if (auto path = args.get("json"))
    if (Status w = writeTextFile(*path, timeJson(*machine, configs, timed).dump(2) + "\n"); !w) return timeError(w.error());
  return timed.status;
}

}  // namespace
}  // namespace mb

MB_COMMAND(time, "time",
           "[SCENE|DIR...] [--pipelines A,B...] [--anim A] [--frames N] [--warmup W] [--best-of K] [--size WxH] [--tiny WxH] "
           "[--level N[,M...]] [--instances N] [--lp-threads N] [--gpu auto|llvmpipe|N] [--json FILE]",
           "frame time (glFinish wall clock) and CPU update time of every pipeline; motor/matrix "
           "ratios from one interleaved run; scenes with >= 10 drawn vertices per tiny-viewport pixel "
           "(the crowd) also at that viewport (vertex-bound)",
           mb::runTime);
MB_COMMAND_HELP(time, "time",
               "  SCENE|DIR...       scenes to time (default: the built-in scenes)\n"
               "  --pipelines A,B..  the pipelines timed (default: every registered one; ratios need matrix)\n"
               "  --anim A           the one animation played, index or name (default 0; each scene says which)\n"
               "  --frames N         measured frames per pipeline (default 30);  --warmup W  dropped first (default 5)\n"
               "  --best-of K        renders per frame, the fastest kept (default 3)\n"
               "  --size WxH         viewport (default 512x512);  --tiny WxH  the vertex-bound viewport (default 64x64)\n"
               "  --level N[,M...]   refinement levels of Bezier patch scenes (teapot)\n"
               MB_INSTANCES_OPTION_HELP
               "  --lp-threads N     LP_NUM_THREADS for llvmpipe\n"
               MB_GPU_OPTION_HELP
               "  --json FILE        every sample, spread and ratio as JSON (missing folders are created; checked first)\n"
               "  Ratios are motor/matrix (< 1: motor faster) with their spread [q1-q3]; \"noise\" marks a ratio\n"
               "  whose quartiles lie on both sides of 1; \"too few frames\" one measured on fewer than 5 frames.\n",
                "motorbench time normal_torus --frames 5 --warmup 1 --json out/time.json", false);
