// The one way the harness turns (scene, pipeline, animation state, camera, size) into an
// image: used by `render` and `compare`, and by any later command that needs frames.
#pragma once
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/options/args.h"
#include "harness/render/image_metrics.h"
#include "pipelines/pipeline.h"
#include "pipelines/result.h"

namespace mb {

struct FrameSettings {
  AnimState anim;       // animation indices already resolved against the scene
  int camera = -1;      // glTF camera index, -1 = automatic framing (camera_rule.h)
  int width = 512, height = 512;
};

struct Frame {
  RgbaImage image;  // top row first, alpha 1 (opaque)
  PipelineStats stats;
  View view;
  std::string glRenderer, glVersion, glBackend;
};

// Background every pipeline clears to (RGBA8 values / 255, written as-is).
constexpr float kBackground[4] = {0.2f, 0.2f, 0.22f, 1.0f};

// Renders `scene` with the registered pipeline `pipeline` on the shared headless context:
// create, prepare, update(settings.anim), render(frameScene(...)), read back. Errors name the
// scene source and the reason: unknown pipeline (listing the registered ones), a placeholder
// pipeline (registered, factory returns nullptr), GL context/shader/upload failures.
Result<Frame> renderFrame(const Scene& scene, const std::string& pipeline,
                          const FrameSettings& settings);

// The same for several animation times with one prepared pipeline (update + render per time;
// `settings.anim.time` is replaced by each of `times`): for animated comparisons.
Result<std::vector<RgbaImage>> renderFrames(const Scene& scene, const std::string& pipeline,
                                            const FrameSettings& settings, const std::vector<float>& times);

// The options shared by render/compare: --anim A --time T [--anim2 B --time2 T2 --blend W]
// --camera C --size WxH (or N for NxN). Animations and cameras are indices or names (checked
// against `scene`); --time2 defaults to --time. Errors name the option and the value.
Result<FrameSettings> frameSettingsFromArgs(const Args& args, const Scene& scene);
// The option names frameSettingsFromArgs reads (for unknown-option checks).
const std::vector<std::string>& frameOptionNames();

// The start of every command that renders one SCENE to an output (-o / --output): rejects
// parse errors, options other than `options` + -o/--output + the frame options, anything but
// one SCENE, a missing output (`outputWhat` names it in the message, e.g. "out.png"); then
// loads the scene and reads the frame options. Errors are messages for the user.
struct SceneCommand {
  std::string output;
  Scene scene;
  FrameSettings settings;
};
Result<SceneCommand> parseSceneCommand(const Args& args, const std::set<std::string>& options,
                                       const std::string& outputWhat);

// Option --`key` as a number (`fallback` when absent); the error names the option and value.
Result<double> numberOption(const Args& args, const std::string& key, double fallback);

// Prints "motorbench <command>: error: <message>" on stderr; returns 2, the error exit code.
int commandError(const char* command, const std::string& message);

// JSON forms for the result files of the commands (every counter, by its field name).
nlohmann::json toJson(const PipelineStats& stats);
nlohmann::json toJson(const FrameSettings& settings);
nlohmann::json toJson(const View& view);
// psnr is null (and "identical" true) for identical images: JSON has no infinity.
nlohmann::json toJson(const ImageMetrics& metrics);

// The items of a comma-separated option value ("matrix,motor"), empty items dropped.
std::vector<std::string> splitList(const std::string& s);

}  // namespace mb
