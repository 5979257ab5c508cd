// loadScene: a file (glTF/GLB or .bpt) or the name of a built-in or curved scene. Apart from
// gltf_loader.cpp so that what loads bytes (the fuzzers link it) does not pull in the scene
// generators (builtin_*.cpp, gltf_writer.cpp, curved_space.cpp, bpt_reader.cpp).
#include <cctype>
#include <filesystem>

#include "pipelines/scene/builtin/bpt_reader.h"
#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/curved_space.h"
#include "pipelines/scene/loader.h"

namespace mb {
namespace {

// ".bpt" in any case: the Bezier patch text format (bpt_reader.h).
bool hasBptExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".bpt";
}

}  // namespace

Result<Scene> loadScene(const std::string& fileOrBuiltinName) {
  if (isCurvedScene(fileOrBuiltinName)) return buildCurvedScene(fileOrBuiltinName);
  if (hasBptExtension(fileOrBuiltinName)) return loadBptFile(fileOrBuiltinName);
  if (!isBuiltinScene(fileOrBuiltinName)) return loadGltfFile(fileOrBuiltinName);
  auto glb = builtinSceneGlb(fileOrBuiltinName);
  if (!glb) return Result<Scene>::fail(glb.error());
  Result<Scene> scene = loadGltfMemory(*glb, fileOrBuiltinName);
  // The built-in scenes keep the framing their goldens and committed figures were made with.
  if (scene) scene->framing = Framing::BoundingSphere;
  return scene;
}

}  // namespace mb
