#include "harness/timing/frame_timing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <memory>
#include <thread>

#include "harness/figures/figure_statistics.h"
#include "harness/render/render_frame.h"
#include "pipelines/gl/context.h"
#include "pipelines/gl/framebuffer.h"
#include "pipelines/scene/camera_rule.h"
#include "pipelines/scene/scene_stats.h"

namespace mb::timing {
namespace {

using Clock = std::chrono::steady_clock;

double ms(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

// CPU time of the whole process (all threads, llvmpipe's rasterisers included), in ms.
double processCpuMs() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return 1e3 * double(ts.tv_sec) + 1e-6 * double(ts.tv_nsec);
}

std::string cpuModel() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) {
      const size_t colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  return "unknown";
}

// Bits of the GL_TIME_ELAPSED counter (0: the implementation has no timer).
int timerBits() {
  GLint bits = 0;
  glGetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &bits);
  return bits;
}

// The animation state of frame `i`: animation `anim` alone playing at 60 Hz (wrapped); the rest
// pose for -1 or a scene without that animation. (Blending two silently mixed a file's
// animations into a pose neither shows.)
AnimState stateForFrame(const Scene& scene, int i, int anim) {
  AnimState st;
  if (anim < 0 || size_t(anim) >= scene.animations.size()) return st;
  const float d = scene.animations[size_t(anim)].duration;
  st.anim = anim, st.time = d > 0 ? std::fmod(float(i) / 60.0f, d) : 0.0f;
  return st;
}

double ratioOf(double motor, double matrix) { return motor > 0 && matrix > 0 ? motor / matrix : -1; }

}  // namespace

// The statistics are the figures layer's (one definition for every room).
std::vector<double> pairedRatios(const std::vector<double>& a, const std::vector<double>& b) {
  return figures::pairedRatios(a, b);
}

Spread spreadOf(std::vector<double> s) {
  Spread r;
  r.n = int(s.size());
  if (s.empty()) return r;
  std::sort(s.begin(), s.end());
  r.median = figures::quantileSorted(s, 0.5), r.q1 = figures::quantileSorted(s, 0.25), r.q3 = figures::quantileSorted(s, 0.75);
  r.min = s.front(), r.max = s.back();
  std::vector<double> dev;
  for (double x : s) dev.push_back(std::abs(x - r.median));
  std::sort(dev.begin(), dev.end());
  r.mad = figures::quantileSorted(dev, 0.5);
  return r;
}

Result<MachineInfo> machineInfo() {
  auto ctx = gl::sharedContext();
  if (!ctx) return Result<MachineInfo>::fail(ctx.error());
  MachineInfo m;
  m.cpuModel = cpuModel();
  m.cores = std::thread::hardware_concurrency();
  m.glRenderer = (*ctx)->info().renderer;
  m.glVersion = (*ctx)->info().version;
  m.glBackend = (*ctx)->info().backend;
  m.gl = (*ctx)->info();
  const char* lp = std::getenv("LP_NUM_THREADS");
  m.lpNumThreads = lp ? lp : "unset";
  m.realGpu = m.gl.realGpu();
  return m;
}

const char* toString(FrameTimeSource source) {
  return source == FrameTimeSource::GpuTimer ? "gpu-timer" : "wall-clock";
}

FrameTimeSource chooseFrameTimeSource(bool realGpu, int timerBits, bool forced) {
  return (realGpu || forced) && timerBits > 0 ? FrameTimeSource::GpuTimer : FrameTimeSource::WallClock;
}

bool drawsVertexBoundAt(const Scene& scene, int width, int height) {
  const double pixels = double(width) * double(height);
  return pixels > 0 && computeFileStats(scene).drawnVertices >= kVertexBoundVerticesPerPixel * pixels;
}

namespace {

// The pipelines that time: each of the scene's space (only those --pipelines names) created,
// configured and prepared; every one gets a PipelineTiming in out.pipelines (with its error
// when it cannot run), the running ones a slot in `live`.
struct LivePipelines {
  std::vector<std::unique_ptr<Pipeline>> live;  // parallel to `slots`
  std::vector<size_t> slots;                    // index into out.pipelines
};
LivePipelines preparePipelines(const Scene& scene, const Settings& settings, ConfigTiming& out) {
  LivePipelines l;
  for (const std::string& name : pipelineNames(scene.curved.space)) {  // the scene's space's pair
    if (!settings.pipelines.empty() &&
        std::find(settings.pipelines.begin(), settings.pipelines.end(), name) == settings.pipelines.end())
      continue;  // --pipelines: only those named
    PipelineTiming t;
    t.pipeline = name;
    auto p = createPipeline(name);
    if (!p) {
      t.error = "registered but not implemented (placeholder factory)";
    } else {
      p->configure(settings.options);
      if (Status s = p->prepare(scene); !s) t.error = s.error();
    }
    if (t.error.empty()) {
      l.live.push_back(std::move(p));
      l.slots.push_back(out.pipelines.size());
    }
    out.pipelines.push_back(std::move(t));
  }
  return l;
}

// Update: the fastest of bestOf blocks of `repeats` back-to-back calls, per call (ms).
double timeUpdate(Pipeline& p, const AnimState& st, int repeats, int bestOf) {
  double updateMs = 0;
  for (int rep = 0; rep < std::max(1, bestOf); ++rep) {
    const auto t0 = Clock::now();
    for (int r = 0; r < repeats; ++r) p.update(st);
    const double u = ms(t0, Clock::now()) / repeats;
    updateMs = rep ? std::min(updateMs, u) : u;
  }
  return updateMs;
}

// The phases: bestOf more blocks of `repeats` calls with the phase clock on, summed per phase
// over the block (not yet per call); the block with the smallest total counts, by the same
// rule as the whole update (a single block let one disturbed block show phases several times
// the whole update).
void timeUpdatePhases(Pipeline& p, const AnimState& st, int repeats, int bestOf, double phases[kUpdatePhaseCount]) {
  p.timeUpdatePhases(true);
  for (int rep = 0; rep < std::max(1, bestOf); ++rep) {
    double block[kUpdatePhaseCount] = {};
    for (int r = 0; r < repeats; ++r) {
      p.update(st);
      const UpdatePhases ph = p.stats().updatePhases;
      for (int k2 = 0; k2 < kUpdatePhaseCount; ++k2) block[k2] += ph.*kUpdatePhases[k2].field;
    }
    double total = 0, best = 0;
    for (int k2 = 0; k2 < kUpdatePhaseCount; ++k2) total += block[k2], best += phases[k2];
    if (rep == 0 || total < best) std::copy(block, block + kUpdatePhaseCount, phases);
  }
  p.timeUpdatePhases(false);
}

// One frame's draw times (ms), each the smallest of bestOf clears + renders + glFinish: wall
// clock, process CPU, and the GPU timer where `query` is one.
struct RenderSample {
  double wallMs = 0, cpuMs = 0, gpuMs = 0;
};

// The draw timed bestOf times into `sample`; "" or the error (a timer result missing after
// glFinish).
std::string timeRender(Pipeline& p, const View& view, gl::Framebuffer& fb, GLuint query, int bestOf,
                       const std::string& sceneName, RenderSample& sample) {
  double wallMs = 0, cpuMs = 0, gpuMs = 0;
  for (int rep = 0; rep < std::max(1, bestOf); ++rep) {
    const auto r0 = Clock::now();
    const double c0 = processCpuMs();
    if (query) glBeginQuery(GL_TIME_ELAPSED, query);
    fb.clear(kBackground[0], kBackground[1], kBackground[2], kBackground[3]);
    p.render(view);
    if (query) glEndQuery(GL_TIME_ELAPSED);
    glFinish();
    const double wall = ms(r0, Clock::now()), cpu = processCpuMs() - c0;
    double gpu = 0;
    if (query) {  // after glFinish the result is there: reading it waits for nothing
      GLint available = 0;
      glGetQueryObjectiv(query, GL_QUERY_RESULT_AVAILABLE, &available);
      if (!available) return sceneName + ": GL_TIME_ELAPSED result not available after glFinish";
      GLuint64 ns = 0;
      glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);
      gpu = double(ns) * 1e-6;
    }
    wallMs = rep ? std::min(wallMs, wall) : wall;
    cpuMs = rep ? std::min(cpuMs, cpu) : cpu;
    gpuMs = rep ? std::min(gpuMs, gpu) : gpu;
  }
  sample = {wallMs, cpuMs, gpuMs};
  return "";
}

// One pipeline's figures of frame i: on a warm-up frame the update repeats calibrated (enough
// calls for a block of kMinUpdateBlockMs), on a timed frame every sample kept.
void recordFrame(PipelineTiming& t, const Pipeline& p, bool warmup, bool gpuTimer, double updateMs,
                 const double phases[kUpdatePhaseCount], const RenderSample& r) {
  if (warmup) {
    // Calibrate R on the warm-up: enough calls for a block of kMinUpdateBlockMs.
    if (updateMs > 0)
      t.updateRepeats = std::clamp(int(std::ceil(kMinUpdateBlockMs / updateMs)), 1, 1000);
    return;
  }
  t.fallbacks.add(p.stats());
  t.updateMs.push_back(updateMs);
  for (int k2 = 0; k2 < kUpdatePhaseCount; ++k2) t.phaseMs[k2].push_back(phases[k2] / t.updateRepeats);
  t.frameMs.push_back(gpuTimer ? r.gpuMs : r.wallMs);
  t.wallMs.push_back(r.wallMs);
  t.cpuMs.push_back(r.cpuMs);
  if (gpuTimer) t.gpuMs.push_back(r.gpuMs);  // the warm-up frames above absorb first-use costs
}

// Each running pipeline's spreads of its samples and its last stats.
void summarise(const LivePipelines& l, ConfigTiming& out) {
  for (size_t k = 0; k < l.live.size(); ++k) {
    PipelineTiming& t = out.pipelines[l.slots[k]];
    t.frame = spreadOf(t.frameMs), t.update = spreadOf(t.updateMs), t.gpu = spreadOf(t.gpuMs);
    t.wall = spreadOf(t.wallMs);
    t.cpu = spreadOf(t.cpuMs);
    for (int k2 = 0; k2 < kUpdatePhaseCount; ++k2) t.phases[k2] = spreadOf(t.phaseMs[k2]);
    t.stats = l.live[k]->stats();
  }
}

// The motor / matrix ratios of the scene's space's pair (matrix / motor, s3_matrix / s3_motor,
// h3_matrix / h3_motor): of the median frames, and the medians of the per-frame paired ratios
// of frame, process CPU and update times; left as they are when the pair did not both run.
void pairRatios(ConfigTiming& out) {
  const PipelineTiming* matrix = nullptr;
  const PipelineTiming* motor = nullptr;
  for (const PipelineTiming& t : out.pipelines) {
    if (!t.error.empty()) continue;
    // The pair of the scene's space: matrix / motor, s3_matrix / s3_motor, h3_matrix / h3_motor.
    if (t.pipeline == "matrix" || t.pipeline.ends_with("_matrix")) matrix = &t;
    if (t.pipeline == "motor" || t.pipeline.ends_with("_motor")) motor = &t;
  }
  if (!matrix || !motor) return;
  out.frameRatio = ratioOf(motor->frame.median, matrix->frame.median);
  auto pairedMedian = [](const std::vector<double>& r) { return r.empty() ? -1 : spreadOf(r).median; };
  const std::vector<double> frames = pairedRatios(matrix->frameMs, motor->frameMs);
  out.pairedFrame = spreadOf(frames);
  out.pairedFrameRatio = pairedMedian(frames);
  out.pairedCpuRatio = pairedMedian(pairedRatios(matrix->cpuMs, motor->cpuMs));
  out.updateRatio = pairedMedian(pairedRatios(matrix->updateMs, motor->updateMs));
}

}  // namespace

Result<ConfigTiming> timeScene(const Scene& scene, const std::string& sceneName,
                               const Settings& settings) {
  using R = Result<ConfigTiming>;
  auto machine = machineInfo();
  if (!machine) return R::fail(machine.error());
  auto fb = gl::Framebuffer::create(settings.width, settings.height);
  if (!fb) return R::fail(sceneName + ": " + fb.error());

  ConfigTiming out;
  out.scene = sceneName, out.config = settings.config;
  out.width = settings.width, out.height = settings.height;
  out.patchLevel = computeFileStats(scene).patches > 0 ? scene.patchLevel : 0;
  const LivePipelines l = preparePipelines(scene, settings, out);

  // A fixed camera (the rest pose's framing): the same view for every frame and pipeline.
  const View view = frameScene(scene, stateForFrame(scene, 0, settings.animation),
                               float(settings.width) / float(settings.height));
  out.source = chooseFrameTimeSource(machine->realGpu, timerBits(), settings.forceTimerQueries);
  // One query object, reused: each result is read after the glFinish that ends its sample.
  GLuint query = 0;
  if (out.source == FrameTimeSource::GpuTimer) glGenQueries(1, &query);
  const int total = settings.warmup + settings.frames;
  // Process CPU: llvmpipe's threads work while the calling thread waits in glFinish.
  const DisturbanceWatch watch(CpuClock::Process);
  for (int i = 0; i < total; ++i) {
    const AnimState st = stateForFrame(scene, i, settings.animation);
    for (size_t k = 0; k < l.live.size(); ++k) {
      // Alternate the order every frame: A B, B A, A B ...
      const size_t idx = i % 2 ? l.live.size() - 1 - k : k;
      Pipeline& p = *l.live[idx];
      PipelineTiming& t = out.pipelines[l.slots[idx]];
      glFinish();  // nothing of the previous pipeline is left in flight
      const double updateMs = timeUpdate(p, st, t.updateRepeats, settings.bestOf);
      double phases[kUpdatePhaseCount] = {};
      timeUpdatePhases(p, st, t.updateRepeats, settings.bestOf, phases);
      RenderSample r;
      if (auto e = timeRender(p, view, **fb, query, settings.bestOf, sceneName, r); !e.empty()) return R::fail(e);
      recordFrame(t, p, i < settings.warmup, query != 0, updateMs, phases, r);
    }
  }
  out.disturbance = watch.finish();
  if (query) glDeleteQueries(1, &query);
  if (GLenum err = glGetError(); err != GL_NO_ERROR)
    return R::fail(sceneName + ": GL error while timing: " + gl::errorName(err));
  summarise(l, out);
  pairRatios(out);
  return out;
}

nlohmann::json toJson(const Spread& s) {
  return {{"median", s.median}, {"q1", s.q1}, {"q3", s.q3}, {"iqr", s.iqr()}, {"mad", s.mad},
          {"min", s.min}, {"max", s.max}, {"n", s.n}};
}

nlohmann::json updatePhasesJson(const PipelineTiming& t) {
  nlohmann::json j = nlohmann::json::object();
  double total = 0;
  for (int k = 0; k < kUpdatePhaseCount; ++k) {
    j[kUpdatePhases[k].key] = toJson(t.phases[k]);
    total += t.phases[k].median;
  }
  j["sum_of_medians"] = total;
  return j;
}

nlohmann::json toJson(const MachineInfo& m) {
  return {{"cpu_model", m.cpuModel}, {"cores", m.cores}, {"GL_RENDERER", m.glRenderer},
          {"GL_VERSION", m.glVersion}, {"gl_backend", m.glBackend},
          {"LP_NUM_THREADS", m.lpNumThreads}, {"gpu_timer_queries", m.realGpu},
          {"gl", mb::toJson(m.gl)}};
}

void FallbackTally::add(const PipelineStats& s) {
  if (s.linearFallbackDraws + s.skinFallbackDraws == 0) return;
  ++frames;
  linearDraws = std::max(linearDraws, s.linearFallbackDraws);
  skinDraws = std::max(skinDraws, s.skinFallbackDraws);
  skinJoints = std::max(skinJoints, s.skinFallbackJoints);
  vertices = std::max(vertices, s.fallbackVertices);
}

double verticesPerUs(const PipelineTiming& t, bool gpu) {
  const double ms = gpu ? (t.gpuMs.empty() ? 0.0 : t.gpu.median) : t.frame.median;
  return ms > 0 ? double(t.stats.drawnVertices) / (ms * 1000.0) : 0.0;
}

nlohmann::json toJson(const ConfigTiming& c) {
  // Each pipeline's ratios to its space's matrix pipeline ("matrix", "s3_matrix", ...), paired
  // frame by frame as the text prints them, with their spread and the noise mark (q1 <= 1 <= q3).
  const PipelineTiming* matrix = nullptr;
  for (const PipelineTiming& t : c.pipelines)
    if (t.error.empty() && (t.pipeline == "matrix" || t.pipeline.ends_with("_matrix"))) matrix = &t;
  auto ratioJson = [](const std::vector<double>& base, const std::vector<double>& other) {
    const Spread r = spreadOf(pairedRatios(base, other));
    if (r.n == 0) return nlohmann::json();
    nlohmann::json j = toJson(r);
    j["noise"] = r.q1 <= 1.0 && r.q3 >= 1.0;
    return j;
  };
  nlohmann::json pipelines = nlohmann::json::object();
  for (const PipelineTiming& t : c.pipelines) {
    nlohmann::json j = {{"error", t.error.empty() ? nlohmann::json() : nlohmann::json(t.error)}};
    if (t.error.empty()) {
      j["frame_ms"] = toJson(t.frame);  // the figure: frameTimeSource's samples
      j["wall_ms"] = toJson(t.wall);
      j["frame_cpu_ms"] = toJson(t.cpu);
      j["update_ms"] = toJson(t.update);
      j["update_calls_per_block"] = t.updateRepeats;
      j["update_phases_ms"] = updatePhasesJson(t);
      j["frame_samples_ms"] = t.frameMs;
      j["frame_cpu_samples_ms"] = t.cpuMs;
      j["update_samples_ms"] = t.updateMs;
      j["gpu_ms"] = t.gpuMs.empty() ? nlohmann::json() : toJson(t.gpu);
      j["vertices"] = t.stats.vertices;
      j["draws"] = t.stats.draws;
      j["drawn_vertices"] = t.stats.drawnVertices;
      j["instances"] = t.stats.instances;
      j["vertices_per_us"] = verticesPerUs(t);
      j["fallbacks"] = {{"frames", t.fallbacks.frames}, {"of_frames", t.frameMs.size()},
                        {"linearFallbackDraws", t.fallbacks.linearDraws}, {"skinFallbackDraws", t.fallbacks.skinDraws},
                        {"skinFallbackJoints", t.fallbacks.skinJoints}, {"fallbackVertices", t.fallbacks.vertices}};
      j["ratios_with_fallback"] = t.fallbacks.any();
      j["gpu_vertices_per_us"] = t.gpuMs.empty() ? nlohmann::json() : nlohmann::json(verticesPerUs(t, true));
      if (matrix) {
        j["frame_ratio_to_matrix"] = ratioJson(matrix->frameMs, t.frameMs);
        j["update_ratio_to_matrix"] = ratioJson(matrix->updateMs, t.updateMs);
      }
    }
    pipelines[t.pipeline] = j;
  }
  auto num = [](double r) { return r > 0 ? nlohmann::json(r) : nlohmann::json(); };
  return {{"scene", c.scene},
          {"config", c.config},
          {"width", c.width},
          {"height", c.height},
          {"patchLevel", c.patchLevel ? nlohmann::json(c.patchLevel) : nlohmann::json()},
          {"frameTimeSource", toString(c.source)},
          {"pipelines", pipelines},
          {"ratio_motor_over_matrix", num(c.frameRatio)},
          {"paired_ratio_motor_over_matrix", num(c.pairedFrameRatio)},
          {"paired_ratio_spread", toJson(c.pairedFrame)},
          {"paired_cpu_ratio_motor_over_matrix", num(c.pairedCpuRatio)},
          {"update_ratio_motor_over_matrix", num(c.updateRatio)},
          {"disturbance", toJson(c.disturbance)}};
}

}  // namespace mb::timing
