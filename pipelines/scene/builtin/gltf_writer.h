// GlbBuilder: assembles a tinygltf::Model from plain arrays (one binary buffer, PNG images
// encoded by tinygltf's stb_image_write) and serialises it as .glb bytes. Used by the
// built-in scenes; counts what it adds so tests can compare with what the loader reports.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "pipelines/result.h"

namespace tinygltf {
class Model;
}

namespace mb {

// One morph target's deltas (empty streams are not written).
struct MorphTargetData {
  std::vector<glm::vec3> positions, normals, tangents;
};

// One triangle-list primitive as plain streams (empty streams are not written).
struct MeshData {
  std::vector<glm::vec3> positions, normals;
  std::vector<glm::vec4> tangents;
  std::vector<glm::vec2> uv0;
  std::vector<glm::u16vec4> joints;
  std::vector<glm::vec4> weights;
  std::vector<uint32_t> indices;
  std::vector<MorphTargetData> targets;  // morph targets
  std::vector<float> targetWeights;      // the mesh's default weights (empty: not written)
};

// What a generator put into a file (meshes counted once, not per instance).
struct BuiltinFacts {
  int meshes = 0, primitives = 0, vertices = 0, triangles = 0, materials = 0, images = 0;
  int nodes = 0, skins = 0, joints = 0, animations = 0, channels = 0;
  int normalMappedPrimitives = 0;
};

struct MaterialDesc {
  std::string name;
  glm::vec4 baseColor{1.0f};
  float metallic = 0.0f, roughness = 0.5f;
  int baseColorTexture = -1, normalTexture = -1;  // texture indices
  float normalScale = 1.0f;
};

class GlbBuilder {
public:
  GlbBuilder();
  ~GlbBuilder();

  // Float accessor of `comps` components; with `minMax` the bounds are written (POSITION).
  int addFloatAccessor(const float* data, size_t count, int comps, bool minMax = false);
  int addMesh(const std::string& name, const MeshData& mesh, int material);
  int addMaterial(const MaterialDesc& m);
  // rgba: w*h*4 bytes; stored as an embedded PNG. Returns the texture index (linear, repeat).
  int addTexturePng(const std::string& name, int w, int h, const std::vector<uint8_t>& rgba);
  int addNode(const std::string& name, const glm::vec3& t = glm::vec3(0.0f),
              const glm::quat& r = glm::quat(1, 0, 0, 0), const glm::vec3& s = glm::vec3(1.0f));
  void addChild(int parent, int child);
  void setMesh(int node, int mesh, int skin = -1);
  void addRoot(int node);
  // Skin over `joints`; `ibmAccessor` (MAT4 floats) may be shared between skins.
  int addSkin(const std::string& name, const std::vector<int>& joints, int ibmAccessor);
  int addInverseBindMatrices(const std::vector<glm::mat4>& m);
  int addAnimation(const std::string& name);
  // path: "translation" | "rotation" (values x,y,z,w) | "scale" | "weights" (scalars, one per
  // target per key); interpolation "LINEAR" etc.
  // `inputAccessor` may be shared (-1: written from `times`).
  void addChannel(int anim, int node, const std::string& path, const std::vector<float>& times,
                  const std::vector<float>& values, const std::string& interpolation = "LINEAR",
                  int inputAccessor = -1, int outputAccessor = -1);

  BuiltinFacts& facts() { return facts_; }
  tinygltf::Model& model() { return *model_; }
  // Binary glTF bytes (deterministic for the same calls).
  Result<std::vector<uint8_t>> writeGlb();

private:
  int addView(const void* data, size_t bytes, int target);
  std::unique_ptr<tinygltf::Model> model_;
  std::vector<uint8_t>* bin_ = nullptr;
  BuiltinFacts facts_;
};

}  // namespace mb
