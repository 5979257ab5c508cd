#include "harness/report/report_inputs.h"

#include <algorithm>
#include <filesystem>
#include <set>

#include "harness/render/scene_inputs.h"
#include "pipelines/scene/builtin_scenes.h"

namespace mb::report {
namespace {

namespace fs = std::filesystem;

// The file stem with anything but [A-Za-z0-9_-] replaced, so ids are safe in paths and URLs.
std::string safeStem(const std::string& spec) {
  std::string stem = isBuiltinScene(spec) ? spec : fs::path(spec).stem().string();
  if (stem.empty()) stem = "scene";
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') c = '_';
  return stem;
}

}  // namespace

std::vector<Input> expandInputs(const std::vector<std::string>& args) {
  // Folders as their .gltf/.glb files, as every command that takes many scenes expands them.
  const std::vector<std::string> specs = args.empty() ? builtinSceneNames() : expandSceneInputs(args);
  std::vector<Input> out;
  std::set<std::string> used;
  for (const std::string& s : specs) {
    std::string id = safeStem(s);
    for (int n = 2; used.count(id); ++n) id = safeStem(s) + "_" + std::to_string(n);
    used.insert(id);
    out.push_back({s, id});
  }
  return out;
}

}  // namespace mb::report
