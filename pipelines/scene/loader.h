// glTF 2.0 loading (tinygltf) into the neutral Scene. Errors name the file and the reason.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "pipelines/result.h"
#include "pipelines/scene/scene.h"

namespace mb {

// Loads a .gltf (external files, data: URIs) or .glb file.
Result<Scene> loadGltfFile(const std::string& path);

// Loads glTF/GLB bytes already in memory. `name` is used in messages and Scene::source;
// `baseDir` resolves external URIs ("" = none allowed).
Result<Scene> loadGltfMemory(const std::vector<uint8_t>& bytes, const std::string& name,
                             const std::string& baseDir = "");

// A file path, or the name of a built-in scene (see builtin_scenes.h), which is generated as
// .glb bytes and loaded through loadGltfMemory, the same path user files take. Files ending
// in .bpt (any case) are Bezier patch files (bpt_reader.h); everything else is glTF.
Result<Scene> loadScene(const std::string& fileOrBuiltinName);

}  // namespace mb
