#include "harness/render/scene_inputs.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "pipelines/scene/builtin_scenes.h"

namespace mb {

namespace fs = std::filesystem;

bool isGltfPath(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".gltf" || ext == ".glb";
}

std::vector<std::string> expandSceneInputs(const std::vector<std::string>& inputs,
                                           std::vector<std::string>* warnings) {
  std::vector<std::string> out;
  for (const auto& in : inputs) {
    std::error_code ec;
    if (isBuiltinScene(in) || !fs::is_directory(in, ec)) {
      out.push_back(in);
      continue;
    }
    std::vector<std::string> found;
    for (auto it = fs::recursive_directory_iterator(in, fs::directory_options::skip_permission_denied, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
      if (it->is_regular_file(ec) && isGltfPath(it->path().string())) found.push_back(it->path().string());
    std::sort(found.begin(), found.end());
    if (found.empty() && warnings) warnings->push_back(in + ": folder holds no .gltf or .glb files");
    out.insert(out.end(), found.begin(), found.end());
  }
  return out;
}

std::vector<std::string> emptyInputWarnings(const std::vector<std::string>& inputs) {
  std::vector<std::string> warnings;
  expandSceneInputs(inputs, &warnings);
  return warnings;
}

}  // namespace mb
