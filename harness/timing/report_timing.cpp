#include "harness/timing/report_timing.h"

#include <algorithm>
#include <cstdio>

#include "harness/render/render_frame.h"
#include "harness/timing/frame_timing.h"

namespace mb::timing {
namespace {

using json = nlohmann::json;

// The viewport of the vertex-bound configuration (`motorbench time --tiny`'s default).
constexpr int kTiny = 64;

// One configuration in the report's shape (frame_timing's own JSON also keeps every sample,
// which the report does not need).
json configJson(const timing::ConfigTiming& c, const std::vector<std::string>& pipelines) {
  json out = {{"width", c.width}, {"height", c.height}, {"config", c.config},
              {"frameTimeSource", timing::toString(c.source)}, {"pipelines", json::object()}};
  for (const timing::PipelineTiming& t : c.pipelines) {
    if (std::find(pipelines.begin(), pipelines.end(), t.pipeline) == pipelines.end()) continue;
    if (!t.error.empty()) {
      out["pipelines"][t.pipeline] = {{"error", t.error}};
      continue;
    }
    out["pipelines"][t.pipeline] = {{"medianMs", t.frame.median}, {"q1Ms", t.frame.q1}, {"q3Ms", t.frame.q3},
                                    {"madMs", t.frame.mad}, {"minMs", t.frame.min}, {"maxMs", t.frame.max},
                                    {"frames", t.frame.n}, {"wallMedianMs", t.wall.median},
                                    {"gpuMedianMs", t.gpuMs.empty() ? json() : json(t.gpu.median)},
                                    {"cpuMedianMs", t.cpu.median},
                                    {"updateMedianMs", t.update.median},
                                    {"updateCallsPerBlock", t.updateRepeats},
                                    {"drawnVertices", t.stats.drawnVertices},
                                    {"verticesPerUs", timing::verticesPerUs(t)}};
    // Frame time / the space's matrix pipeline: the median of per-frame paired ratios with their
    // quartiles (the one statistic of a time ratio, harness/figures).
    for (const timing::PipelineTiming& m : c.pipelines)
      if (m.error.empty() && (m.pipeline == "matrix" || m.pipeline.ends_with("_matrix"))) {
        const timing::Spread r = timing::spreadOf(timing::pairedRatios(m.frameMs, t.frameMs));
        if (r.n > 0)
          out["pipelines"][t.pipeline]["pairedRatioToMatrix"] = {{"median", r.median}, {"q1", r.q1}, {"q3", r.q3}, {"n", r.n}};
      }
    json phases = json::object();  // the update's phases, median ms per call
    for (int k = 0; k < timing::kUpdatePhaseCount; ++k) phases[timing::kUpdatePhases[k].key] = t.phases[k].median;
    out["pipelines"][t.pipeline]["updatePhasesMedianMs"] = phases;
  }
  auto num = [](double r) { return r > 0 ? json(r) : json(); };
  out["ratio_motor_matrix"] = num(c.frameRatio);
  out["paired_ratio_motor_matrix"] = num(c.pairedFrameRatio);
  // The figure's spread (harness/figures): the interquartile range of the per-frame ratios.
  if (c.pairedFrame.n > 0)
    out["paired_ratio_spread"] = {{"q1", c.pairedFrame.q1}, {"q3", c.pairedFrame.q3}, {"n", c.pairedFrame.n}};
  out["paired_cpu_ratio_motor_matrix"] = num(c.pairedCpuRatio);
  out["update"] = {{"ratio_motor_matrix", num(c.updateRatio)}};
  out["disturbance"] = timing::toJson(c.disturbance);
  return out;
}

}  // namespace

json timeScene(const Scene& scene, const std::vector<std::string>& pipelines, int frames, int width, int height,
               const PipelineOptions& options) {
  timing::Settings normal;
  normal.options = options;
  normal.frames = std::max(1, frames);
  normal.warmup = std::max(2, std::min(5, frames / 5));
  normal.width = width, normal.height = height;
  auto t = timing::timeScene(scene, scene.source, normal);
  if (!t) return {{"error", t.error()}};
  json out = configJson(*t, pipelines);
  timing::Settings tiny = normal;
  tiny.width = tiny.height = kTiny;
  tiny.config = "vertex-bound";
  if (timing::drawsVertexBoundAt(scene, kTiny, kTiny)) {
    auto v = timing::timeScene(scene, scene.source, tiny);
    out["vertexBound"] = v ? configJson(*v, pipelines) : json{{"error", v.error()}};
  } else {
    out["vertexBound"] = {{"skipped", "not vertex-bound at " + std::to_string(kTiny) + "x" + std::to_string(kTiny) +
                                          ": fewer than " + std::to_string(timing::kVertexBoundVerticesPerPixel) +
                                          " drawn vertices per pixel"}};
  }
  if (auto m = timing::machineInfo()) out["gl"] = mb::toJson(m->gl);  // the device every figure above is from
  out["frames"] = normal.frames;
  out["warmup"] = normal.warmup;
  out["bestOf"] = normal.bestOf;
  out["error"] = nullptr;
  const bool gpuTimer = out["frameTimeSource"] == "gpu-timer";
  char summary[384];
  std::snprintf(summary, sizeof summary,
                "%d frames per pipeline after %d warm-up at %dx%d, each the fastest of %d renders, pipelines "
                "interleaved in alternating order (harness/timing/frame_timing.h); frame time: %s; vertex-bound: "
                "the same at %dx%d where the scene draws enough vertices.",
                normal.frames, normal.warmup, width, height, normal.bestOf,
                gpuTimer ? "GL_TIME_ELAPSED timer queries (wall clock beside it)" : "wall clock around render + glFinish",
                kTiny, kTiny);
  out["summary"] = summary;
  return out;
}

}  // namespace mb::timing
