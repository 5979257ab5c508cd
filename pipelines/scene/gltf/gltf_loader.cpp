// loadGltfFile / loadGltfMemory: preflight, tinygltf parse, conversion to Scene (loadScene, which
// also builds the built-in, curved and .bpt scenes, is load_scene.cpp: the fuzzers link this file
// without the scene generators).
#include "pipelines/scene/loader.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "pipelines/scene/gltf/compressed_geometry.h"
#include "pipelines/scene/gltf/gltf_convert.h"
#include "pipelines/scene/gltf/image_decode.h"
#include "pipelines/scene/instancing.h"
#include "pipelines/scene/repair/preflight.h"

namespace mb {
namespace {

constexpr uint64_t kMaxFileBytes = uint64_t(2) << 30;  // tinygltf takes an unsigned int length

struct LoadContext {
  bool allowFiles = false;
  std::string baseDir;
  std::vector<std::string> imageNotes;
  int webpImages = 0;
};

// Filesystem callbacks: the defaults, except that in-memory loads without a base directory
// must not resolve relative URIs against the working directory, and that a URI with a scheme
// (http://..., an undecodable data: URI) is never looked up as a file (conformance.h notes it).
bool fsExists(const std::string& path, void* user) {
  const auto* ctx = static_cast<LoadContext*>(user);
  std::string rel = path.rfind(ctx->baseDir, 0) == 0 ? path.substr(ctx->baseDir.size()) : path;
  while (!rel.empty() && rel.front() == '/') rel.erase(0, 1);
  return ctx->allowFiles && uriScheme(rel).empty() && tinygltf::FileExists(path, nullptr);
}
std::string fsExpand(const std::string& path, void*) { return path; }  // no ~ or $VAR expansion
bool fsRead(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  if (!static_cast<LoadContext*>(user)->allowFiles) {
    if (err) *err += "external file '" + path + "' not allowed (no base directory)\n";
    return false;
  }
  return tinygltf::ReadWholeFile(out, err, path, nullptr);
}
bool fsWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "writing files is not allowed while loading\n";
  return false;
}

// Undecodable images do not fail the file: the image stays empty (replaced by 1x1 white and
// counted later) and the reason is listed. Decoding is decodeImage's: header checks, then
// OpenImageIO's PNG or JPEG reader; the result is always RGBA8.
bool loadImage(tinygltf::Image* image, const int index, std::string* err, std::string* warn,
               int reqWidth, int reqHeight, const unsigned char* bytes, int size, void* user) {
  (void)err;
  (void)warn;
  auto& notes = static_cast<LoadContext*>(user)->imageNotes;
  image->image.clear();
  Result<DecodedImage> d = decodeImage(bytes, size > 0 ? size_t(size) : 0);
  if (d && ((reqWidth > 0 && reqWidth != d->width) || (reqHeight > 0 && reqHeight != d->height)))
    d = Result<DecodedImage>::fail("size differs from the declared " + std::to_string(reqWidth) + "x" + std::to_string(reqHeight));
  if (!d) {
    notes.push_back("image " + std::to_string(index) + ": " + d.error());
    return true;
  }
  image->width = d->width;
  image->height = d->height;
  image->component = 4;
  image->bits = 8;
  image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  image->image = std::move(d->rgba);
  static_cast<LoadContext*>(user)->webpImages += d->format == ImageFormat::Webp;
  return true;
}

std::string firstLines(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  for (auto& c : s)
    if (c == '\n') c = ';';
  return s.size() > 400 ? s.substr(0, 400) + "..." : s;
}

void noteExtensions(const tinygltf::Model& m, Scene& scene) {
  static const std::set<std::string> supported = {"KHR_mesh_quantization", kBezierPatchesExtension,
                                                  "KHR_draco_mesh_compression", "EXT_meshopt_compression",
                                                  "KHR_meshopt_compression", "EXT_texture_webp", kInstancingExtension,
                                                  "KHR_texture_transform", "KHR_materials_emissive_strength"};
  std::set<std::string> seen;
  for (const auto* list : {&m.extensionsRequired, &m.extensionsUsed})
    for (const auto& ext : *list) {
      if (supported.count(ext) || !seen.insert(ext).second) continue;
      scene.unsupported.push_back("extension " + ext + " not supported (ignored)");
    }
}

// The accessors a Draco primitive declares, before decodeDracoPrimitives replaces them by the
// decoded ones: a primitive whose decoded count differs from a declared one is drawn from the
// decoded data (as three.js does) and counted (LoadStats::dracoCountMismatch).
struct DeclaredDraco {
  size_t mesh = 0, primitive = 0;
  std::map<std::string, int> attributes;
  int indices = -1;
};

std::vector<DeclaredDraco> declaredDraco(const tinygltf::Model& m) {
  std::vector<DeclaredDraco> out;
  for (size_t mi = 0; mi < m.meshes.size(); ++mi)
    for (size_t pi = 0; pi < m.meshes[mi].primitives.size(); ++pi) {
      const tinygltf::Primitive& p = m.meshes[mi].primitives[pi];
      if (p.extensions.count("KHR_draco_mesh_compression")) out.push_back({mi, pi, p.attributes, p.indices});
    }
  return out;
}

int dracoCountMismatches(const tinygltf::Model& m, const std::vector<DeclaredDraco>& declared) {
  auto count = [&](int a) { return a >= 0 && size_t(a) < m.accessors.size() ? m.accessors[size_t(a)].count : size_t(0); };
  int n = 0;
  for (const DeclaredDraco& d : declared) {
    const tinygltf::Primitive& p = m.meshes[d.mesh].primitives[d.primitive];
    bool differs = d.indices >= 0 && p.indices != d.indices && count(p.indices) != count(d.indices);
    for (const auto& [name, before] : d.attributes) {
      auto now = p.attributes.find(name);
      differs |= now != p.attributes.end() && now->second != before && count(now->second) != count(before);
    }
    n += differs;
  }
  return n;
}

// A GLB whose JSON chunk length is not a multiple of 4 (preflightGltf read it as three.js does).
bool jsonChunkUnpadded(const std::vector<uint8_t>& b) {
  if (b.size() < 20 || std::memcmp(b.data(), "glTF", 4) != 0) return false;
  uint32_t length = 0;
  std::memcpy(&length, b.data() + 12, 4);
  return length % 4 != 0;
}

Result<Scene> convert(const tinygltf::Model& m, const std::string& name, LoadContext& ctx,
                      const ConformedGltf& conformed, const CompressionStats& compression, int dracoMismatches,
                      bool jsonUnpadded) {
  Scene scene;
  scene.source = name;
  scene.compression = compression;
  scene.compression.webpImages = ctx.webpImages;
  scene.stats.binChunkUnaligned = conformed.binChunkPadded;
  scene.stats.dracoCountMismatch = dracoMismatches;
  scene.stats.jsonChunkUnpadded = jsonUnpadded;
  for (const auto& note : conformed.notes) scene.unsupported.push_back(note);
  noteExtensions(m, scene);
  Status s = convertNodes(m, scene);
  if (s) s = convertMaterials(m, scene);
  if (!s) return Result<Scene>::fail(name + ": " + s.error());
  for (auto& note : ctx.imageNotes) scene.unsupported.push_back(note);
  // JOINTS_n bounds: the smallest skin a mesh is drawn with.
  std::vector<uint32_t> jointLimit(m.meshes.size(), 65536u);
  for (const auto& n : scene.nodes)
    if (n.mesh >= 0 && n.skin >= 0)
      jointLimit[size_t(n.mesh)] = std::min(jointLimit[size_t(n.mesh)], uint32_t(scene.skins[size_t(n.skin)].joints.size()));
  for (size_t i = 0; i < m.meshes.size(); ++i) {
    auto mesh = convertMesh(m, int(i), jointLimit[i], scene);
    if (!mesh) return Result<Scene>::fail(name + ": " + mesh.error());
    scene.meshes.push_back(mesh.take());
  }
  scene.stats.instancingDrawnOnce += dropUndrawableInstances(scene);
  checkNodeWeights(scene);
  if (s = convertAnimations(m, scene); !s) return Result<Scene>::fail(name + ": " + s.error());
  countAccessorBoundsMismatches(m, scene);
  countAccessorsPastBufferView(m, scene);
  return scene;
}

}  // namespace

Result<Scene> loadGltfMemory(const std::vector<uint8_t>& original, const std::string& name,
                             const std::string& baseDir) {
  try {
    bool glb = false;
    if (original.size() >= kMaxFileBytes) return Result<Scene>::fail(name + ": file too large");
    ConformedGltf conformed;
    if (Status s = preflightGltf(original, name, &glb, &conformed); !s) return Result<Scene>::fail(name + ": " + s.error());
    const std::vector<uint8_t>& bytes = conformed.bytes.empty() ? original : conformed.bytes;
    if (bytes.size() >= kMaxFileBytes) return Result<Scene>::fail(name + ": file too large (after re-encoding data: URIs)");
    LoadContext ctx;
    ctx.allowFiles = !baseDir.empty();
    ctx.baseDir = baseDir;
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&fsExists, &fsExpand, &fsRead, &fsWrite, &ctx});
    loader.SetImageLoader(&loadImage, &ctx);
    tinygltf::Model model;
    std::string err, warn;
    bool ok = glb ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), baseDir)
                  : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                               unsigned(bytes.size()), baseDir);
    if (!ok && err.empty()) {
      const std::string why = explainRefusal(bytes);
      return Result<Scene>::fail(name + ": " + (why.empty() ? "tinygltf refused the file without saying why" : why));
    }
    if (!ok) return Result<Scene>::fail(name + ": " + firstLines(err));
    applyConformance(conformed, model);
    CompressionStats compression;
    const std::vector<DeclaredDraco> declared = declaredDraco(model);
    Status decoded = decodeMeshoptViews(model, compression);
    if (decoded) decoded = decodeDracoPrimitives(model, compression);
    if (!decoded) return Result<Scene>::fail(name + ": " + decoded.error());
    return convert(model, name, ctx, conformed, compression, dracoCountMismatches(model, declared),
                   glb && jsonChunkUnpadded(original));
  } catch (const std::exception& e) {
    return Result<Scene>::fail(name + ": " + e.what());
  }
}

Result<Scene> loadGltfFile(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return Result<Scene>::fail(path + ": no such file");
  uint64_t size = fs::file_size(path, ec);
  if (ec || size >= kMaxFileBytes) return Result<Scene>::fail(path + ": cannot read (size)");
  std::ifstream in(path, std::ios::binary);
  std::vector<uint8_t> bytes(size_t(size), 0);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size)))
    return Result<Scene>::fail(path + ": read error");
  std::string dir = fs::path(path).parent_path().string();
  return loadGltfMemory(bytes, path, dir.empty() ? "." : dir);
}

}  // namespace mb
