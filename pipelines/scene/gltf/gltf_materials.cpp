// Materials, textures, samplers and images (RGBA8) from a tinygltf::Model.
#include <tiny_gltf.h>

#include <cmath>

#include "pipelines/scene/gltf/gltf_convert.h"

namespace mb {
namespace {

// Any tinygltf image (1-4 channels, 8 or 16 bits) -> RGBA8; false when the data is unusable.
bool toRgba8(const tinygltf::Image& src, Image* dst) {
  int comps = src.component, bytes = src.bits / 8;
  if (src.width <= 0 || src.height <= 0 || comps < 1 || comps > 4 || (bytes != 1 && bytes != 2))
    return false;
  size_t pixels = size_t(src.width) * size_t(src.height);
  if (src.image.size() != pixels * size_t(comps) * size_t(bytes)) return false;
  dst->width = src.width;
  dst->height = src.height;
  dst->rgba.resize(pixels * 4);
  for (size_t i = 0; i < pixels; ++i) {
    uint8_t c[4] = {0, 0, 0, 255};
    for (int k = 0; k < comps; ++k)  // 16-bit little-endian: keep the high byte
      c[k] = src.image[(i * size_t(comps) + size_t(k)) * size_t(bytes) + size_t(bytes - 1)];
    if (comps <= 2) {  // grey (+ alpha)
      uint8_t a = comps == 2 ? c[1] : 255;
      c[1] = c[2] = c[0];
      c[3] = a;
    }
    for (int k = 0; k < 4; ++k) dst->rgba[i * 4 + size_t(k)] = c[k];
  }
  return true;
}

constexpr const char* kTextureTransform = "KHR_texture_transform";
constexpr const char* kEmissiveStrength = "KHR_materials_emissive_strength";

// `n` finite numbers from array `v` into out[0..n); false (out untouched) otherwise.
bool numbers(const tinygltf::Value& v, size_t n, float* out) {
  if (!v.IsArray() || v.ArrayLen() != n) return false;
  for (size_t k = 0; k < n; ++k)
    if (!v.Get(int(k)).IsNumber() || !std::isfinite(v.Get(int(k)).GetNumberAsDouble())) return false;
  for (size_t k = 0; k < n; ++k) out[k] = float(v.Get(int(k)).GetNumberAsDouble());
  return true;
}

// KHR_texture_transform on one textureInfo (offset, rotation, scale, texCoord override). A member
// of the wrong type keeps its default and is listed: the rest of the transform still applies.
void readTransform(const tinygltf::Value& ext, const std::string& where, TextureRef* out, Scene& scene) {
  out->hasTransform = true;
  if (!ext.IsObject()) {
    scene.unsupported.push_back(where + ": " + kTextureTransform + " is not an object (ignored)");
    out->hasTransform = false;
    return;
  }
  auto bad = [&](const char* member, const char* want) {
    scene.unsupported.push_back(where + ": " + kTextureTransform + " " + member + " is not " + want + " (default used)");
  };
  if (ext.Has("offset") && !numbers(ext.Get("offset"), 2, &out->transform.offset.x)) bad("offset", "2 finite numbers");
  if (ext.Has("scale") && !numbers(ext.Get("scale"), 2, &out->transform.scale.x)) bad("scale", "2 finite numbers");
  if (ext.Has("rotation")) {
    const tinygltf::Value& r = ext.Get("rotation");
    if (r.IsNumber() && std::isfinite(r.GetNumberAsDouble())) out->transform.rotation = float(r.GetNumberAsDouble());
    else bad("rotation", "a finite number");
  }
  if (ext.Has("texCoord")) {
    const tinygltf::Value& t = ext.Get("texCoord");
    if (t.IsInt() && t.GetNumberAsInt() >= 0) out->texCoord = t.GetNumberAsInt();
    else bad("texCoord", "an integer >= 0");
  }
}

Status textureRef(const tinygltf::Model& m, int index, int texCoord, double scale,
                  const tinygltf::ExtensionMap& extensions, const std::string& where, TextureRef* out,
                  Scene& scene) {
  if (index < -1 || index >= int(m.textures.size()))
    return Status::fail(where + ": texture " + std::to_string(index) + " does not exist");
  out->texture = index;
  out->texCoord = texCoord;
  out->scale = float(scale);
  for (const auto& [ext, v] : extensions) {
    if (ext == kTextureTransform) readTransform(v, where, out, scene);
    else scene.unsupported.push_back(where + ": texture extension " + ext + " ignored");
  }
  return {};
}

// The textures some material's textureInfo names (the ones a draw can sample).
std::vector<bool> texturesUsed(const tinygltf::Model& m) {
  std::vector<bool> used(m.textures.size(), false);
  for (const auto& mat : m.materials) {
    const auto& pbr = mat.pbrMetallicRoughness;
    for (int t : {pbr.baseColorTexture.index, pbr.metallicRoughnessTexture.index, mat.normalTexture.index,
                  mat.occlusionTexture.index, mat.emissiveTexture.index})
      if (t >= 0 && size_t(t) < used.size()) used[size_t(t)] = true;
  }
  return used;
}

// Every image as RGBA8; one that does not decode is replaced by 1x1 white, named and counted.
void convertImages(const tinygltf::Model& m, Scene& scene) {
  for (size_t i = 0; i < m.images.size(); ++i) {
    Image img;
    img.name = m.images[i].name;
    if (!toRgba8(m.images[i], &img)) {
      img.width = img.height = 1;
      img.rgba = {255, 255, 255, 255};
      scene.unsupported.push_back("image " + std::to_string(i) + " (" +
                                  (m.images[i].uri.size() > 64 ? m.images[i].uri.substr(0, 64) + "..." : m.images[i].uri) +
                                  ") not decoded: replaced by 1x1 white");
      ++scene.stats.imagesNotDecoded;
    }
    scene.images.push_back(std::move(img));
  }
}

// Every sampler (glTF's "no filter given" leaves our default).
void convertSamplers(const tinygltf::Model& m, Scene& scene) {
  for (const auto& s : m.samplers) {
    Sampler out;
    if (s.magFilter >= 0) out.magFilter = s.magFilter;
    if (s.minFilter >= 0) out.minFilter = s.minFilter;
    out.wrapS = s.wrapS;
    out.wrapT = s.wrapT;
    scene.samplers.push_back(out);
  }
}

// The image texture `i` draws after its extensions: EXT_texture_webp's image when it names
// one, else the texture's own source (KHR_texture_basisu: its fallback); what is not decoded
// is named and counted.
int textureSource(const tinygltf::Model& m, size_t i, bool used, Scene& scene) {
  const auto& t = m.textures[i];
  const std::string who = "texture " + std::to_string(i);
  int source = t.source;
  for (const auto& [ext, v] : t.extensions) {
    const int extSource = v.Has("source") && v.Get("source").IsInt() ? v.Get("source").GetNumberAsInt() : -2;
    if (ext == "EXT_texture_webp") {  // decoded like PNG/JPEG (image_decode.h); preferred to the fallback
      if (extSource >= 0 && extSource < int(m.images.size())) {
        source = extSource;
        continue;
      }
      // No image named (the Khronos validator passes such a texture when no material uses it):
      // the texture's own source stands, as it does for a viewer without the extension.
      ++scene.stats.webpTexturesWithoutSource;
      if (used && source == -1)
        scene.unsupported.push_back(who + ": EXT_texture_webp names no image (" +
                                    (v.Has("source") ? "source " + std::to_string(extSource) + " does not exist"
                                                     : std::string("no source")) +
                                    ") and the texture has no source: drawn untextured");
    } else if (ext == "KHR_texture_basisu") {  // KTX2: no decoder in Debian
      scene.unsupported.push_back(who + ": KHR_texture_basisu (KTX2) not decoded, no BasisU decoder: " +
                                  (source >= 0 ? "its fallback image " + std::to_string(source) + " is used" : "drawn untextured"));
      ++scene.stats.basisuTexturesNotDecoded;
    } else {
      scene.unsupported.push_back(who + ": extension " + ext + " ignored");
    }
  }
  return source;
}

// Texture `i`: its image and sampler, both checked (a missing image of a texture no material
// samples is dropped and counted; of one a material samples, an error).
Status convertTexture(const tinygltf::Model& m, size_t i, bool used, Scene& scene) {
  const auto& t = m.textures[i];
  const std::string who = "texture " + std::to_string(i);
  int source = textureSource(m, i, used, scene);
  if (t.sampler < -1 || t.sampler >= int(m.samplers.size()))
    return Status::fail(who + " refers to sampler " + std::to_string(t.sampler) + ", which does not exist (" +
                        std::to_string(m.samplers.size()) + " samplers)");
  if (source < -1 || source >= int(m.images.size())) {
    const std::string missing = who + " refers to image " + std::to_string(source) + ", which does not exist (" +
                                std::to_string(m.images.size()) + " images)";
    if (used) return Status::fail(missing);
    // No material samples it: nothing is drawn differently without it (three.js and the
    // Sample Viewer load such files). Kept as a texture without image.
    ++scene.stats.unusedTexturesWithoutImage;
    source = -1;
  }
  scene.textures.push_back({source, t.sampler});
  return {};
}

// The material's five textureInfos, each checked against the textures.
Status materialTextures(const tinygltf::Model& m, const tinygltf::Material& src, const std::string& where, Material& mat,
                        Scene& scene) {
  const auto& pbr = src.pbrMetallicRoughness;
  Status s;
  if (s = textureRef(m, pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, 1.0, pbr.baseColorTexture.extensions,
                     where + " baseColorTexture", &mat.baseColor, scene); !s) return s;
  if (s = textureRef(m, pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord, 1.0,
                     pbr.metallicRoughnessTexture.extensions, where + " metallicRoughnessTexture", &mat.metallicRoughness,
                     scene); !s) return s;
  if (s = textureRef(m, src.normalTexture.index, src.normalTexture.texCoord, src.normalTexture.scale,
                     src.normalTexture.extensions, where + " normalTexture", &mat.normal, scene); !s) return s;
  if (s = textureRef(m, src.occlusionTexture.index, src.occlusionTexture.texCoord, src.occlusionTexture.strength,
                     src.occlusionTexture.extensions, where + " occlusionTexture", &mat.occlusion, scene); !s) return s;
  return textureRef(m, src.emissiveTexture.index, src.emissiveTexture.texCoord, 1.0, src.emissiveTexture.extensions,
                    where + " emissiveTexture", &mat.emissive, scene);
}

// The material's extensions: KHR_materials_emissive_strength applied, the others named.
void materialExtensions(const tinygltf::Material& src, const std::string& where, Material& mat, Scene& scene) {
  for (const auto& [ext, v] : src.extensions) {
    if (ext != kEmissiveStrength) {
      scene.unsupported.push_back(where + ": extension " + ext + " ignored");
      continue;
    }
    // The emissive factor's multiplier (default 1); forward.fs draws emissive linear, unclamped
    // until the final sRGB encoding.
    const tinygltf::Value& k = v.IsObject() ? v.Get("emissiveStrength") : tinygltf::Value();
    if (k.IsNumber() && std::isfinite(k.GetNumberAsDouble()) && k.GetNumberAsDouble() >= 0)
      mat.emissiveFactor *= float(k.GetNumberAsDouble());
    else if (!v.IsObject() || v.Has("emissiveStrength"))
      scene.unsupported.push_back(where + ": " + kEmissiveStrength + " emissiveStrength is not a number >= 0 (ignored)");
  }
}

// Material `i`: its factors, textures, alpha mode and extensions.
Status convertMaterial(const tinygltf::Model& m, size_t i, Scene& scene) {
  const auto& src = m.materials[i];
  std::string where = "material " + std::to_string(i);
  Material mat;
  mat.name = src.name;
  const auto& pbr = src.pbrMetallicRoughness;
  for (size_t k = 0; k < 4 && k < pbr.baseColorFactor.size(); ++k) mat.baseColorFactor[int(k)] = float(pbr.baseColorFactor[k]);
  for (size_t k = 0; k < 3 && k < src.emissiveFactor.size(); ++k) mat.emissiveFactor[int(k)] = float(src.emissiveFactor[k]);
  mat.metallicFactor = float(pbr.metallicFactor);
  mat.roughnessFactor = float(pbr.roughnessFactor);
  if (Status s = materialTextures(m, src, where, mat, scene); !s) return s;
  mat.alphaMode = src.alphaMode == "MASK" ? AlphaMode::Mask : src.alphaMode == "BLEND" ? AlphaMode::Blend : AlphaMode::Opaque;
  mat.alphaCutoff = float(src.alphaCutoff);
  mat.doubleSided = src.doubleSided;
  materialExtensions(src, where, mat, scene);
  scene.materials.push_back(std::move(mat));
  return {};
}

}  // namespace

Status convertMaterials(const tinygltf::Model& m, Scene& scene) {
  convertImages(m, scene);
  convertSamplers(m, scene);
  const std::vector<bool> used = texturesUsed(m);
  for (size_t i = 0; i < m.textures.size(); ++i)
    if (Status s = convertTexture(m, i, used[i], scene); !s) return s;
  for (size_t i = 0; i < m.materials.size(); ++i)
    if (Status s = convertMaterial(m, i, scene); !s) return s;
  return {};
}

}  // namespace mb
