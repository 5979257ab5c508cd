// The committed fuzz seed corpus, tests/fuzz/seeds: it is what the generator
// (tests/fuzz/seed_corpus_scenes.cpp) writes, every seed loads (images decoded) and passes what the
// fuzzer checks, it covers the variety it claims -- read from the files themselves, not from the
// generator -- and it stays small.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

#include "pipelines/scene/gltf/image_decode.h"
#include "pipelines/scene/loader.h"
#include "tests/fuzz/fuzz_exercise.h"
#include "tests/fuzz/seed_files.h"

namespace {

namespace fs = std::filesystem;
using mb::hostile::Bytes;
using mb::hostile::Json;

const fs::path kSeeds = fs::path(MB_SOURCE_DIR) / "tests" / "fuzz" / "seeds";

std::map<std::string, Bytes> readDir(const fs::path& dir) {
  std::map<std::string, Bytes> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    std::ifstream in(e.path(), std::ios::binary);
    out[e.path().filename().string()] = Bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }
  return out;
}

bool endsWith(const std::string& s, const std::string& t) { return s.size() >= t.size() && s.compare(s.size() - t.size(), t.size(), t) == 0; }

Json jsonOf(const std::string& name, const Bytes& b) {
  if (endsWith(name, ".glb")) {
    uint32_t len = mb::hostile::get32(b, 12);
    return Json::parse(b.begin() + 20, b.begin() + 20 + len);
  }
  return Json::parse(b.begin(), b.end());
}

TEST(FuzzSeeds, CommittedFilesAreWhatTheGeneratorWrites) {
  for (const auto& [sub, files] : {std::pair{"loader", mb::fuzz::loaderSeeds()}, std::pair{"images", mb::fuzz::imageSeeds()}}) {
    auto onDisk = readDir(kSeeds / sub);
    std::set<std::string> generated;
    for (const auto& f : files) {
      generated.insert(f.name);
      auto it = onDisk.find(f.name);
      ASSERT_NE(it, onDisk.end()) << sub << "/" << f.name << " missing: run `fuzz_seeds --repo tests/fuzz/seeds` (fuzz build)";
      EXPECT_EQ(it->second, f.bytes) << sub << "/" << f.name << " differs from the generator: regenerate";
    }
    for (const auto& [name, bytes] : onDisk) EXPECT_TRUE(generated.count(name)) << sub << "/" << name << " is not generated";
  }
}

TEST(FuzzSeeds, EverySeedLoadsWithItsImagesAndPassesTheFuzzChecks) {
  auto files = readDir(kSeeds / "loader");
  ASSERT_GE(files.size(), 40u);
  size_t total = 0;
  for (const auto& [name, bytes] : files) {
    total += bytes.size();
    EXPECT_LE(bytes.size(), size_t(16) << 10) << name << ": seeds stay small";
    if (!endsWith(name, ".glb") && !endsWith(name, ".gltf")) continue;
    auto r = mb::loadGltfFile((kSeeds / "loader" / name).string());
    ASSERT_TRUE(r.ok()) << r.error();
    EXPECT_EQ(r->stats.imagesNotDecoded, 0) << name;
    EXPECT_EQ(mb::fuzz::exercise(bytes.data(), bytes.size()), "") << name;
  }
  for (const auto& [name, bytes] : readDir(kSeeds / "images")) total += bytes.size();
  std::printf("[ seeds    ] %zu loader files, %zu bytes in all\n", files.size(), total);
  EXPECT_LE(total, size_t(400) << 10);
}

TEST(FuzzSeeds, LoaderSeedsCoverTheVariety) {
  std::set<std::pair<int, bool>> componentTypes;  // (componentType, normalized)
  std::set<int> sparseIndexTypes;
  std::set<std::string> interpolations, paths, cameraKinds, slots, extensions;
  bool sparseWithoutView = false, stridedShared = false, dataUriBuffer = false, dataUriImage = false, externalBin = false,
       externalImage = false, skinWithIbm = false, skinWithoutIbm = false;
  std::set<std::string> mimeTypes;
  auto files = readDir(kSeeds / "loader");
  for (const auto& [name, bytes] : files) {
    if (!endsWith(name, ".glb") && !endsWith(name, ".gltf")) continue;
    Json j = jsonOf(name, bytes);
    std::map<int, int> accessorsPerStridedView;
    for (const auto& a : j.value("accessors", Json::array())) {
      componentTypes.insert({a["componentType"].get<int>(), a.value("normalized", false)});
      if (a.contains("sparse")) {
        sparseIndexTypes.insert(a["sparse"]["indices"]["componentType"].get<int>());
        sparseWithoutView |= !a.contains("bufferView");
      }
      if (a.contains("bufferView") && j["bufferViews"][a["bufferView"].get<int>()].contains("byteStride"))
        ++accessorsPerStridedView[a["bufferView"].get<int>()];
    }
    for (const auto& [view, n] : accessorsPerStridedView) stridedShared |= n >= 3;
    for (const auto& b : j.value("buffers", Json::array())) {
      std::string uri = b.value("uri", "");
      dataUriBuffer |= uri.rfind("data:", 0) == 0;
      externalBin |= !uri.empty() && uri.rfind("data:", 0) != 0 && files.count(uri);
    }
    for (const auto& im : j.value("images", Json::array())) {
      std::string uri = im.value("uri", "");
      dataUriImage |= uri.rfind("data:image/", 0) == 0;
      externalImage |= !uri.empty() && uri.rfind("data:", 0) != 0 && files.count(uri);
      if (im.contains("mimeType")) mimeTypes.insert(im["mimeType"].get<std::string>());
      if (uri.rfind("data:image/jpeg", 0) == 0) mimeTypes.insert("image/jpeg");
    }
    for (const auto& an : j.value("animations", Json::array())) {
      for (const auto& s : an["samplers"]) interpolations.insert(s.value("interpolation", "LINEAR"));
      for (const auto& c : an["channels"]) paths.insert(c["target"]["path"].get<std::string>());
    }
    for (const auto& s : j.value("skins", Json::array())) (s.contains("inverseBindMatrices") ? skinWithIbm : skinWithoutIbm) = true;
    for (const auto& c : j.value("cameras", Json::array())) cameraKinds.insert(c["type"].get<std::string>());
    for (const auto& m : j.value("materials", Json::array())) {
      for (const char* k : {"normalTexture", "occlusionTexture", "emissiveTexture"})
        if (m.contains(k)) slots.insert(k);
      for (const char* k : {"baseColorTexture", "metallicRoughnessTexture"})
        if (m.contains("pbrMetallicRoughness") && m["pbrMetallicRoughness"].contains(k)) slots.insert(k);
    }
    for (const auto& e : j.value("extensionsUsed", Json::array())) extensions.insert(e.get<std::string>());
  }
  using namespace mb::hostile;
  for (int ct : {kByte, kUByte, kShort, kUShort, kUInt, kFloat}) EXPECT_TRUE(componentTypes.count({ct, false})) << ct;
  for (int ct : {kByte, kUByte, kShort, kUShort}) EXPECT_TRUE(componentTypes.count({ct, true})) << ct << " normalized";
  EXPECT_EQ(sparseIndexTypes, (std::set<int>{kUByte, kUShort, kUInt}));
  EXPECT_TRUE(sparseWithoutView);
  EXPECT_TRUE(stridedShared) << "an interleaved view (three accessors, one byteStride)";
  EXPECT_TRUE(dataUriBuffer && dataUriImage);
  EXPECT_TRUE(externalBin && externalImage) << ".gltf with an external .bin and image next to it";
  EXPECT_EQ(interpolations, (std::set<std::string>{"LINEAR", "STEP", "CUBICSPLINE"}));
  EXPECT_EQ(paths, (std::set<std::string>{"translation", "rotation", "scale", "weights"}));
  EXPECT_TRUE(skinWithIbm && skinWithoutIbm);
  EXPECT_EQ(cameraKinds, (std::set<std::string>{"perspective", "orthographic"}));
  EXPECT_EQ(slots.size(), 5u);
  EXPECT_TRUE(mimeTypes.count("image/png") && mimeTypes.count("image/jpeg"));
  int ignoredKhr = 0;
  for (const auto& e : extensions) ignoredKhr += e.rfind("KHR_", 0) == 0 && e != "KHR_mesh_quantization";
  EXPECT_GE(ignoredKhr, 4) << "KHR extensions the loader ignores";
}

TEST(FuzzSeeds, ImageSeedsCoverPngColourTypesAndJpegKindsAndDecode) {
  std::set<std::pair<int, int>> png;  // (colour type, bit depth)
  bool adam7 = false;
  std::set<int> jpegComponents, jpegFrames;  // SOF marker: C0 baseline, C2 progressive
  for (const auto& [name, b] : readDir(kSeeds / "images")) {
    auto d = mb::decodeImage(b.data(), b.size());
    EXPECT_TRUE(d.ok()) << name << ": " << d.error();
    if (b.size() > 28 && b[0] == 0x89) {
      png.insert({b[25], b[24]});
      adam7 |= b[28] == 1;
    } else {
      for (size_t i = 2; i + 9 < b.size(); ++i)
        if (b[i] == 0xFF && (b[i + 1] == 0xC0 || b[i + 1] == 0xC2)) {
          jpegFrames.insert(b[i + 1]);
          jpegComponents.insert(b[i + 9]);
          break;
        }
    }
  }
  for (auto ct : {std::pair{0, 8}, {0, 16}, {0, 1}, {0, 4}, {2, 8}, {2, 16}, {3, 8}, {3, 2}, {4, 8}, {6, 8}, {6, 16}})
    EXPECT_TRUE(png.count(ct)) << "PNG colour type " << ct.first << " depth " << ct.second;
  EXPECT_TRUE(adam7);
  EXPECT_EQ(jpegComponents, (std::set<int>{1, 3}));
  EXPECT_EQ(jpegFrames, (std::set<int>{0xC0, 0xC2}));
}

}  // namespace
