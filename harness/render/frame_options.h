// The command-line side of a frame: which scene, animation, time, camera and size, read once
// from the options every rendering command shares, checked against the scene, and described
// back to the user (render, compare; the same rules for report/time sizes via Args::size).
#pragma once
#include <set>
#include <string>
#include <vector>

#include "harness/options/args.h"
#include "pipelines/pipeline.h"
#include "pipelines/result.h"
#include "pipelines/scene/animation.h"
#include "pipelines/scene/scene.h"

namespace mb {

struct FrameSettings {
  AnimState anim;       // animation indices already resolved against the scene
  int camera = -1;      // glTF camera index, -1 = automatic framing (camera_rule.h)
  int width = 512, height = 512;
  int instances = 1;    // --instances N: every mesh node drawn N times (addGridInstances)
  PipelineOptions options;  // given to the pipeline before prepare() (e.g. the motor morph method)
};

// --instances N (1..kMaxInstances, default 1): read from `args` and applied to `scene` with
// addGridInstances (pipelines/scene/instancing.h); a note says what it did (nodes instanced,
// nodes left drawn once). Returns N, or an error naming the option.
constexpr long kMaxInstances = 1 << 20;
// Its line under "options:" in every command's help that takes it (a literal, as gpu_option.h's).
#define MB_INSTANCES_OPTION_HELP \
  "  --instances N      every mesh node drawn N times on a grid around it, one instanced draw (1..1048576,\n" \
  "                     default 1; skinned and Bezier patch nodes stay drawn once)\n"

Result<int> applyInstancesOption(const options::Args& args, Scene& scene, std::vector<std::string>* notes);

// The option spec of a command that renders one SCENE to -o/--output: `values` and `flags`
// plus -o/--output and the frame options --anim A --time T [--anim2 B --time2 T2 --blend W]
// --camera C --size WxH --instances N --gpu (gpu_option.h). A repeated --time is an error (one
// frame per run).
options::OptionSpec sceneCommandOptions(std::set<std::string> values, std::set<std::string> flags = {});

// Reads the frame options against `scene`. Animations and cameras are indices or names. Rules
// (each failure is a message naming the option and value):
//  - --time T is seconds >= 0; without --anim it poses animation 0 and says so in `notes`; a
//    scene without animations rejects --time. A time past the animation's end is clamped to
//    its duration (what the sampler draws) and noted. --time2 needs --anim2 (default: --time).
//  - --blend W in [0, 1] needs --anim2 (default 0.5 with --anim2).
//  - --size WxH as Args::size.
// `notes` receives lines for the user about choices made for them (may be nullptr).
Result<FrameSettings> frameSettingsFromArgs(const options::Args& args, const Scene& scene,
                                            std::vector<std::string>* notes = nullptr);

// Why `spec` cannot be a scene, checked before loading: a folder ("... is a folder; render and
// compare take one file, inspect/report/time take folders"), or neither a file nor a built-in
// name (listing the built-in names). Success for an existing file or a built-in name.
Status checkSceneSpec(const std::string& spec);

// Checks pipeline names given to `option` (e.g. "--pipeline") against the registry before any
// scene is loaded: "--pipeline Motor: unknown pipeline (registered: matrix, motor, ...)".
Status checkPipelineNames(const std::string& option, const std::vector<std::string>& names);

// The start of every command that renders one SCENE to an output (-o / --output): rejects a
// parse error (args.error()), anything but one SCENE, a missing output (`outputWhat` names it
// in the message, e.g. "out.png"), a bad --gpu (applyGpuOption); then checks and loads the
// scene and reads the frame options.
struct SceneCommand {
  std::string output;
  Scene scene;
  FrameSettings settings;
  std::vector<std::string> notes;  // from frameSettingsFromArgs
};
Result<SceneCommand> parseSceneCommand(const options::Args& args, const std::string& outputWhat);

// What will be drawn, one line each, for stderr: "animation 0 'Suzanne' (1 of 1, duration
// 3.708 s) at t = 1.5 s" or "rest pose (...)", the blend when there is one, "camera: ..."
// (automatic framing, or the glTF camera's index, name and type), "size: WxH".
std::vector<std::string> describeFrame(const Scene& scene, const FrameSettings& settings);

// The one animation `time` plays: --anim A (index or name) resolved against `scene`; without
// --anim, 0 when the scene has animations, else -1 (the rest pose). `text` says which, e.g.
// "animation 1 'Run' (2 of 3, duration 0.8 s)" or "the rest pose (no animations)".
struct ChosenAnimation { int index = -1; std::string text; };
Result<ChosenAnimation> chooseAnimation(const options::Args& args, const Scene& scene);

// Prints "motorbench <command>: error: <message>" on stderr; returns 2, the error exit code.
int commandError(const char* command, const std::string& message);
// Prints "motorbench <command>: <line>" on stderr for each line.
void commandNotes(const char* command, const std::vector<std::string>& lines);

// The items of a comma-separated option value ("matrix,motor"), empty items dropped.
std::vector<std::string> splitList(const std::string& s);

// "a, b, c".
std::string joinNames(const std::vector<std::string>& names);

}  // namespace mb
