// `motorbench morph [SCENE|FOLDER|MORPH.json ...] [--size N] [--json FILE]`: the image and byte
// cost of each morph method (matrix, motor (a) frame, motor (b) rotor deltas) on morph scenes
// (morph_cost.h). A FOLDER stands for the files its MANIFEST.tsv marks "morph-targets"; a .json
// file (motorbench-morph/1, written by --json) for the scenes measured there, taken as they are
// and counted in the figures with those measured now (scripts/reproduce.sh: a corpus a clone
// lacks, measured where it was present); without arguments the built-in morph_torus. Exit 0:
// every scene measured; 1: some scene failed (recorded in the JSON with its reason); 2: bad input.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "harness/cli/command.h"
#include "harness/cli/morph_cost.h"
#include "harness/cli/output_paths.h"
#include "harness/figures/figure.h"
#include "harness/options/args.h"

namespace {

using json = nlohmann::json;

int fail(const std::string& message) {
  std::fprintf(stderr, "motorbench morph: %s\n", message.c_str());
  return 2;
}

bool isMorphJson(const std::string& arg) { return std::filesystem::path(arg).extension() == ".json"; }

// A morph JSON given as an argument: its document, or why it cannot be counted with this run's
// scenes (not a morph document; frames of another size).
mb::Result<json> measuredBefore(const std::string& path, int size) {
  std::ifstream in(path);
  if (!in) return mb::Result<json>::fail(path + ": cannot read");
  json doc = json::parse(in, nullptr, false);
  if (doc.is_discarded() || !doc.is_object() || doc.value("schema", "") != "motorbench-morph/1" ||
      !doc.value("scenes", json()).is_array())
    return mb::Result<json>::fail(path + ": not a motorbench-morph/1 JSON (motorbench morph --json)");
  if (doc.value("size", 0) != size)
    return mb::Result<json>::fail(path + ": measured at " + std::to_string(doc.value("size", 0)) + " x " +
                                  std::to_string(doc.value("size", 0)) + " px, this run at " + std::to_string(size) +
                                  ": give --size " + std::to_string(doc.value("size", 0)));
  return doc;
}

// One argument in order: the scenes to measure now, or a document measured before.
struct Source {
  std::vector<std::string> scenes;
  json before;  // null: measured now
};

// `doc` (the scenes measured now) with the scenes of each earlier document, in the order the
// arguments gave them (a scene also measured now is taken from this run, one in two documents
// from the first), and the figures over all of them; `errors` counts the failed scenes read.
void countMeasuredBefore(json& doc, const std::vector<Source>& sources, const std::vector<std::string>& measuredNow,
                         int& errors) {
  const json now = doc["scenes"];
  json ordered = json::array();
  std::set<std::string> read;
  size_t next = 0;
  for (const Source& s : sources) {
    if (s.before.is_null()) {
      for (size_t i = 0; i < s.scenes.size(); ++i) ordered.push_back(now[next++]);
      continue;
    }
    for (const json& scene : s.before["scenes"]) {
      const std::string name = scene.value("scene", "");
      if (std::find(measuredNow.begin(), measuredNow.end(), name) != measuredNow.end() || !read.insert(name).second) continue;
      errors += scene.contains("error");
      ordered.push_back(scene);
    }
    // Nothing measured now: the GL of the document read (its frames were drawn there).
    const json gl = s.before.value("gl", json());
    if (doc["gl"].is_null()) doc["gl"] = gl;
    else if (gl != doc["gl"])
      std::fprintf(stderr, "motorbench morph: note: the scenes read from a JSON were drawn by another GL (%s) than this run's (%s)\n",
                   gl.is_object() ? gl.value("renderer", std::string("?")).c_str() : "?",
                   doc["gl"].value("renderer", std::string("?")).c_str());
  }
  doc["scenes"] = ordered;
  doc.update(mb::morph::morphFigures(doc));
}

int runMorphCommand(const std::vector<std::string>& argv) {
  const mb::options::Args args(argv, {{"json", "size"}, {}, {}, {}});
  if (!args.error().empty()) return fail(args.error());
  int size = 0;
  try {
    size = int(args.integer("size", 128, 16, 2048));
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  std::vector<Source> sources;
  std::vector<std::string> scenes;  // measured now
  for (const std::string& p : args.positional()) {
    if (isMorphJson(p)) {
      auto before = measuredBefore(p, size);
      if (!before) return fail(before.error());
      sources.push_back({{}, before.take()});
      continue;
    }
    std::vector<std::string> files{p};
    if (std::filesystem::is_directory(p)) {
      files = mb::morph::manifestMorphFiles(p);
      if (files.empty()) return fail(p + ": a folder without a MANIFEST.tsv listing 'morph-targets' files");
    }
    sources.push_back({files, nullptr});
    scenes.insert(scenes.end(), files.begin(), files.end());
  }
  if (sources.empty()) sources.push_back({{"morph_torus"}, nullptr}), scenes.push_back("morph_torus");
  if (const auto path = args.get("json"))
    if (mb::Status ok = mb::prepareOutputFile("--json", *path); !ok) return fail(ok.error());

  int errors = 0;
  nlohmann::json doc = mb::morph::measureMorphCost(scenes, size, &errors);
  if (std::any_of(sources.begin(), sources.end(), [](const Source& s) { return !s.before.is_null(); }))
    countMeasuredBefore(doc, sources, scenes, errors);
  for (const json& s : doc["scenes"])
    if (s.contains("error"))
      std::printf("%s: not measured: %s\n", s["scene"].get<std::string>().c_str(), s["error"].get<std::string>().c_str());
  std::printf("morph methods on %zu scene(s), %d x %d px; motor default: %s\n", doc["scenes"].size(), size, size,
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

MB_COMMAND(morph, "morph", "[SCENE|FOLDER|MORPH.json ...] [--size N] [--json FILE]",
           "image and byte cost of each morph method (matrix, motor (a) frame, (b) rotor deltas) vs matrix",
           runMorphCommand);
MB_COMMAND_HELP(morph, "morph",
                "  MORPH.json         the scenes of an earlier --json, taken as they are and counted in the figures\n"
                "  --size N           square frames of N pixels (16..2048, default 128)\n"
                "  --json FILE        every frame's PSNR and max error per method, bytes and figures (motorbench-morph/1)\n",
                "motorbench morph morph_torus ../shared/corpus-wide --json results/morph.json", false);
