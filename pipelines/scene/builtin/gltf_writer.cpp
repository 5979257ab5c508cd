#include "pipelines/scene/builtin/gltf_writer.h"

#include <tiny_gltf.h>

#include <cstring>
#include <map>
#include <sstream>

namespace mb {

GlbBuilder::GlbBuilder() : model_(std::make_unique<tinygltf::Model>()) {
  model_->asset.version = "2.0";
  model_->asset.generator = "motorbench built-in scene generator";
  model_->buffers.emplace_back();
  bin_ = &model_->buffers[0].data;
  model_->scenes.emplace_back();
  model_->defaultScene = 0;
}

GlbBuilder::~GlbBuilder() = default;

int GlbBuilder::addView(const void* data, size_t bytes, int target) {
  while (bin_->size() % 4) bin_->push_back(0);  // accessor alignment
  tinygltf::BufferView v;
  v.buffer = 0;
  v.byteOffset = bin_->size();
  v.byteLength = bytes;
  v.target = target;
  const auto* p = static_cast<const uint8_t*>(data);
  bin_->insert(bin_->end(), p, p + bytes);
  model_->bufferViews.push_back(v);
  return int(model_->bufferViews.size() - 1);
}

int GlbBuilder::addFloatAccessor(const float* data, size_t count, int comps, bool minMax) {
  tinygltf::Accessor a;
  a.bufferView = addView(data, count * size_t(comps) * sizeof(float), 0);
  a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  a.count = count;
  a.type = comps == 1 ? TINYGLTF_TYPE_SCALAR : comps == 2 ? TINYGLTF_TYPE_VEC2 : comps == 3 ? TINYGLTF_TYPE_VEC3
         : comps == 4 ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_MAT4;
  if (minMax && count) {
    a.minValues.assign(data, data + comps);
    a.maxValues.assign(data, data + comps);
    for (size_t i = 0; i < count; ++i)
      for (int c = 0; c < comps; ++c) {
        double v = data[i * size_t(comps) + size_t(c)];
        a.minValues[size_t(c)] = std::min(a.minValues[size_t(c)], v);
        a.maxValues[size_t(c)] = std::max(a.maxValues[size_t(c)], v);
      }
  }
  model_->accessors.push_back(a);
  return int(model_->accessors.size() - 1);
}

int GlbBuilder::addMesh(const std::string& name, const MeshData& m, int material) {
  tinygltf::Primitive p;
  p.mode = TINYGLTF_MODE_TRIANGLES;
  p.material = material;
  size_t n = m.positions.size();
  p.attributes["POSITION"] = addFloatAccessor(&m.positions[0].x, n, 3, true);
  if (!m.normals.empty()) p.attributes["NORMAL"] = addFloatAccessor(&m.normals[0].x, n, 3);
  if (!m.tangents.empty()) p.attributes["TANGENT"] = addFloatAccessor(&m.tangents[0].x, n, 4);
  if (!m.uv0.empty()) p.attributes["TEXCOORD_0"] = addFloatAccessor(&m.uv0[0].x, n, 2);
  if (!m.weights.empty()) p.attributes["WEIGHTS_0"] = addFloatAccessor(&m.weights[0].x, n, 4);
  if (!m.joints.empty()) {
    tinygltf::Accessor a;
    a.bufferView = addView(m.joints.data(), n * sizeof(glm::u16vec4), TINYGLTF_TARGET_ARRAY_BUFFER);
    a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    a.count = n;
    a.type = TINYGLTF_TYPE_VEC4;
    model_->accessors.push_back(a);
    p.attributes["JOINTS_0"] = int(model_->accessors.size() - 1);
  }
  tinygltf::Accessor idx;
  idx.bufferView = addView(m.indices.data(), m.indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  idx.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  idx.count = m.indices.size();
  idx.type = TINYGLTF_TYPE_SCALAR;
  model_->accessors.push_back(idx);
  p.indices = int(model_->accessors.size() - 1);
  for (const MorphTargetData& t : m.targets) {
    std::map<std::string, int> target;
    if (!t.positions.empty()) target["POSITION"] = addFloatAccessor(&t.positions[0].x, n, 3, true);
    if (!t.normals.empty()) target["NORMAL"] = addFloatAccessor(&t.normals[0].x, n, 3);
    if (!t.tangents.empty()) target["TANGENT"] = addFloatAccessor(&t.tangents[0].x, n, 3);
    p.targets.push_back(target);
  }
  tinygltf::Mesh mesh;
  mesh.name = name;
  mesh.weights.assign(m.targetWeights.begin(), m.targetWeights.end());
  mesh.primitives.push_back(p);
  model_->meshes.push_back(mesh);
  ++facts_.meshes;
  ++facts_.primitives;
  facts_.vertices += int(n);
  facts_.triangles += int(m.indices.size() / 3);
  if (material >= 0 && model_->materials[size_t(material)].normalTexture.index >= 0) ++facts_.normalMappedPrimitives;
  return int(model_->meshes.size() - 1);
}

int GlbBuilder::addMaterial(const MaterialDesc& d) {
  tinygltf::Material m;
  m.name = d.name;
  m.pbrMetallicRoughness.baseColorFactor = {d.baseColor.r, d.baseColor.g, d.baseColor.b, d.baseColor.a};
  m.pbrMetallicRoughness.metallicFactor = d.metallic;
  m.pbrMetallicRoughness.roughnessFactor = d.roughness;
  m.pbrMetallicRoughness.baseColorTexture.index = d.baseColorTexture;
  m.normalTexture.index = d.normalTexture;
  m.normalTexture.scale = d.normalScale;
  model_->materials.push_back(m);
  ++facts_.materials;
  return int(model_->materials.size() - 1);
}

int GlbBuilder::addTexturePng(const std::string& name, int w, int h, const std::vector<uint8_t>& rgba) {
  tinygltf::Image img;
  img.name = name;
  img.width = w;
  img.height = h;
  img.component = 4;
  img.bits = 8;
  img.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  img.image = rgba;
  img.mimeType = "image/png";
  model_->images.push_back(img);
  ++facts_.images;
  if (model_->samplers.empty()) {
    tinygltf::Sampler s;
    s.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    s.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
    model_->samplers.push_back(s);
  }
  tinygltf::Texture t;
  t.source = int(model_->images.size() - 1);
  t.sampler = 0;
  model_->textures.push_back(t);
  return int(model_->textures.size() - 1);
}

int GlbBuilder::addNode(const std::string& name, const glm::vec3& t, const glm::quat& r, const glm::vec3& s) {
  tinygltf::Node n;
  n.name = name;
  if (t != glm::vec3(0.0f)) n.translation = {t.x, t.y, t.z};
  if (r != glm::quat(1, 0, 0, 0)) n.rotation = {r.x, r.y, r.z, r.w};
  if (s != glm::vec3(1.0f)) n.scale = {s.x, s.y, s.z};
  model_->nodes.push_back(n);
  ++facts_.nodes;
  return int(model_->nodes.size() - 1);
}

void GlbBuilder::addChild(int parent, int child) { model_->nodes[size_t(parent)].children.push_back(child); }

void GlbBuilder::setMesh(int node, int mesh, int skin) {
  model_->nodes[size_t(node)].mesh = mesh;
  model_->nodes[size_t(node)].skin = skin;
}

void GlbBuilder::addRoot(int node) { model_->scenes[0].nodes.push_back(node); }

int GlbBuilder::addInverseBindMatrices(const std::vector<glm::mat4>& m) {
  return addFloatAccessor(&m[0][0][0], m.size(), 16);
}

int GlbBuilder::addSkin(const std::string& name, const std::vector<int>& joints, int ibm) {
  tinygltf::Skin s;
  s.name = name;
  s.joints = joints;
  s.inverseBindMatrices = ibm;
  s.skeleton = joints.empty() ? -1 : joints[0];
  model_->skins.push_back(s);
  ++facts_.skins;
  facts_.joints += int(joints.size());
  return int(model_->skins.size() - 1);
}

int GlbBuilder::addAnimation(const std::string& name) {
  tinygltf::Animation a;
  a.name = name;
  model_->animations.push_back(a);
  ++facts_.animations;
  return int(model_->animations.size() - 1);
}

void GlbBuilder::addChannel(int anim, int node, const std::string& path, const std::vector<float>& times,
                            const std::vector<float>& values, const std::string& interpolation,
                            int inputAccessor, int outputAccessor) {
  auto& a = model_->animations[size_t(anim)];
  tinygltf::AnimationSampler s;
  s.input = inputAccessor >= 0 ? inputAccessor : addFloatAccessor(times.data(), times.size(), 1, true);
  int comps = path == "rotation" ? 4 : path == "weights" ? 1 : 3;
  s.output = outputAccessor >= 0 ? outputAccessor
                                 : addFloatAccessor(values.data(), values.size() / size_t(comps), comps);
  s.interpolation = interpolation;
  a.samplers.push_back(s);
  tinygltf::AnimationChannel c;
  c.sampler = int(a.samplers.size() - 1);
  c.target_node = node;
  c.target_path = path;
  a.channels.push_back(c);
  ++facts_.channels;
}

Result<std::vector<uint8_t>> GlbBuilder::writeGlb() {
  model_->buffers[0].name = "";
  tinygltf::TinyGLTF writer;
  std::ostringstream out;
  if (!writer.WriteGltfSceneToStream(model_.get(), out, false, true))
    return Result<std::vector<uint8_t>>::fail("tinygltf could not serialise the scene");
  std::string s = out.str();
  return std::vector<uint8_t>(s.begin(), s.end());
}

}  // namespace mb
