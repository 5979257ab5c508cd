// motorbench render SCENE --pipeline NAME [frame options] -o out.png
#include <cstdio>
#include <set>

#include "harness/args.h"
#include "harness/command.h"
#include "harness/render_frame.h"
#include "pipelines/scene/loader.h"

namespace mb {
namespace {

int runRender(const std::vector<std::string>& argv) {
  Args args(argv);
  std::set<std::string> known = {"pipeline", "o", "output"};
  for (const std::string& n : frameOptionNames()) known.insert(n);
  auto fail = [](const std::string& message) {
    std::fprintf(stderr, "motorbench render: error: %s\n", message.c_str());
    return 2;
  };
  if (!args.error().empty()) return fail(args.error());
  if (auto unknown = args.unknown(known); !unknown.empty()) return fail("unknown option " + unknown[0]);
  if (args.positional().size() != 1) return fail("expected one SCENE (a file or a built-in scene name)");
  std::string out = args.get("o", args.get("output", ""));
  if (out.empty()) return fail("missing -o out.png");
  std::string pipeline = args.get("pipeline", "matrix");

  auto scene = loadScene(args.positional()[0]);
  if (!scene) return fail(scene.error());
  auto settings = frameSettingsFromArgs(args, *scene);
  if (!settings) return fail(settings.error());
  auto frame = renderFrame(*scene, pipeline, *settings);
  if (!frame) return fail(frame.error());
  Status written = writeImage(out, frame->image);
  if (!written) return fail(written.error());
  const PipelineStats& s = frame->stats;
  std::printf("%s: %s %dx%d, %d draws, %.0f floats/vertex, %llu vertex bytes -> %s (%s)\n",
              scene->source.c_str(), pipeline.c_str(), frame->image.width, frame->image.height, s.draws,
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
