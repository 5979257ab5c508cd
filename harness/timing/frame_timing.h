// Frame timing of every registered pipeline on a scene, measured in one run
// so that motor/matrix ratios cancel what the machine does meanwhile:
//  - each frame: the CPU update (hierarchy, animation, skin palette: Pipeline::update) timed
//    on its own (R back-to-back calls, R chosen in the warm-up so that a block lasts at least
//    kMinUpdateBlockMs: tiny scenes update in microseconds, below the clock's noise; the
//    fastest of Settings::bestOf blocks), then
//    Settings::bestOf more blocks of R calls (the smallest total kept) with the pipeline's phase clock on (Pipeline::timeUpdatePhases:
//    sampling, blending, conversion, hierarchy, palette, pipelines/update_phases.h), per call,
//    kept apart from the timed blocks so that their clock reads never weigh on the update time;
//    clear + render + glFinish timed by the wall clock and, beside it, by the process's CPU
//    time (llvmpipe's worker threads included: what the frame cost the machine, insensitive to
//    other processes taking the cores meanwhile); each frame rendered Settings::bestOf times,
//    the fastest kept;
//  - pipelines are interleaved frame by frame, in alternating order (A B, B A, ...), so drift
//    and order effects fall on both alike;
//  - W warm-up frames are dropped, then N frames give median, quartiles and MAD;
//  - ratios: of the medians, and the median of the per-frame ratios (both pipelines render the
//    same frame back to back, so a slow spell of the machine hits both samples of a pair);
//  - the frame-time figure (frameTimeSource): on a real GPU the GL_TIME_ELAPSED timer query
//    around clear + render, read after the glFinish that ends the wall-clock sample (so reading
//    it never stalls a measured frame), with the wall clock beside it; on a CPU rasteriser the
//    wall clock (llvmpipe's timer queries do not time a GPU: README.md).
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/timing/disturbance.h"
#include "pipelines/gl/context.h"
#include "pipelines/pipeline.h"
#include "pipelines/result.h"
#include "pipelines/scene/scene.h"

namespace mb::timing {

struct Spread {
  double median = 0, q1 = 0, q3 = 0, mad = 0, min = 0, max = 0;
  int n = 0;
  double iqr() const { return q3 - q1; }
};
// Median, quartiles (linear interpolation) and median absolute deviation of `samples`.
Spread spreadOf(std::vector<double> samples);
// Per-frame ratios b[i] / a[i] of two sample series (frames where a[i] > 0).
std::vector<double> pairedRatios(const std::vector<double>& a, const std::vector<double>& b);

struct MachineInfo {
  std::string cpuModel;    // /proc/cpuinfo "model name"
  unsigned cores = 0;      // hardware threads
  std::string glRenderer, glVersion, glBackend;
  std::string lpNumThreads;  // LP_NUM_THREADS as set, or "unset"
  bool realGpu = false;      // neither the device nor GL_RENDERER is a software rasteriser
  gl::ContextInfo gl;        // the whole record (device index, DRM node, vendor)
};
// Needs the shared GL context (creates it on first use).
Result<MachineInfo> machineInfo();

// Where a frame-time figure comes from: GL_TIME_ELAPSED ("gpu-timer") or steady_clock around
// clear + render + glFinish ("wall-clock").
enum class FrameTimeSource { GpuTimer, WallClock };
const char* toString(FrameTimeSource source);
// The rule: timer queries on a real GPU whose GL_TIME_ELAPSED counter has bits
// (GL_QUERY_COUNTER_BITS > 0), the wall clock elsewhere; `forced` (tests only) takes the timer
// queries on any renderer that has them.
FrameTimeSource chooseFrameTimeSource(bool realGpu, int timerBits, bool forced = false);

struct Settings {
  int frames = 30, warmup = 5;
  // Each frame is rendered this many times back to back and the fastest counts: other
  // processes can only ever add time to a render, so the minimum is the least disturbed one.
  int bestOf = 3;
  int width = 512, height = 512;
  std::string config = "normal";  // label: "normal", "vertex-bound"
  PipelineOptions options;        // given to every pipeline (e.g. the same SkinSpace for both)
  // The one animation played (at 60 Hz, wrapped; -1: the rest pose), never a blend of two.
  int animation = 0;
  // The pipelines timed (registry order kept); empty: every registered one of the scene's space.
  std::vector<std::string> pipelines;
  // Tests only: time with GL timer queries on a CPU rasteriser too (chooseFrameTimeSource).
  bool forceTimerQueries = false;
};

inline constexpr double kMinUpdateBlockMs = 0.25;

// The update's phases (pipelines/update_phases.h) in the order they are reported.
struct UpdatePhaseName {
  const char* key;  // JSON key ("sampling", ...)
  double UpdatePhases::*field;
};
inline constexpr UpdatePhaseName kUpdatePhases[] = {
    {"sampling", &UpdatePhases::samplingMs},     {"blending", &UpdatePhases::blendingMs},
    {"conversion", &UpdatePhases::conversionMs}, {"hierarchy", &UpdatePhases::hierarchyMs},
    {"palette", &UpdatePhases::paletteMs}};
inline constexpr int kUpdatePhaseCount = int(sizeof kUpdatePhases / sizeof kUpdatePhases[0]);

// The motor family's exact fallbacks over the measured frames (PipelineStats after each frame's
// render): how many frames took one, and the most draws, joints and vertices in one frame.
struct FallbackTally {
  int frames = 0;  // measured frames whose render drew an exact fallback
  int linearDraws = 0, skinDraws = 0, skinJoints = 0;
  uint64_t vertices = 0;
  bool any() const { return frames > 0; }
  void add(const PipelineStats& s);
};

struct PipelineTiming {
  std::string pipeline;
  // Per measured frame: the frame-time figure (ConfigTiming::source: GPU timer or wall clock),
  // wall clock, process CPU time, CPU update (per call), GPU timer query (empty without).
  std::vector<double> frameMs, wallMs, cpuMs, updateMs, gpuMs;
  Spread frame, wall, cpu, update, gpu;
  // Per measured frame and phase (kUpdatePhases order): ms per update call, from the block
  // timed with the phase clock on; their spreads.
  std::vector<double> phaseMs[kUpdatePhaseCount];
  Spread phases[kUpdatePhaseCount];
  int updateRepeats = 1;  // R: update calls per timed block
  PipelineStats stats;
  FallbackTally fallbacks;  // a ratio to matrix taken with a fallback says so
  std::string error;  // non-empty: this pipeline could not run (no samples)
};

struct ConfigTiming {
  std::string scene, config;
  int width = 0, height = 0;
  int patchLevel = 0;  // Scene::patchLevel when the scene has Bezier patches, else 0
  FrameTimeSource source = FrameTimeSource::WallClock;  // of every PipelineTiming::frameMs
  std::vector<PipelineTiming> pipelines;  // registry order, matrix first
  // motor / matrix, negative when either side is missing. frameRatio: of the frame-time
  // medians; pairedFrameRatio (spread: pairedFrame): the median of the per-frame ratios;
  // pairedCpuRatio: the same for CPU time; updateRatio: the median of the per-frame update
  // ratios.
  double frameRatio = -1, pairedFrameRatio = -1, pairedCpuRatio = -1, updateRatio = -1;
  Spread pairedFrame;
  // The whole measurement's process CPU time / real time and the load around it
  // (disturbance.h): a disturbed configuration's ratios are printed marked, not verdict inputs.
  Disturbance disturbance;
};

// The vertex-bound configuration (a tiny viewport) measures the vertex stage only when the
// scene draws many vertices per pixel of it; with fewer, a frame is mostly fixed per-frame cost
// (clear, draw calls, uniform uploads, glFinish) and its ratio says nothing about transforming
// vertices: the 24-vertex textured_box at 64x64 gave motor/matrix 1.00 timed alone and 1.35..1.45
// timed after its 512x512 run in one report worker; the crowd (108,800 drawn vertices, 27 per
// pixel) gives 0.78..0.80 either way.
inline constexpr int kVertexBoundVerticesPerPixel = 10;
// Vertices the scene's mesh nodes draw per frame (instances counted), and whether that is at
// least kVertexBoundVerticesPerPixel per pixel of a width x height viewport.
bool drawsVertexBoundAt(const Scene& scene, int width, int height);

// Times the registered pipelines of `scene`'s space (pipelineNames(space)) under `settings`.
Result<ConfigTiming> timeScene(const Scene& scene, const std::string& sceneName,
                               const Settings& settings);

// Vertices drawn per microsecond of frame time: PipelineStats::drawnVertices (instances
// counted) / (median ms x 1000); 0 without samples. `gpu`: of the GPU timer-query median.
double verticesPerUs(const PipelineTiming& t, bool gpu = false);

nlohmann::json toJson(const Spread& s);
nlohmann::json toJson(const MachineInfo& m);
// {phase: Spread (ms per update call)} in kUpdatePhases order, plus "sum_of_medians".
nlohmann::json updatePhasesJson(const PipelineTiming& t);
nlohmann::json toJson(const ConfigTiming& c);

}  // namespace mb::timing
