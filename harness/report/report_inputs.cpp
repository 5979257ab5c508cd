#include "harness/report/report_inputs.h"

#include <algorithm>
#include <filesystem>
#include <set>

#include "pipelines/scene/builtin_scenes.h"

namespace mb::report {
namespace {

namespace fs = std::filesystem;

bool isGltf(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".gltf" || ext == ".glb";
}

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
  std::vector<std::string> specs;
  if (args.empty()) specs = builtinSceneNames();
  for (const std::string& a : args) {
    std::error_code ec;
    if (isBuiltinScene(a) || !fs::is_directory(a, ec)) {
      specs.push_back(a);
      continue;
    }
    std::vector<std::string> found;
    for (auto it = fs::recursive_directory_iterator(a, fs::directory_options::skip_permission_denied, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
      if (it->is_regular_file(ec) && isGltf(it->path())) found.push_back(it->path().string());
    std::sort(found.begin(), found.end());
    specs.insert(specs.end(), found.begin(), found.end());
  }
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
