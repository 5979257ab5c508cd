// `motorbench morph [SCENE|FOLDER ...] [--size N] [--json FILE]`: the image and byte cost of each
// morph method (matrix, motor (a) frame, motor (b) rotor deltas) on morph scenes (morph_cost.h).
// A FOLDER stands for the files its MANIFEST.tsv marks "morph-targets"; without arguments the
// built-in morph_torus. Exit 0: every scene measured; 1: some scene failed (recorded in the JSON
// with its reason); 2: bad input.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "harness/cli/command.h"
#include "harness/cli/morph_cost.h"
#include "harness/cli/output_paths.h"
#include "harness/figures/figure.h"
#include "harness/options/args.h"

namespace {

int fail(const std::string& message) {
  std::fprintf(stderr, "motorbench morph: %s\n", message.c_str());
  return 2;
}

int runMorphCommand(const std::vector<std::string>& argv) {
  const mb::Args args(argv, {{"json", "size"}, {}, {}, {}});
  if (!args.error().empty()) return fail(args.error());
  int size = 0;
  try {
    size = int(args.integer("size", 128, 16, 2048));
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  std::vector<std::string> scenes;
  for (const std::string& p : args.positional()) {
    if (!std::filesystem::is_directory(p)) {
      scenes.push_back(p);
      continue;
    }
    const std::vector<std::string> files = mb::morph::manifestMorphFiles(p);
    if (files.empty()) return fail(p + ": a folder without a MANIFEST.tsv listing 'morph-targets' files");
    scenes.insert(scenes.end(), files.begin(), files.end());
  }
  if (scenes.empty()) scenes.push_back("morph_torus");
  if (const auto path = args.get("json"))
    if (mb::Status ok = mb::prepareOutputFile("--json", *path); !ok) return fail(ok.error());

  int errors = 0;
  const nlohmann::json doc = mb::morph::measureMorphCost(scenes, size, &errors);
  for (const nlohmann::json& s : doc["scenes"])
    if (s.contains("error")) std::printf("%s: not measured: %s\n", s["scene"].get<std::string>().c_str(),
                                         s["error"].get<std::string>().c_str());
  std::printf("morph methods on %zu scene(s), %d x %d px; motor default: %s\n", scenes.size(), size, size,
              doc["motorDefault"].is_string() ? doc["motorDefault"].get<std::string>().c_str() : "unknown");
  for (const auto& [name, f] : doc["figures"].items()) {
    std::string where;
    if (doc["worst"].contains(name) && !doc["worst"][name].is_null()) {
      const nlohmann::json& w = doc["worst"][name];
      char t[32];
      std::snprintf(t, sizeof t, "%.3g", w["time"].get<double>());
      where = "  worst: " + std::filesystem::path(w["scene"].get<std::string>()).filename().string() + " anim " +
              std::to_string(w["anim"].get<int>()) + " t " + t;
    }
    std::printf("  %-42s %s%s\n", name.c_str(), mb::figures::valueText(mb::figures::figureFromJson(name, f)).c_str(),
                where.c_str());
  }
  if (const auto path = args.get("json"))
    if (mb::Status ok = mb::writeTextFile(*path, doc.dump(1) + "\n"); !ok) return fail(ok.error());
  return errors ? 1 : 0;
}

}  // namespace

MB_COMMAND(morph, "morph", "[SCENE|FOLDER ...] [--size N] [--json FILE]",
           "image and byte cost of each morph method (matrix, motor (a) frame, (b) rotor deltas) vs matrix",
           runMorphCommand);
MB_COMMAND_HELP(morph, "morph",
                "  --size N           square frames of N pixels (16..2048, default 128)\n"
                "  --json FILE        every frame's PSNR and max error per method, bytes and figures (motorbench-morph/1)\n",
                "motorbench morph morph_torus ../shared/corpus-wide --json results/morph.json", false);
