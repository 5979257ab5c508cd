// What `motorbench check FILE|DIR|SCENE...` checks: each argument a built-in scene name, a glTF
// file or a folder (its .gltf/.glb files, recursively, sorted), each input with the scene name
// its goldens carry (golden.h: a built-in's own name; a file's path relative to its folder
// argument, sanitised, so the names stay the same wherever the folder is checked out).
#pragma once
#include <string>
#include <vector>

#include "pipelines/result.h"

namespace mb::check {

struct CheckInput {
  std::string spec;   // what loadScene reads: the built-in name or the file's path
  std::string scene;  // the scene name in golden.json and in the image names
  std::string shown;  // a file's path relative to its folder argument (its name for a file
                      // argument); a built-in's name
  bool file = false;
};

// Errors name the argument: neither a built-in nor an existing file or folder, a file that is not
// .gltf/.glb, a folder without any, or two files whose sanitised names are the same.
Result<std::vector<CheckInput>> checkInputs(const std::vector<std::string>& arguments);

}  // namespace mb::check
