// Frame timing of one scene for the report and the claims: an adapter over the measurements
// of `motorbench time` (harness/timing/frame_timing.h), run in a worker process one scene at a time
// (never in parallel with other scenes, so the pipelines' ratio is not disturbed by --jobs).
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipelines/pipeline.h"
#include "pipelines/scene/scene.h"

namespace mb::timing {

// Times every pipeline on `scene` over `frames` frames (after warm-up) at width x height.
// Returns {"frames", "pipelines": {name: {"medianMs", ...}}, "ratio_motor_matrix" (frame time,
// < 1: motor faster), ...} or {"error": "..."}.
// `options` go to every pipeline (claims time the skinned crowd with both in one SkinSpace).
nlohmann::json timeScene(const Scene& scene, const std::vector<std::string>& pipelines,
                         int frames, int width, int height, const PipelineOptions& options = {});

}  // namespace mb::timing
