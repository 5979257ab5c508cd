// Malformed inputs give an error naming the file and the problem, never a crash: truncated
// .glb at many offsets, bad magic, broken JSON, accessor/index/bufferView out of range, a
// missing external buffer, huge counts.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/loader.h"
#include "tests/support/scene_test_gltf.h"

namespace fs = std::filesystem;

namespace {

void expectError(const mb::Result<mb::Scene>& r, const std::string& file, const std::string& reason) {
  ASSERT_FALSE(r.ok()) << file << " loaded but should fail with '" << reason << "'";
  EXPECT_EQ(r.error().rfind(file + ": ", 0), 0u) << r.error();
  EXPECT_NE(r.error().find(reason), std::string::npos) << r.error();
}

mbtest::TestGltf triangle() {
  mbtest::TestGltf g;
  int pos = g.accessor(g.viewOf(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}), 5126, 3, "VEC3");
  g.doc["accessors"][size_t(pos)]["min"] = {0, 0, 0};
  g.doc["accessors"][size_t(pos)]["max"] = {1, 1, 0};
  int idx = g.accessor(g.viewOf(std::vector<uint16_t>{0, 1, 2}), 5123, 3, "SCALAR");
  g.meshPrimitive({{"POSITION", pos}}, idx);
  return g;
}

}  // namespace

TEST(SceneMalformed, ValidBaselineLoads) {
  auto g = triangle();
  EXPECT_TRUE(mb::loadGltfMemory(g.glb(), "t.glb").ok());
  EXPECT_TRUE(mb::loadGltfMemory(g.gltf(), "t.gltf").ok());
}

TEST(SceneMalformed, TruncatedGlbAtEveryOffset) {
  auto glb = mb::builtinSceneGlb("textured_box");
  ASSERT_TRUE(glb.ok());
  const auto& bytes = *glb;
  std::vector<size_t> cuts = {0, 1, 4, 11, 12, 16, 19, 20, 21, 100, bytes.size() / 2, bytes.size() - 8,
                              bytes.size() - 4, bytes.size() - 1};
  for (size_t step = 7; step < bytes.size(); step += 997) cuts.push_back(step);
  for (size_t cut : cuts) {
    std::vector<uint8_t> part(bytes.begin(), bytes.begin() + long(cut));
    auto r = mb::loadGltfMemory(part, "box.glb");
    ASSERT_FALSE(r.ok()) << "cut at " << cut;
    EXPECT_EQ(r.error().rfind("box.glb: ", 0), 0u) << r.error();
    if (cut == 0)  // no byte at all: said so, not taken for a wrong header
      EXPECT_NE(r.error().find("empty file (0 bytes)"), std::string::npos) << r.error();
    else
      EXPECT_TRUE(r.error().find("truncated") != std::string::npos || r.error().find("magic") != std::string::npos)
          << "cut at " << cut << ": " << r.error();
  }
}

TEST(SceneMalformed, BadMagicAndBrokenJson) {
  auto glb = triangle().glb();
  glb[0] = 'x';
  expectError(mb::loadGltfMemory(glb, "box.glb"), "box.glb", "bad GLB magic");
  auto json = triangle().gltf();
  json.resize(json.size() / 2);
  expectError(mb::loadGltfMemory(json, "box.gltf"), "box.gltf", "invalid JSON");
  std::string notObject = "[1, 2, 3]";
  expectError(mb::loadGltfMemory({notObject.begin(), notObject.end()}, "arr.gltf"), "arr.gltf", "not an object");
  auto version = triangle().glb();
  version[4] = 1;
  expectError(mb::loadGltfMemory(version, "v1.glb"), "v1.glb", "GLB version 1");
}

TEST(SceneMalformed, AccessorAndIndexOutOfRange) {
  auto g = triangle();
  g.doc["accessors"][0]["count"] = 4;
  expectError(mb::loadGltfMemory(g.glb(), "box.glb"), "box.glb", "accessor 0 (POSITION) reads past bufferView 0");

  g = triangle();
  g.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 7;
  expectError(mb::loadGltfMemory(g.glb(), "box.glb"), "box.glb", "accessor 7 (POSITION) does not exist");

  g = triangle();
  g.bin[36 + 2] = 9;  // second index -> 9
  expectError(mb::loadGltfMemory(g.glb(), "box.glb"), "box.glb", "index 9 out of range (3 vertices)");

  g = triangle();
  g.doc["bufferViews"][0]["byteLength"] = 4000;
  expectError(mb::loadGltfMemory(g.glb(), "box.glb"), "box.glb", "bufferView 0 (byteOffset 0, byteLength 4000) exceeds buffer 0");

  g = triangle();
  g.doc["accessors"][0]["count"] = 4000000000u;  // huge count: refused before allocating
  expectError(mb::loadGltfMemory(g.glb(), "huge.glb"), "huge.glb", "implausibly large");

  g = triangle();
  g.doc["accessors"][0]["bufferView"] = 5;
  expectError(mb::loadGltfMemory(g.glb(), "box.glb"), "box.glb", "missing bufferView 5");

  g = triangle();
  g.doc["nodes"][0]["children"] = {0};
  expectError(mb::loadGltfMemory(g.glb(), "cycle.glb"), "cycle.glb", "more than one parent");
}

TEST(SceneMalformed, MissingExternalBuffer) {
  fs::path dir = fs::temp_directory_path() / ("mb_scene_malformed_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  auto g = triangle();
  nlohmann::json d = g.doc;
  d["buffers"] = {{{"byteLength", g.bin.size()}, {"uri", "missing.bin"}}};
  fs::path file = dir / "external.gltf";
  std::ofstream(file) << d.dump();
  auto r = mb::loadGltfFile(file.string());
  expectError(r, file.string(), "missing.bin");
  // With the buffer present it loads.
  std::ofstream(dir / "missing.bin", std::ios::binary).write(reinterpret_cast<const char*>(g.bin.data()),
                                                              std::streamsize(g.bin.size()));
  EXPECT_TRUE(mb::loadGltfFile(file.string()).ok());
  // From memory without a base directory, external files are refused, not read from the cwd.
  std::string text = d.dump();
  expectError(mb::loadGltfMemory({text.begin(), text.end()}, "mem.gltf"), "mem.gltf", "missing.bin");
  fs::remove_all(dir);
  expectError(mb::loadGltfFile((dir / "nothing.glb").string()), (dir / "nothing.glb").string(), "no such file");
}
