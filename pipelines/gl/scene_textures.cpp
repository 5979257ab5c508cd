#include "pipelines/gl/scene_textures.h"

#include <string>

#include "pipelines/gl/gpu_geometry.h"
#include "pipelines/gl/upload.h"

namespace mb::gl {
namespace {

GLuint uploadImage(const Image& img, bool srgb, uint64_t& counter) {
  GLuint id = 0;
  glGenTextures(1, &id);
  glBindTexture(GL_TEXTURE_2D, id);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, img.width, img.height, 0,
               GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
  counter += img.rgba.size();
  glGenerateMipmap(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, 0);
  return id;
}

GLuint makeSampler(const Sampler& s) {
  GLuint id = 0;
  glGenSamplers(1, &id);
  glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, s.magFilter);
  glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, s.minFilter);
  glSamplerParameteri(id, GL_TEXTURE_WRAP_S, s.wrapS);
  glSamplerParameteri(id, GL_TEXTURE_WRAP_T, s.wrapT);
  return id;
}

// The view-space direction rotated into world space by the camera orientation.
glm::vec3 cameraRelative(const View& view, glm::vec3 v) {
  return glm::normalize(view.orientation * glm::normalize(v));
}

}  // namespace

SceneTextures::~SceneTextures() { release(); }

void SceneTextures::release() {
  for (GLuint t : linear_) if (t) glDeleteTextures(1, &t);
  for (GLuint t : srgb_) if (t) glDeleteTextures(1, &t);
  for (GLuint s : samplers_) if (s) glDeleteSamplers(1, &s);
  if (defaultSampler_) glDeleteSamplers(1, &defaultSampler_);
  if (white_) glDeleteTextures(1, &white_);
  linear_.clear();
  srgb_.clear();
  samplers_.clear();
  defaultSampler_ = white_ = 0;
  scene_ = nullptr;
}

Status SceneTextures::upload(const Scene& scene, uint64_t& counter) {
  release();
  scene_ = &scene;
  linear_.assign(scene.images.size(), 0);
  srgb_.assign(scene.images.size(), 0);
  auto need = [&](const TextureRef& ref, bool srgb) -> Status {
    if (ref.texture < 0) return {};
    if (size_t(ref.texture) >= scene.textures.size())
      return Status::fail(scene.source + ": material references missing texture " +
                          std::to_string(ref.texture));
    int image = scene.textures[size_t(ref.texture)].image;
    if (image < 0 || size_t(image) >= scene.images.size()) return {};  // rendered untextured
    const Image& img = scene.images[size_t(image)];
    if (img.width <= 0 || img.height <= 0 ||
        img.rgba.size() != size_t(img.width) * size_t(img.height) * 4)
      return Status::fail(scene.source + ": image " + std::to_string(image) + " (" + img.name +
                          ") has no decoded RGBA8 data");
    GLuint& slot = (srgb ? srgb_ : linear_)[size_t(image)];
    if (!slot) slot = uploadImage(img, srgb, counter);
    return {};
  };
  for (const Material& m : scene.materials)
    for (Status s : {need(m.baseColor, true), need(m.emissive, true),
                     need(m.metallicRoughness, false), need(m.normal, false),
                     need(m.occlusion, false)})
      if (!s) return s;
  for (const Sampler& s : scene.samplers) samplers_.push_back(makeSampler(s));
  defaultSampler_ = makeSampler(Sampler{});
  const uint8_t white[4] = {255, 255, 255, 255};
  glGenTextures(1, &white_);
  glBindTexture(GL_TEXTURE_2D, white_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
  glBindTexture(GL_TEXTURE_2D, 0);
  GLenum err = glGetError();
  if (err != GL_NO_ERROR)
    return Status::fail(scene.source + ": texture upload: " + errorName(err));
  return {};
}

GLuint SceneTextures::textureFor(int textureIndex, bool srgb) const {
  if (!scene_ || textureIndex < 0 || size_t(textureIndex) >= scene_->textures.size()) return 0;
  int image = scene_->textures[size_t(textureIndex)].image;
  if (image < 0 || size_t(image) >= linear_.size()) return 0;
  return (srgb ? srgb_ : linear_)[size_t(image)];
}

void SceneTextures::bindMaterial(const Program& program, int materialIndex,
                                 uint64_t& counter) const {
  static const Material kDefault;  // glTF default: white, metallic 1, roughness 1
  const Material& m = (scene_ && materialIndex >= 0 && size_t(materialIndex) < scene_->materials.size())
                          ? scene_->materials[size_t(materialIndex)]
                          : kDefault;
  // Binds one texture slot and sets its u_<name>UV: the uv set forward.fs should sample, -1 for
  // none, set + 2 with a KHR_texture_transform, whose matrix then goes to u_<name>UVTransform
  // (only then: a material without transforms sets, and counts, what it did before them).
  auto slot = [&](const char* name, GLuint unit, const TextureRef& ref, bool srgb) {
    GLuint tex = textureFor(ref.texture, srgb);
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, tex ? tex : white_);
    int sampler = tex ? scene_->textures[size_t(ref.texture)].sampler : -1;
    glBindSampler(unit, sampler >= 0 && size_t(sampler) < samplers_.size()
                            ? samplers_[size_t(sampler)] : defaultSampler_);
    int set = tex ? (ref.texCoord == 1 ? 1 : 0) : -1;
    if (tex && ref.hasTransform) {
      const glm::mat3 t = uvTransformMatrix(ref.transform);
      uniformMatrix3(program.uniform(std::string("u_") + name + "UVTransform"), 1, &t[0][0], counter);
      set += 2;
    }
    uniform1i(program.uniform(std::string("u_") + name + "UV"), set, counter);
  };
  slot("BaseColor", kUnitBaseColor, m.baseColor, true);
  slot("MetallicRoughness", kUnitMetallicRoughness, m.metallicRoughness, false);
  slot("Normal", kUnitNormal, m.normal, false);
  slot("Occlusion", kUnitOcclusion, m.occlusion, false);
  slot("Emissive", kUnitEmissive, m.emissive, true);
  glActiveTexture(GL_TEXTURE0);

  uniform4f(program.uniform("u_BaseColorFactor"), &m.baseColorFactor.x, counter);
  uniform1f(program.uniform("u_MetallicFactor"), m.metallicFactor, counter);
  uniform1f(program.uniform("u_RoughnessFactor"), m.roughnessFactor, counter);
  uniform3f(program.uniform("u_EmissiveFactor"), &m.emissiveFactor.x, counter);
  uniform1f(program.uniform("u_NormalScale"), m.normal.scale, counter);
  uniform1f(program.uniform("u_OcclusionStrength"), m.occlusion.scale, counter);
  int mode = m.alphaMode == AlphaMode::Mask ? 1 : m.alphaMode == AlphaMode::Blend ? 2 : 0;
  uniform1i(program.uniform("u_AlphaMode"), mode, counter);
  uniform1f(program.uniform("u_AlphaCutoff"), m.alphaCutoff, counter);

  (m.doubleSided ? glDisable : glEnable)(GL_CULL_FACE);  // back faces: GL's default glCullFace
  if (m.alphaMode == AlphaMode::Blend) {
    // Straight alpha over the framebuffer; destination alpha stays 1 (opaque image).
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);  // blended surfaces do not hide each other
  } else {
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
  }
}

void setFrameUniforms(const Program& program, const View& view, uint64_t& counter) {
  glm::vec3 key = cameraRelative(view, {-0.45f, 0.75f, 0.55f});
  glm::vec3 fill = cameraRelative(view, {0.7f, -0.15f, 0.6f});
  const glm::vec3 eye = shadingEye(view);
  uniform3f(program.uniform("u_CameraPosition"), &eye.x, counter);
  uniform3f(program.uniform("u_KeyLightDirection"), &key.x, counter);
  uniform3f(program.uniform("u_FillLightDirection"), &fill.x, counter);
}

void setWinding(bool mirrored) { glFrontFace(mirrored ? GL_CW : GL_CCW); }

std::vector<DrawItem> buildDrawList(const Scene& scene) {
  std::vector<DrawItem> opaque, blend;
  for (int n : nodesInDrawOrder(scene)) {
    const Node& node = scene.nodes[size_t(n)];
    if (node.mesh < 0 || size_t(node.mesh) >= scene.meshes.size()) continue;
    const Mesh& mesh = scene.meshes[size_t(node.mesh)];
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      int mat = mesh.primitives[p].material;
      bool isBlend = mat >= 0 && size_t(mat) < scene.materials.size() &&
                     scene.materials[size_t(mat)].alphaMode == AlphaMode::Blend;
      (isBlend ? blend : opaque).push_back({n, node.mesh, int(p)});
    }
  }
  opaque.insert(opaque.end(), blend.begin(), blend.end());
  return opaque;
}

void ExtraStreams::upload(const Primitive& p, uint64_t& extraBytes, uint64_t& skinBytes) {
  if (!p.uv1.empty()) {
    uv1 = createBuffer(GL_ARRAY_BUFFER, p.uv1, extraBytes);
    pointAttributes({{kAttribUv1, 2}});
  }
  if (!p.colors.empty()) {
    color = createBuffer(GL_ARRAY_BUFFER, p.colors, extraBytes);
    pointAttributes({{kAttribColor, 4}});
  }
  if (!p.joints.empty() && p.weights.size() == p.joints.size()) {
    joints = createBuffer(GL_ARRAY_BUFFER, p.joints, skinBytes);
    glEnableVertexAttribArray(kAttribJoints);
    glVertexAttribIPointer(kAttribJoints, 4, GL_UNSIGNED_SHORT, 0, nullptr);
    weights = createBuffer(GL_ARRAY_BUFFER, p.weights, skinBytes);
    pointAttributes({{kAttribWeights, 4}});
  }
}

void ExtraStreams::setDefaults() const {
  if (!uv1) glVertexAttrib2f(kAttribUv1, 0.0f, 0.0f);
  if (!color) glVertexAttrib4f(kAttribColor, 1.0f, 1.0f, 1.0f, 1.0f);
}

void ExtraStreams::release() {
  for (GLuint* b : {&uv1, &color, &joints, &weights})
    if (*b) {
      glDeleteBuffers(1, b);
      *b = 0;
    }
}

}  // namespace mb::gl
