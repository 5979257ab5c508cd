// motorbench render SCENE [--pipeline NAME] [frame options] -o out.png
// motorbench render SCENE --pipelines LIST|all [frame options] -o DIR: the same frame by several
// pipelines from one load on one GL context, DIR/<pipeline>.png each (a process start costs more
// than a small frame: this is how scripts and tests get every pipeline's image at once).
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "harness/cli/command.h"
#include "harness/cli/output_paths.h"
#include "harness/options/args.h"
#include "harness/render/counter_glossary.h"
#include "harness/render/frame_notes.h"
#include "harness/render/gpu_option.h"
#include "harness/render/render_frame.h"

namespace mb {
namespace {

// --pipelines LIST|all as names, checked before anything is loaded: registered, none twice;
// "all" alone (every pipeline of the scene's space) comes back as {"all"}.
Result<std::vector<std::string>> pipelineList(const std::string& value) {
  using R = Result<std::vector<std::string>>;
  const std::vector<std::string> names = splitList(value);
  if (names.empty()) return R::fail("--pipelines needs pipeline names (a,b,c) or all");
  if (names == std::vector<std::string>{"all"}) return names;
  if (Status ok = checkPipelineNames("--pipelines", names); !ok) return R::fail(ok.error());
  for (size_t i = 0; i < names.size(); ++i)
    if (std::count(names.begin(), names.end(), names[i]) > 1)
      return R::fail("--pipelines " + value + ": " + names[i] + " given twice (each writes DIR/" + names[i] + ".png)");
  return names;
}

// Renders one pipeline's frame of `scene` to `out` and prints its line on stdout.
Status renderTo(const Scene& scene, const std::string& pipeline, const FrameSettings& settings,
                const std::string& out) {
  auto frame = renderFrame(scene, pipeline, settings);
  if (!frame) return Status::fail(frame.error());
  commandNotes("render", pipelineFallbackLines(pipeline, frame->stats));
  const auto parent = std::filesystem::path(out).parent_path();
  std::error_code ec;
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  if (ec) return Status::fail(parent.string() + ": cannot create folder: " + ec.message());
  if (Status written = writeImage(out, frame->image); !written) return written;
  const PipelineStats& s = frame->stats;
  std::string instanced;  // instanced draws: how many and what each instance uploads
  if (s.instances)
    instanced = ", " + std::to_string(s.instances) + " instances x " +
                std::to_string(s.instanceBytes / s.instances) + " bytes";
  const int64_t drawn = drawnPixels(frame->image);
  std::printf("%s: %s %dx%d, %d draws, %llu vertices drawn%s, %lld drawn pixels (not background), %.0f floats/vertex, "
              "%llu vertex bytes -> %s (%s)\n",
              scene.source.c_str(), pipeline.c_str(), frame->image.width, frame->image.height, s.draws,
              static_cast<unsigned long long>(s.drawnVertices), instanced.c_str(), (long long)drawn,
              s.floatsPerVertex, static_cast<unsigned long long>(s.vertexBytes), out.c_str(),
              describeGl(frame->gl).c_str());
  // Written, but said: a background-only image is easy to take for a rendering.
  if (drawn == 0)
    commandNotes("render", {"warning: nothing drawn by " + pipeline +
                            ": the image is background only (the scene is off screen, empty or scaled to zero at this pose)"});
  return Status();
}

int runRender(const std::vector<std::string>& argv) {
  auto fail = [](const std::string& message) { return commandError("render", message); };
  options::Args args(argv, sceneCommandOptions({"pipeline", "pipelines"}));
  if (!args.error().empty()) return fail(args.error());
  const bool several = args.has("pipelines");
  if (several && args.has("pipeline"))
    return fail("--pipeline and --pipelines: give one (--pipeline NAME -o FILE, --pipelines LIST|all -o DIR)");
  // Pipeline names and the output path are checked before the (slow) load and render.
  std::vector<std::string> pipelines;
  if (several) {
    auto list = pipelineList(args.get("pipelines", ""));
    if (!list) return fail(list.error());
    pipelines = list.take();
  } else if (auto p = args.get("pipeline")) {
    if (Status ok = checkPipelineNames("--pipeline", {*p}); !ok) return fail(ok.error());
  }
  if (auto out = args.get("o", args.get("output", "")); !out.empty()) {
    // The format, then the folder: created and written into now, before the load and render.
    Status ok = several ? prepareOutputFolder("-o", out, "one <pipeline>.png per pipeline") : checkImageOutput(out);
    if (ok && !several) ok = prepareOutputFile("-o", out);
    if (!ok) return fail(ok.error());
  }
  auto cmd = parseSceneCommand(args, several ? "DIR" : "out.png");
  if (!cmd) return fail(cmd.error());
  const std::string& out = cmd->output;
  const Scene& scene = cmd->scene;
  // Default: the matrix baseline of the scene's space (matrix, s3_matrix, h3_matrix).
  const std::vector<std::string> ofSpace = pipelineNames(scene.curved.space);
  if (!several) pipelines = {args.get("pipeline", ofSpace.front())};
  if (pipelines == std::vector<std::string>{"all"}) pipelines = ofSpace;
  for (const std::string& p : pipelines)  // a whole list is refused before its first image
    if (several && std::find(ofSpace.begin(), ofSpace.end(), p) == ofSpace.end())
      return fail(scene.source + ": --pipelines " + p + " does not draw this scene's space (its pipelines: " +
                  joinNames(ofSpace) + ")");
  commandNotes("render", cmd->notes);
  commandNotes("render", loaderFallbackLines(scene));
  commandNotes("render", unsupportedLines(scene));  // inspect's list: what this image leaves out
  std::vector<std::string> what = describeFrame(scene, cmd->settings);
  what.insert(what.begin(), several ? "pipelines: " + joinNames(pipelines) + " -> " + out + "/<pipeline>.png"
                                    : "pipeline: " + pipelines[0] + (args.has("pipeline") ? "" : " (the default)"));
  commandNotes("render", what);
  std::vector<std::string> written;
  for (const std::string& p : pipelines) {
    const std::string file = several ? (std::filesystem::path(out) / (p + ".png")).string() : out;
    if (Status ok = renderTo(scene, p, cmd->settings, file); !ok)
      return fail(ok.error() + (written.empty() ? "" : " (written before it: " + joinNames(written) + ")"));
    written.push_back(file);
  }
  return 0;
}

}  // namespace
}  // namespace mb

MB_COMMAND(render, "render",
           "SCENE [--pipeline NAME (default matrix; curved scenes: their space's matrix) | --pipelines A,B,...|all] [--anim A] "
           "[--time T] [--anim2 B --time2 T2 --blend W] [--camera C] [--size WxH] [--instances N] [--gpu auto|llvmpipe|N] "
           "-o out.png (--pipelines: -o DIR)",
           "render one frame of a scene (file or built-in name) with one pipeline to an image, or with several "
           "(--pipelines) to DIR/<pipeline>.png; --time alone poses animation 0; prints the animation, time and camera on stderr",
           mb::runRender);
MB_COMMAND_HELP(render, "render",
               "  SCENE              a .gltf/.glb file or a built-in scene name\n"
               "  -o, --output FILE  the image (.png or any format OpenImageIO writes); missing folders are created\n"
               "  --pipeline NAME    the pipeline that draws (default matrix; curved scenes: their space's matrix)\n"
               "  --pipelines A,B,...|all   instead of --pipeline: each pipeline named (all: every one of the scene's\n"
               "                     space) draws the same frame in this one process; -o is then a folder: DIR/<pipeline>.png\n"
               "  --anim A           animation index or name (inspect lists them)\n"
               "  --time T           seconds >= 0 (alone: poses animation 0; past the end: its last pose)\n"
               "  --anim2 B --time2 T2 --blend W   blend towards a second animation (W in 0..1, default 0.5)\n"
               "  --camera C         glTF camera index or name (default: automatic framing)\n"
               "  --size WxH         image size (default 512x512)\n"
               MB_INSTANCES_OPTION_HELP MB_GPU_OPTION_HELP,
                "motorbench render skinned_tube --time 0.5 -o out/tube.png", true);
