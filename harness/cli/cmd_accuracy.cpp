// `motorbench accuracy [--skinned-files DIR] [--drift-steps N] [--json FILE]`: the accuracy
// figures of the motor side (harness/accuracy): on the built-in scenes the paper's handedness
// rule, motor blend vs slerp, the candy-wrapper skin (LBS vs motor), the quaternion -> rotor
// conversion and the curved camera drift; with --skinned-files only the volumes of the skinned
// files under DIR. Figures on stdout, progress on stderr, everything as JSON with --json. Exit 0:
// measured; 1: a skinned file failed to load (named on stderr, recorded in the JSON); 2: bad
// usage, an unwritable --json or a missing folder.
#include <cstdio>
#include <optional>

#include <nlohmann/json.hpp>

#include "harness/accuracy/accuracy_run.h"
#include "harness/accuracy/drift.h"
#include "harness/cli/command.h"
#include "harness/cli/output_paths.h"
#include "harness/figures/figure.h"
#include "harness/options/args.h"
#include "harness/process/progress.h"
#include "harness/render/frame_options.h"

namespace mb {
namespace {

using json = nlohmann::json;

void printFigures(const json& doc) {
  std::printf("%s\n", doc.value("scope", std::string()).c_str());
  for (const auto& [name, f] : doc["figures"].items())
    std::printf("  %-44s %s\n", name.c_str(), figures::valueText(figures::figureFromJson(name, f)).c_str());
}

int runAccuracy(const std::vector<std::string>& argv) {
  auto fail = [](const std::string& message) { return commandError("accuracy", message); };
  options::Args args(argv, {{"skinned-files", "drift-steps", "json"}, {}, {}});
  if (!args.error().empty()) return fail(args.error());
  if (!args.positional().empty()) return fail("unexpected argument '" + args.positional()[0] + "'");
  const int64_t driftSteps = args.integer("drift-steps", long(accuracy::kDriftSteps), 1, 1000000000);
  const std::optional<std::string> path = args.get("json");
  if (path)  // refused (or its folder made) before the work
    if (Status ok = prepareOutputFile("--json", *path); !ok) return fail(ok.error());
  int failedFiles = 0;
  json doc;
  if (const auto dir = args.get("skinned-files")) {
    doc = accuracy::newDocument("skinned-file volumes under " + *dir + ", LBS vs motor");
    std::fprintf(stderr, "motorbench accuracy: measuring the skinned-file volumes under %s\n", dir->c_str());
    if (Status ok = accuracy::addSkinnedFileFigures(*dir, doc); !ok) return fail(ok.error());
    for (const json& f : doc["details"]["skinned_files"]["failed"]) {
      std::fprintf(stderr, "motorbench accuracy: FAILED %s\n", f.value("error", std::string()).c_str());
      ++failedFiles;
    }
  } else {
    doc = accuracy::newDocument("built-in scenes: handedness rule, motor blend vs slerp, candy-wrapper skinning, "
                                "quaternion to rotor, curved camera drift");
    const std::vector<accuracy::Step> steps = accuracy::builtinSteps(driftSteps);
    process::Progress progress("accuracy", "measurements", steps.size(), false);
    for (const accuracy::Step& s : steps) {
      s.run(doc);
      progress.done(s.name);
    }
  }
  printFigures(doc);
  if (path)
    if (Status w = writeTextFile(*path, doc.dump(2, ' ', false, json::error_handler_t::replace) + "\n"); !w)
      return fail(w.error());
  return failedFiles ? 1 : 0;
}

}  // namespace
}  // namespace mb

MB_COMMAND(accuracy, "accuracy", "[--skinned-files DIR] [--drift-steps N] [--json FILE]",
           "accuracy figures: the paper's handedness rule, motor blend vs slerp, LBS vs motor skin volume, "
           "quaternion -> rotor bits, curved camera drift",
           mb::runAccuracy);
MB_COMMAND_HELP(accuracy, "accuracy",
               "  --skinned-files DIR  only the skin volumes (LBS vs motor) of the animated skinned meshes of the\n"
               "                     .gltf/.glb files under DIR (default: the built-in scenes' figures)\n"
               "  --drift-steps N    steps of the curved camera drift (default 1000000, the figures' definition)\n"
               "  --json FILE        the figures as JSON (motorbench-accuracy/1; missing folders are created)\n",
                "motorbench accuracy --json out/accuracy.json", false);
