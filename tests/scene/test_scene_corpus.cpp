// Every glTF file of ../shared/corpus loads, or fails with a message naming file and reason.
#include <gtest/gtest.h>

#include <filesystem>

#include "pipelines/scene/loader.h"
#include "pipelines/scene/scale_analysis.h"

namespace fs = std::filesystem;

namespace {

fs::path corpusDir() { return fs::path(MB_SOURCE_DIR) / ".." / "shared" / "corpus"; }

const mb::Scene* find(const std::string& file, mb::Scene* storage) {
  auto r = mb::loadGltfFile((corpusDir() / file).string());
  if (!r) return nullptr;
  *storage = r.take();
  return storage;
}

size_t vertexCount(const mb::Scene& s) {
  size_t n = 0;
  for (const auto& m : s.meshes)
    for (const auto& p : m.primitives) n += p.positions.size();
  return n;
}

}  // namespace

TEST(SceneCorpus, EveryFileLoadsOrFailsWithReason) {
  if (!fs::is_directory(corpusDir())) GTEST_SKIP() << "no corpus at " << corpusDir();
  int files = 0;
  for (const auto& e : fs::directory_iterator(corpusDir())) {
    std::string ext = e.path().extension().string();
    if (ext != ".gltf" && ext != ".glb") continue;
    ++files;
    auto r = mb::loadGltfFile(e.path().string());
    if (!r) {
      EXPECT_NE(r.error().find(e.path().filename().string()), std::string::npos) << r.error();
      EXPECT_GT(r.error().size(), e.path().string().size() + 4) << r.error();
      continue;
    }
    EXPECT_FALSE(r->meshes.empty()) << e.path();
    for (const auto& m : r->meshes)
      for (const auto& p : m.primitives) {
        EXPECT_EQ(p.normals.size(), p.positions.size());
        EXPECT_EQ(p.indices.size() % 3, 0u);
        for (uint32_t i : p.indices) ASSERT_LT(i, p.positions.size());
      }
  }
  EXPECT_GT(files, 0);
}

TEST(SceneCorpus, ManifestFacts) {
  if (!fs::is_directory(corpusDir())) GTEST_SKIP() << "no corpus";
  mb::Scene s;
  if (find("RiggedSimple.gltf", &s)) {
    ASSERT_EQ(s.skins.size(), 1u);
    EXPECT_EQ(s.skins[0].joints.size(), 2u);
    EXPECT_EQ(vertexCount(s), 160u);
    EXPECT_EQ(s.animations.size(), 1u);
  } else {
    ADD_FAILURE() << "RiggedSimple.gltf did not load";
  }
  if (find("barrel.glb", &s)) {
    ASSERT_EQ(s.meshes.size(), 1u);
    const auto& p = s.meshes[0].primitives[0];
    EXPECT_TRUE(p.hadTangents);
    EXPECT_EQ(p.positions.size(), 856u);
    ASSERT_GE(p.material, 0);
    EXPECT_GE(s.materials[size_t(p.material)].normal.texture, 0);
    EXPECT_EQ(s.images.size(), 3u);
    for (const auto& img : s.images) EXPECT_EQ(img.rgba.size(), size_t(img.width) * img.height * 4);
  } else {
    ADD_FAILURE() << "barrel.glb did not load";
  }
  if (find("stip.glb", &s)) {
    mb::ScaleReport rep = mb::analyzeScale(s);
    EXPECT_TRUE(rep.animatedScale);
    EXPECT_TRUE(rep.animatedNonUniformScale);
    bool armL = false;
    for (size_t i = 0; i < s.nodes.size(); ++i)
      if (s.nodes[i].name == "Arm_L") armL = rep.nodes[i].restClass == mb::ScaleClass::NonUniform;
    EXPECT_TRUE(armL);
    EXPECT_EQ(s.meshes.size(), 20u);
    size_t joints = 0;
    for (const auto& sk : s.skins) joints += sk.joints.size();
    EXPECT_EQ(joints, 23u);
  } else {
    ADD_FAILURE() << "stip.glb did not load";
  }
  if (find("Box.gltf", &s)) {
    EXPECT_EQ(vertexCount(s), 24u);
  }
  if (find("AnimatedTriangle.gltf", &s)) {
    EXPECT_EQ(s.stats.flatNormalsGenerated, 1);  // no NORMAL in the file
    EXPECT_EQ(s.animations.size(), 1u);
  }
}
