// The one way the harness turns (scene, pipeline, animation state, camera, size) into an
// image: used by `render` and `compare`, and by any later command that needs frames.
#pragma once
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/render/frame_options.h"
#include "harness/render/image_metrics.h"
#include "pipelines/gl/context.h"
#include "pipelines/pipeline.h"
#include "pipelines/result.h"

namespace mb {

struct Frame {
  RgbaImage image;  // top row first, alpha 1 (opaque)
  PipelineStats stats;
  View view;
  std::string glRenderer, glVersion, glBackend;
  gl::ContextInfo gl;  // the whole record: device, vendor (toJson below)
};

// Background every pipeline clears to (RGBA8 values / 255, written as-is).
constexpr float kBackground[4] = {0.2f, 0.2f, 0.22f, 1.0f};

// Pixels some primitive covered: those whose RGB differs from kBackground as the framebuffer
// stores it (8-bit, rounded). A drawn pixel that happens to equal the background exactly is not
// counted. 0: the frame is background only (nothing drawn, or drawn off screen or at zero scale).
int64_t drawnPixels(const RgbaImage& image);

// Renders `scene` with the registered pipeline `pipeline` on the shared headless context:
// create, prepare, update(settings.anim), render(frameScene(...)), read back. Errors name the
// scene source and the reason: unknown pipeline (listing the registered ones), a placeholder
// pipeline (registered, factory returns nullptr), GL context/shader/upload failures, and an
// exception thrown inside the pipeline ("internal error (exception): map::at"): never thrown on.
// The drawn nodes whose morph weights at `anim` are not all zero (sampleMorphWeights): what a
// pipeline that morphs no draw leaves in the base shape (PipelineStats::morphNotDrawnNodes).
int morphedNodes(const Scene& scene, const AnimState& anim);

Result<Frame> renderFrame(const Scene& scene, const std::string& pipeline,
                          const FrameSettings& settings);

// The same for several animation times with one prepared pipeline (update + render per time;
// `settings.anim.time` is replaced by each of `times`): for animated comparisons.
Result<std::vector<RgbaImage>> renderFrames(const Scene& scene, const std::string& pipeline,
                                            const FrameSettings& settings, const std::vector<float>& times);

// JSON forms for the result files of the commands (every counter, by its field name).
// The update phases (updateSamplingMs, ...) are null when this run did not time them (every
// phase 0: render, compare and report never turn the phase clock on; `motorbench time` does).
nlohmann::json toJson(const PipelineStats& stats);
nlohmann::json toJson(const FrameSettings& settings);
nlohmann::json toJson(const View& view);
// The GL context a figure was taken on, as report.json's machine.gl, `time --json` and compare's
// metrics.json record it: {"backend", "renderer", "version", "vendor", "realGpu", "kind" ("gpu" |
// "cpu-rasterizer"), "device": {"index" (null unless egl-device), "software", "drm" (or null)}}.
nlohmann::json toJson(const gl::ContextInfo& gl);
// "llvmpipe (LLVM 15.0.6, 256 bits) on egl-device 0, software": what every command prints.
std::string describeGl(const gl::ContextInfo& gl);
// psnr is null (and "identical" true) for identical images: JSON has no infinity.
nlohmann::json toJson(const ImageMetrics& metrics);

}  // namespace mb
