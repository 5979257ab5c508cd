#include "pipelines/scene/builtin_scenes.h"

#include <algorithm>

#include "pipelines/scene/builtin/builtin_internal.h"
#include "pipelines/scene/curved_space.h"

namespace mb {
namespace {

using Builder = void (*)(GlbBuilder&);

Builder builderFor(const std::string& name) {
  if (name == "normal_torus") return &buildNormalTorus;
  if (name == "textured_box") return &buildTexturedBox;
  if (name == "skinned_tube") return &buildSkinnedTube;
  if (name == "scaled_hierarchy") return &buildScaledHierarchy;
  if (name == "crowd") return &buildCrowd;
  if (name == "dense_torus") return &buildDenseTorus;
  if (name == "teapot") return &buildTeapot;
  if (name == "instanced_grid") return &buildInstancedGrid;
  if (name == "morph_torus") return &buildMorphTorus;
  return nullptr;
}

}  // namespace

const std::vector<std::string>& builtinSceneNames() {
  static const std::vector<std::string> names = {"normal_torus", "textured_box", "skinned_tube",
                                                 "scaled_hierarchy", "crowd", "dense_torus", "teapot",
                                                 "instanced_grid"};
  return names;
}

const std::vector<std::string>& goldenOnlySceneNames() {
  static const std::vector<std::string> names = {"morph_torus"};
  return names;
}

bool isBuiltinScene(const std::string& name) {
  return builderFor(name) != nullptr || isCurvedScene(name);
}

Result<std::vector<uint8_t>> builtinSceneGlb(const std::string& name) {
  if (isCurvedScene(name))
    return Result<std::vector<uint8_t>>::fail(name + ": a curved-space scene (built in code); glTF cannot hold it");
  Builder build = builderFor(name);
  if (!build) return Result<std::vector<uint8_t>>::fail(name + ": not a built-in scene");
  GlbBuilder b;
  build(b);
  auto bytes = b.writeGlb();
  if (!bytes) return Result<std::vector<uint8_t>>::fail(name + ": " + bytes.error());
  return bytes;
}

Result<BuiltinFacts> builtinSceneFacts(const std::string& name) {
  Builder build = builderFor(name);
  if (!build) return Result<BuiltinFacts>::fail(name + ": not a built-in scene");
  GlbBuilder b;
  build(b);
  return b.facts();
}

}  // namespace mb
