// The scenes a `motorbench report` run covers: built-in names, files and folders from the
// command line (folders expanded to the .gltf/.glb files below them, sorted), or every
// built-in scene when none is named. Each gets a stable id used for its image folder.
#pragma once
#include <string>
#include <vector>

namespace mb::report {

struct Input {
  std::string spec;  // what loadScene() receives: a built-in name or a file path
  std::string id;    // unique, file-name safe: "skinned_tube", "BoxAnimated", "Box_2"
};

// Arguments that are neither a built-in scene, an existing file nor a folder are kept (the
// scene run records the loader's error for them), so a bad argument never stops a run.
std::vector<Input> expandInputs(const std::vector<std::string>& args);

}  // namespace mb::report
