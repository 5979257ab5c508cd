// loadGltfFile / loadGltfMemory / loadScene: preflight, tinygltf parse, conversion to Scene.
#include "pipelines/scene/loader.h"

#include <stb_image.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>

#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/gltf_convert.h"
#include "pipelines/scene/preflight.h"

namespace mb {
namespace {

constexpr uint64_t kMaxFileBytes = uint64_t(2) << 30;  // tinygltf takes an unsigned int length

struct LoadContext {
  bool allowFiles = false;
  std::vector<std::string> imageNotes;
};

// Filesystem callbacks: the defaults, except that in-memory loads without a base directory
// must not resolve relative URIs against the working directory.
bool fsExists(const std::string& path, void* user) {
  return static_cast<LoadContext*>(user)->allowFiles && tinygltf::FileExists(path, nullptr);
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

// Images above this many pixels (8192 x 8192, 256 MiB as RGBA8) are not decoded: the header
// alone decides, so a few-hundred-byte PNG claiming 16000 x 16000 does not make stb_image
// reserve a gigabyte.
constexpr long long kMaxImagePixels = 1LL << 26;

// stb_image reserves a PNG chunk's declared length before reading it, so a 4 kB file whose IDAT
// claims 1 GB made it allocate 1 GB. Every chunk must fit in the bytes there are.
bool pngChunksFit(const unsigned char* bytes, int size) {
  static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (size < 8 || std::memcmp(bytes, sig, 8) != 0) return true;  // not PNG: nothing to check
  for (size_t at = 8; at + 8 <= size_t(size);) {
    uint64_t len = (uint64_t(bytes[at]) << 24) | (uint64_t(bytes[at + 1]) << 16) | (uint64_t(bytes[at + 2]) << 8) | bytes[at + 3];
    if (len + 12 > size_t(size) - at) return false;
    at += size_t(len) + 12;
  }
  return true;
}

// Undecodable images do not fail the file: the image stays empty and is replaced later.
bool loadImage(tinygltf::Image* image, const int index, std::string* err, std::string* warn,
               int reqWidth, int reqHeight, const unsigned char* bytes, int size, void* user) {
  int w = 0, h = 0, comps = 0;
  if (stbi_info_from_memory(bytes, size, &w, &h, &comps) && (long long)w * h > kMaxImagePixels) {
    static_cast<LoadContext*>(user)->imageNotes.push_back("image " + std::to_string(index) + ": " + std::to_string(w) +
                                                          "x" + std::to_string(h) + " pixels is too large (limit " +
                                                          std::to_string(kMaxImagePixels) + ")");
    image->image.clear();
    return true;
  }
  if (!pngChunksFit(bytes, size)) {
    static_cast<LoadContext*>(user)->imageNotes.push_back("image " + std::to_string(index) +
                                                          ": corrupt PNG (a chunk is longer than the image data)");
    image->image.clear();
    return true;
  }
  std::string myErr;
  if (tinygltf::LoadImageData(image, index, &myErr, warn, reqWidth, reqHeight, bytes, size, nullptr))
    return true;
  (void)err;
  std::string reason = myErr.substr(0, myErr.find('\n'));
  static_cast<LoadContext*>(user)->imageNotes.push_back("image " + std::to_string(index) + ": " + reason);
  image->image.clear();
  return true;
}

std::string firstLines(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  for (auto& c : s)
    if (c == '\n') c = ';';
  return s.size() > 400 ? s.substr(0, 400) + "..." : s;
}

void noteExtensions(const tinygltf::Model& m, Scene& scene) {
  static const std::set<std::string> supported = {"KHR_mesh_quantization"};
  static const std::set<std::string> geometry = {"KHR_draco_mesh_compression", "EXT_meshopt_compression",
                                                 "EXT_mesh_gpu_instancing", "KHR_meshopt_compression"};
  std::set<std::string> seen;
  for (const auto* list : {&m.extensionsRequired, &m.extensionsUsed})
    for (const auto& ext : *list) {
      if (supported.count(ext) || !seen.insert(ext).second) continue;
      scene.unsupported.push_back("extension " + ext + (geometry.count(ext) ? " changes geometry: not supported"
                                                                            : " not supported (ignored)"));
    }
}

Result<Scene> convert(const tinygltf::Model& m, const std::string& name, LoadContext& ctx) {
  Scene scene;
  scene.source = name;
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
  if (s = convertAnimations(m, scene); !s) return Result<Scene>::fail(name + ": " + s.error());
  return scene;
}

}  // namespace

Result<Scene> loadGltfMemory(const std::vector<uint8_t>& bytes, const std::string& name,
                             const std::string& baseDir) {
  try {
    bool glb = false;
    if (bytes.size() >= kMaxFileBytes) return Result<Scene>::fail(name + ": file too large");
    if (Status s = preflightGltf(bytes, name, &glb); !s) return Result<Scene>::fail(name + ": " + s.error());
    LoadContext ctx;
    ctx.allowFiles = !baseDir.empty();
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
    return convert(model, name, ctx);
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

Result<Scene> loadScene(const std::string& fileOrBuiltinName) {
  if (!isBuiltinScene(fileOrBuiltinName)) return loadGltfFile(fileOrBuiltinName);
  auto glb = builtinSceneGlb(fileOrBuiltinName);
  if (!glb) return Result<Scene>::fail(glb.error());
  return loadGltfMemory(*glb, fileOrBuiltinName);
}

}  // namespace mb
