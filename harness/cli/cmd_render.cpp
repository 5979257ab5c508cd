// motorbench render SCENE --pipeline NAME [frame options] -o out.png
#include <cstdio>

#include "harness/options/args.h"
#include "harness/cli/command.h"
#include "harness/render/render_frame.h"

namespace mb {
namespace {

int runRender(const std::vector<std::string>& argv) {
  auto fail = [](const std::string& message) { return commandError("render", message); };
  Args args(argv);
  auto cmd = parseSceneCommand(args, {"pipeline"}, "out.png");
  if (!cmd) return fail(cmd.error());
  const std::string& out = cmd->output;
  const Scene& scene = cmd->scene;
  // Default: the matrix baseline of the scene's space (matrix, s3_matrix, h3_matrix).
  std::string pipeline = args.get("pipeline", pipelineNames(scene.curved.space).front());
  auto frame = renderFrame(scene, pipeline, cmd->settings);
  if (!frame) return fail(frame.error());
  Status written = writeImage(out, frame->image);
  if (!written) return fail(written.error());
  const PipelineStats& s = frame->stats;
  std::printf("%s: %s %dx%d, %d draws, %.0f floats/vertex, %llu vertex bytes -> %s (%s)\n",
              scene.source.c_str(), pipeline.c_str(), frame->image.width, frame->image.height, s.draws,
              s.floatsPerVertex, static_cast<unsigned long long>(s.vertexBytes), out.c_str(),
              frame->glRenderer.c_str());
  return 0;
}

}  // namespace
}  // namespace mb

MB_COMMAND(render, "render",
           "SCENE --pipeline NAME [--anim A --time T] [--anim2 B --time2 T2 --blend W] "
           "[--camera C] [--size WxH] -o out.png",
           "render one frame of a scene (file or built-in name) with one pipeline to a PNG",
           mb::runRender);
