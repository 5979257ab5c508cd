#include "pipelines/scene/builtin_scenes.h"

#include <algorithm>

namespace mb {

const std::vector<std::string>& builtinSceneNames() {
  static const std::vector<std::string> names = {"normal_torus", "textured_box", "skinned_tube",
                                                 "scaled_hierarchy", "crowd"};
  return names;
}

bool isBuiltinScene(const std::string& name) {
  const auto& n = builtinSceneNames();
  return std::find(n.begin(), n.end(), name) != n.end();
}

Result<std::vector<uint8_t>> builtinSceneGlb(const std::string& name) {
  return Result<std::vector<uint8_t>>::fail(name + ": built-in scene generator not implemented yet");
}

}  // namespace mb
