// `motorbench scenes -o DIR [NAME...]`: writes the built-in scenes as DIR/<name>.glb.
#include <cstdio>
#include <filesystem>

#include "harness/options/args.h"
#include "harness/cli/command.h"
#include "harness/cli/output_paths.h"
#include "pipelines/scene/builtin_scenes.h"

namespace {

int runScenes(const std::vector<std::string>& argv) {
  mb::options::Args args(argv, {{"o", "out"}, {}, {}});
  std::string dir = args.get("o", args.get("out", ""));
  if (!args.error().empty() || dir.empty()) {
    std::fprintf(stderr, "usage: motorbench scenes -o DIR [NAME...]\n  %s\n",
                 args.error().empty() ? "missing -o DIR" : args.error().c_str());
    return 2;
  }
  std::vector<std::string> names = args.positional();
  if (names.empty()) names = mb::builtinSceneNames();
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    std::fprintf(stderr, "motorbench scenes: %s: %s\n", dir.c_str(), ec.message().c_str());
    return 2;
  }
  for (const auto& name : names) {
    auto glb = mb::builtinSceneGlb(name);
    if (!glb) {
      std::string known;
      for (const auto& n : mb::builtinSceneNames()) known += (known.empty() ? "" : ", ") + n;
      std::fprintf(stderr, "motorbench scenes: %s (built-in: %s)\n", glb.error().c_str(), known.c_str());
      return 2;
    }
    std::string path = (std::filesystem::path(dir) / (name + ".glb")).string();
    if (mb::Status w = mb::writeTextFile(path, std::string(glb->begin(), glb->end())); !w) {
      std::fprintf(stderr, "motorbench scenes: %s\n", w.error().c_str());
      return 2;
    }
    std::printf("%s (%zu bytes)\n", path.c_str(), glb->size());
  }
  return 0;
}

}  // namespace

MB_COMMAND(scenes, "scenes", "-o DIR [NAME...]",
           "write the built-in procedural scenes as DIR/<name>.glb", runScenes);
MB_COMMAND_HELP(scenes, "scenes",
               "  -o DIR             the folder for DIR/<name>.glb\n"
               "  NAME...            only these built-in scenes (default: all)\n",
                "motorbench scenes -o out/scenes crowd", false);
