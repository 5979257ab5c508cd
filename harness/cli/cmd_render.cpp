// motorbench render SCENE [--pipeline NAME] [frame options] -o out.png
#include <cstdio>
#include <filesystem>

#include "harness/cli/command.h"
#include "harness/options/args.h"
#include "harness/render/counter_glossary.h"
#include "harness/render/frame_notes.h"
#include "harness/render/render_frame.h"

namespace mb {
namespace {

int runRender(const std::vector<std::string>& argv) {
  auto fail = [](const std::string& message) { return commandError("render", message); };
  Args args(argv, sceneCommandOptions({"pipeline"}));
  if (!args.error().empty()) return fail(args.error());
  // The output path is checked before the (slow) load and render.
  if (auto out = args.get("o", args.get("output", "")); !out.empty())
    if (Status ok = checkImageOutput(out); !ok) return fail(ok.error());
  // A pipeline name is checked before the scene is loaded and framed.
  if (auto p = args.get("pipeline"))
    if (Status ok = checkPipelineNames("--pipeline", {*p}); !ok) return fail(ok.error());
  auto cmd = parseSceneCommand(args, "out.png");
  if (!cmd) return fail(cmd.error());
  const std::string& out = cmd->output;
  const Scene& scene = cmd->scene;
  // Default: the matrix baseline of the scene's space (matrix, s3_matrix, h3_matrix).
  const std::string pipeline = args.get("pipeline", pipelineNames(scene.curved.space).front());
  commandNotes("render", cmd->notes);
  commandNotes("render", loaderFallbackLines(scene));
  commandNotes("render", unsupportedLines(scene));  // inspect's list: what this image leaves out
  std::vector<std::string> what = describeFrame(scene, cmd->settings);
  what.insert(what.begin(), "pipeline: " + pipeline + (args.has("pipeline") ? "" : " (the default)"));
  commandNotes("render", what);
  auto frame = renderFrame(scene, pipeline, cmd->settings);
  if (!frame) return fail(frame.error());
  commandNotes("render", pipelineFallbackLines(pipeline, frame->stats));
  const auto parent = std::filesystem::path(out).parent_path();
  std::error_code ec;
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  if (ec) return fail(parent.string() + ": cannot create folder: " + ec.message());
  Status written = writeImage(out, frame->image);
  if (!written) return fail(written.error());
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
    commandNotes("render", {"warning: nothing drawn: the image is background only (the scene is off screen, empty or "
                            "scaled to zero at this pose)"});
  return 0;
}

}  // namespace
}  // namespace mb

MB_COMMAND(render, "render",
           "SCENE [--pipeline NAME (default matrix; curved scenes: their space's matrix)] [--anim A] [--time T] [--anim2 B --time2 T2 "
           "--blend W] [--camera C] [--size WxH] [--instances N] [--gpu auto|llvmpipe|N] -o out.png",
           "render one frame of a scene (file or built-in name) with one pipeline to an image; "
           "--time alone poses animation 0; prints the animation, time and camera on stderr",
           mb::runRender);
MB_COMMAND_HELP(render, "render",
               "  SCENE              a .gltf/.glb file or a built-in scene name\n"
               "  -o, --output FILE  the image (.png or any format OpenImageIO writes); missing folders are created\n"
               "  --pipeline NAME    the pipeline that draws (default matrix; curved scenes: their space's matrix)\n"
               "  --anim A           animation index or name (inspect lists them)\n"
               "  --time T           seconds >= 0 (alone: poses animation 0; past the end: its last pose)\n"
               "  --anim2 B --time2 T2 --blend W   blend towards a second animation (W in 0..1, default 0.5)\n"
               "  --camera C         glTF camera index or name (default: automatic framing)\n"
               "  --size WxH         image size (default 512x512)\n",
                "motorbench render skinned_tube --time 0.5 -o out/tube.png", true);
