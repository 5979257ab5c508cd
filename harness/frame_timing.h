// Frame timing of every registered pipeline on a scene (issue 5, item 4), measured in one run
// so that motor/matrix ratios cancel what the machine does meanwhile:
//  - each frame: the CPU update (hierarchy, animation, skin palette: Pipeline::update) timed
//    on its own, then clear + render + glFinish timed by the wall clock;
//  - pipelines are interleaved frame by frame, in alternating order (A B, B A, ...), so drift
//    and order effects fall on both alike;
//  - W warm-up frames are dropped, then N frames give median, quartiles and MAD;
//  - GL timer queries (GL_TIME_ELAPSED) are used as an extra column only when GL_RENDERER is a
//    real GPU (llvmpipe's are not trustworthy), the first query discarded.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

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

struct MachineInfo {
  std::string cpuModel;    // /proc/cpuinfo "model name"
  unsigned cores = 0;      // hardware threads
  std::string glRenderer, glVersion, glBackend;
  std::string lpNumThreads;  // LP_NUM_THREADS as set, or "unset"
  bool realGpu = false;      // GL_RENDERER is not a software rasteriser
};
// Needs the shared GL context (creates it on first use).
Result<MachineInfo> machineInfo();

struct Settings {
  int frames = 30, warmup = 5;
  int width = 512, height = 512;
  std::string config = "normal";  // label: "normal", "vertex-bound"
};

struct PipelineTiming {
  std::string pipeline;
  std::vector<double> frameMs, updateMs, gpuMs;  // per measured frame
  Spread frame, update, gpu;
  PipelineStats stats;
  std::string error;  // non-empty: this pipeline could not run (no samples)
};

struct ConfigTiming {
  std::string scene, config;
  int width = 0, height = 0;
  std::vector<PipelineTiming> pipelines;  // registry order, matrix first
  // motor / matrix: of the medians, and the median of the per-frame ratios (paired samples);
  // negative when either side is missing.
  double frameRatio = -1, pairedFrameRatio = -1, updateRatio = -1;
};

// Times every registered pipeline on `scene` under `settings`.
Result<ConfigTiming> timeScene(const Scene& scene, const std::string& sceneName,
                               const Settings& settings);

nlohmann::json toJson(const Spread& s);
nlohmann::json toJson(const MachineInfo& m);
nlohmann::json toJson(const ConfigTiming& c);

}  // namespace mb::timing
