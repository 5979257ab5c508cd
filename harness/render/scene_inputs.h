// Scene arguments of the commands that take many (inspect, time, report, check):
// files, built-in names and folders, expanded the same way everywhere.
#pragma once
#include <string>
#include <vector>

namespace mb {

// Each argument as is, except folders (not built-in names), which become their .gltf/.glb
// files (recursively, sorted). `warnings` (may be nullptr) receives one line per folder that
// holds none: "DIR: folder holds no .gltf or .glb files".
std::vector<std::string> expandSceneInputs(const std::vector<std::string>& inputs,
                                           std::vector<std::string>* warnings = nullptr);

// Whether `path` names a glTF file by its extension (.gltf or .glb, any case).
bool isGltfPath(const std::string& path);

// The warnings expandSceneInputs would give for `inputs`, without the list.
std::vector<std::string> emptyInputWarnings(const std::vector<std::string>& inputs);

}  // namespace mb
