// "instanced_grid": the textured, normal-mapped box drawn as 256 instances of one node through
// EXT_mesh_gpu_instancing (a 16 x 16 grid, each instance turned about its own axis and
// uniformly scaled; instance 17 scaled non-uniformly, instance 40 mirrored by a negative
// scale), under a parent that turns once in 4 s, so the per-frame composition node world *
// instance is exercised at every time the report draws.
#include <cmath>

#include <tiny_gltf.h>

#include "pipelines/scene/builtin/builtin_internal.h"

namespace mb {

void buildInstancedGrid(GlbBuilder& b) {
  constexpr int kSide = 16;
  constexpr float kSpacing = 2.5f;
  std::vector<float> translations, rotations, scales;
  for (int i = 0; i < kSide * kSide; ++i) {
    const float x = (float(i % kSide) - 0.5f * (kSide - 1)) * kSpacing;
    const float z = (float(i / kSide) - 0.5f * (kSide - 1)) * kSpacing;
    // A deterministic axis and angle per instance (no random generator: the bytes are fixed).
    const glm::vec3 axis = glm::normalize(glm::vec3(std::sin(0.7f * float(i)), 1.0f, std::cos(1.3f * float(i))));
    const glm::quat q = glm::angleAxis(0.37f * float(i), axis);
    const float s = 0.6f + 0.4f * float((i * 7) % 11) / 10.0f;
    glm::vec3 scale(s);
    if (i == 17) scale = glm::vec3(1.3f, 0.5f, 0.8f);  // non-uniform: the motor scale fallback
    if (i == 40) scale = glm::vec3(-0.8f, 0.8f, 0.8f);  // mirrored: winding flips
    translations.insert(translations.end(), {x, 0.0f, z});
    rotations.insert(rotations.end(), {q.x, q.y, q.z, q.w});
    scales.insert(scales.end(), {scale.x, scale.y, scale.z});
  }
  const size_t count = size_t(kSide * kSide);
  tinygltf::Value::Object attributes;
  attributes["TRANSLATION"] = tinygltf::Value(b.addFloatAccessor(translations.data(), count, 3));
  attributes["ROTATION"] = tinygltf::Value(b.addFloatAccessor(rotations.data(), count, 4));
  attributes["SCALE"] = tinygltf::Value(b.addFloatAccessor(scales.data(), count, 3));
  tinygltf::Value::Object extension;
  extension["attributes"] = tinygltf::Value(attributes);

  const int box = addTexturedBoxMesh(b);
  const int root = b.addNode("turntable", glm::vec3(0.0f), glm::quat(1, 0, 0, 0), glm::vec3(0.5f));
  const int grid = b.addNode("grid", glm::vec3(0.0f, 0.5f, 0.0f), glm::angleAxis(0.3f, glm::vec3(1, 0, 0)));
  b.addChild(root, grid);
  b.setMesh(grid, box);
  b.addRoot(root);
  b.model().nodes[size_t(grid)].extensions["EXT_mesh_gpu_instancing"] = tinygltf::Value(extension);
  b.model().extensionsUsed.push_back("EXT_mesh_gpu_instancing");

  const int anim = b.addAnimation("turn");
  std::vector<float> spin;  // quarter turns about Y (LINEAR slerp)
  for (int k = 0; k <= 4; ++k) {
    const glm::quat q = glm::angleAxis(1.57079632679f * float(k), glm::vec3(0, 1, 0));
    spin.insert(spin.end(), {q.x, q.y, q.z, q.w});
  }
  b.addChannel(anim, root, "rotation", {0, 1, 2, 3, 4}, spin);
}

}  // namespace mb
