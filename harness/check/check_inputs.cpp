#include "harness/check/check_inputs.h"

#include <algorithm>
#include <filesystem>
#include <map>

#include "harness/check/golden.h"
#include "harness/render/scene_inputs.h"
#include "pipelines/scene/builtin_scenes.h"

namespace mb::check {
namespace {

namespace fs = std::filesystem;
using Inputs = Result<std::vector<CheckInput>>;

CheckInput fileInput(const fs::path& path, const fs::path& relative) {
  const std::string shown = relative.generic_string();
  return {path.string(), fileSceneName(shown), shown, true};
}

// The folder's glTF files (expandSceneInputs: recursively, sorted), named by their relative path.
std::vector<CheckInput> folderInputs(const fs::path& folder) {
  std::vector<CheckInput> found;
  for (const std::string& path : expandSceneInputs({folder.string()}))
    found.push_back(fileInput(path, fs::path(path).lexically_relative(folder)));
  std::sort(found.begin(), found.end(), [](const CheckInput& a, const CheckInput& b) { return a.shown < b.shown; });
  return found;
}

}  // namespace

Inputs checkInputs(const std::vector<std::string>& arguments) {
  std::vector<CheckInput> inputs;
  for (const std::string& a : arguments) {
    std::error_code ec;
    if (isBuiltinScene(a)) {
      inputs.push_back({a, a, a, false});
    } else if (fs::is_directory(a, ec)) {
      std::vector<CheckInput> found = folderInputs(a);
      if (found.empty()) return Inputs::fail(a + ": folder holds no .gltf or .glb files");
      inputs.insert(inputs.end(), found.begin(), found.end());
    } else if (fs::is_regular_file(a, ec)) {
      if (!isGltfPath(a)) return Inputs::fail(a + ": not a .gltf or .glb file");
      inputs.push_back(fileInput(a, fs::path(a).filename()));
    } else {
      return Inputs::fail(a + ": no such file or folder, nor a built-in scene (`motorbench scenes` lists them)");
    }
  }
  std::map<std::string, std::string> byScene;  // scene name -> the input that has it
  for (const CheckInput& in : inputs) {
    auto [at, fresh] = byScene.emplace(in.scene, in.spec);
    if (!fresh && at->second != in.spec)
      return Inputs::fail(at->second + " and " + in.spec + " would share the golden name '" + in.scene +
                          "' (their paths relative to the folder argument read the same once sanitised): check them "
                          "from their common parent folder, or with separate --golden folders");
  }
  // The same input named twice is checked once.
  std::vector<CheckInput> unique;
  for (const CheckInput& in : inputs)
    if (std::none_of(unique.begin(), unique.end(), [&](const CheckInput& u) { return u.scene == in.scene; }))
      unique.push_back(in);
  return unique;
}

}  // namespace mb::check
