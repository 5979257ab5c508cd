// Built-in scenes round-trip: generated, written as .glb, loaded back through the file
// loader, and their statistics match what the generator put in; bytes are deterministic.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "pipelines/scene/animation.h"
#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scale_analysis.h"
#include "pipelines/scene/scene_stats.h"
#include "pipelines/scene/transform.h"

namespace fs = std::filesystem;

namespace {

mb::Scene writeAndLoad(const std::string& name) {
  auto glb = mb::builtinSceneGlb(name);
  EXPECT_TRUE(glb.ok()) << glb.error();
  // One folder per process: ctest runs these tests in parallel processes.
  fs::path dir = fs::temp_directory_path() / ("mb_scene_builtin_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  fs::path file = dir / (name + ".glb");
  std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(glb->data()), std::streamsize(glb->size()));
  auto s = mb::loadGltfFile(file.string());
  EXPECT_TRUE(s.ok()) << s.error();
  return s ? s.take() : mb::Scene{};
}

glm::mat4 world(const mb::Scene& s, const std::vector<mb::TRS>& pose, int node) {
  glm::mat4 m(1.0f);
  for (int n = node; n >= 0; n = s.nodes[size_t(n)].parent) m = mb::trsMatrix(pose[size_t(n)]) * m;
  return m;
}

}  // namespace

TEST(SceneBuiltin, NamesAreStable) {
  EXPECT_EQ(mb::builtinSceneNames(),
            (std::vector<std::string>{"normal_torus", "textured_box", "skinned_tube", "scaled_hierarchy", "crowd",
                                      "dense_torus", "teapot", "instanced_grid"}));
  EXPECT_TRUE(mb::isBuiltinScene("crowd"));
  EXPECT_FALSE(mb::isBuiltinScene("crowd.glb"));
  EXPECT_FALSE(mb::builtinSceneGlb("nope").ok());
}

TEST(SceneBuiltin, RoundTripStatisticsMatchGenerator) {
  for (const auto& name : mb::builtinSceneNames()) {
    SCOPED_TRACE(name);
    auto a = mb::builtinSceneGlb(name), b = mb::builtinSceneGlb(name);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(*a, *b) << "bytes not deterministic";
    auto facts = mb::builtinSceneFacts(name);
    ASSERT_TRUE(facts.ok());
    mb::Scene s = writeAndLoad(name);
    mb::FileStats f = mb::computeFileStats(s);
    EXPECT_EQ(f.meshes, facts->meshes);
    EXPECT_EQ(f.primitives, facts->primitives);
    EXPECT_EQ(f.vertices, facts->vertices);
    EXPECT_EQ(f.triangles, facts->triangles);
    EXPECT_EQ(f.materials, facts->materials);
    EXPECT_EQ(f.images, facts->images);
    EXPECT_EQ(f.nodes, facts->nodes);
    EXPECT_EQ(f.skins, facts->skins);
    EXPECT_EQ(f.joints, facts->joints);
    EXPECT_EQ(f.animations, facts->animations);
    EXPECT_EQ(f.channels, facts->channels);
    EXPECT_EQ(f.normalMappedPrimitives, facts->normalMappedPrimitives);
    EXPECT_TRUE(s.unsupported.empty());
    EXPECT_EQ(mb::toJson(s.stats), mb::toJson(mb::LoadStats{})) << "no fallback needed";
    for (const auto& img : s.images) EXPECT_EQ(img.rgba.size(), size_t(img.width) * size_t(img.height) * 4);
  }
}

TEST(SceneBuiltin, InstancedGridHas256InstancesWithOneStretchedAndOneMirrored) {
  mb::Scene s = writeAndLoad("instanced_grid");
  int instanced = -1;
  for (size_t n = 0; n < s.nodes.size(); ++n)
    if (!s.nodes[n].instances.empty()) instanced = int(n);
  ASSERT_GE(instanced, 0);
  const auto& in = s.nodes[size_t(instanced)].instances;
  ASSERT_EQ(in.size(), 256u);
  EXPECT_EQ(s.nodes[size_t(instanced)].mesh, 0);
  EXPECT_EQ(in[17].scale, glm::vec3(1.3f, 0.5f, 0.8f));
  EXPECT_EQ(in[40].scale, glm::vec3(-0.8f, 0.8f, 0.8f));
  int uniform = 0;
  for (const auto& t : in) uniform += t.scale.x == t.scale.y && t.scale.y == t.scale.z && t.scale.x > 0.0f;
  EXPECT_EQ(uniform, 254);
  // Grid spacing 2.5 along x and z: instance 1 is one step from instance 0.
  EXPECT_NEAR(glm::length(in[1].translation - in[0].translation), 2.5f, 1e-6f);
  EXPECT_EQ(mb::computeFileStats(s).drawnVertices, 256 * 24);
}

TEST(SceneBuiltin, TorusHasMirroredHalf) {
  mb::Scene s = writeAndLoad("normal_torus");
  const auto& p = s.meshes[0].primitives[0];
  int neg = 0;
  for (const auto& t : p.tangents) neg += t.w < 0.0f;
  EXPECT_EQ(2 * neg, int(p.tangents.size()));
  EXPECT_GE(s.materials[0].normal.texture, 0);
}

TEST(SceneBuiltin, BoxFramesAreAxisAlignedWithTwoHalfTurns) {
  mb::Scene s = writeAndLoad("textured_box");
  const auto& p = s.meshes[0].primitives[0];
  ASSERT_EQ(p.positions.size(), 24u);
  int halfTurns = 0;
  for (size_t v = 0; v < 24; v += 4) {
    glm::vec3 t(p.tangents[v]), n = p.normals[v], b = glm::cross(n, t) * p.tangents[v].w;
    for (const glm::vec3& axis : {t, b, n}) EXPECT_NEAR(std::fabs(axis.x) + std::fabs(axis.y) + std::fabs(axis.z), 1.0f, 1e-6f);
    float trace = t.x + b.y + n.z;  // rotation by 180 degrees <=> trace -1 (rotor scalar part 0)
    halfTurns += std::fabs(trace + 1.0f) < 1e-6f;
  }
  EXPECT_EQ(halfTurns, 2);
  EXPECT_GE(s.materials[0].baseColor.texture, 0);
}

TEST(SceneBuiltin, TubeAnimationsBendAndTwist) {
  mb::Scene s = writeAndLoad("skinned_tube");
  ASSERT_EQ(s.animations.size(), 3u);
  EXPECT_EQ(s.animations[0].name, "bend");
  EXPECT_EQ(s.animations[1].name, "twist");
  EXPECT_EQ(s.animations[2].name, "candy_wrapper");
  ASSERT_EQ(s.skins.size(), 1u);
  const auto& joints = s.skins[0].joints;
  ASSERT_GE(joints.size(), 4u);
  for (size_t j = 1; j < joints.size(); ++j) EXPECT_EQ(s.nodes[size_t(joints[j])].parent, joints[j - 1]);  // a chain
  auto pose = mb::sampleAnimation(s, 1, s.animations[1].duration);
  glm::mat4 base = world(s, pose, joints.front()), tip = world(s, pose, joints.back());
  glm::vec3 x = glm::mat3(glm::inverse(base) * tip) * glm::vec3(1, 0, 0);
  EXPECT_NEAR(x.x, -1.0f, 1e-5f);  // tip turned 180 degrees about the tube axis (Y)
  glm::vec3 axis = glm::mat3(glm::inverse(base) * tip) * glm::vec3(0, 1, 0);
  EXPECT_NEAR(axis.y, 1.0f, 1e-5f);
  const auto& w = s.meshes[0].primitives[0].weights;
  for (const auto& v : w) EXPECT_NEAR(v.x + v.y + v.z + v.w, 1.0f, 1e-6f);

  // candy_wrapper: only the middle joint turns, by 180 degrees about Y relative to its parent.
  auto wrap = mb::sampleAnimation(s, 2, s.animations[2].duration);
  size_t mid = joints.size() / 2;
  glm::mat3 rel = glm::mat3(glm::inverse(world(s, wrap, joints[mid - 1])) * world(s, wrap, joints[mid]));
  EXPECT_NEAR((rel * glm::vec3(1, 0, 0)).x, -1.0f, 1e-5f);
  EXPECT_NEAR((rel * glm::vec3(0, 1, 0)).y, 1.0f, 1e-5f);
  for (size_t j = 1; j < joints.size(); ++j) {
    if (j == mid) continue;
    glm::mat3 r = glm::mat3(glm::inverse(world(s, wrap, joints[j - 1])) * world(s, wrap, joints[j]));
    EXPECT_NEAR((r * glm::vec3(1, 0, 0)).x, 1.0f, 1e-5f) << "joint " << j << " should not turn";
  }
}

TEST(SceneBuiltin, ScaledHierarchyScaleClasses) {
  mb::Scene s = writeAndLoad("scaled_hierarchy");
  mb::ScaleReport r = mb::analyzeScale(s);
  EXPECT_EQ(r.nonUniformNodes, 1);
  EXPECT_EQ(r.negativeNodes, 1);
  EXPECT_GE(r.uniformNodes, 3);
  EXPECT_TRUE(r.nonUniformOnlyOnLeaves);
  EXPECT_TRUE(r.animatedScale);
  EXPECT_FALSE(r.animatedNonUniformScale);
  int scaledUniform = 0;
  for (const auto& n : s.nodes) scaledUniform += n.local.scale.x != 1.0f && !mb::isNonUniform(n.local.scale) && n.local.scale.x > 0;
  EXPECT_GE(scaledUniform, 3);  // uniform scales at several levels
  for (const auto& n : s.nodes) EXPECT_GE(n.mesh, 0) << n.name;  // every node visible
}

TEST(SceneBuiltin, CrowdInstancesOneSkinnedMesh) {
  mb::Scene s = writeAndLoad("crowd");
  int instances = 0;
  for (const auto& n : s.nodes)
    if (n.mesh == 0) {
      ++instances;
      EXPECT_GE(n.skin, 0);
    }
  EXPECT_GE(instances, 256);
  EXPECT_EQ(s.meshes.size(), 1u);
  EXPECT_FALSE(s.meshes[0].primitives[0].joints.empty());
  EXPECT_EQ(s.animations.size(), 1u);
}

// The one similarity tolerance decides "non-uniform" for the motor fast path and the statistics
// alike: neighbouring scale ratios within 1e-4 are uniform (exporter noise), beyond are not.
TEST(SimilarityTolerance, NoiseIsUniformAPercentIsNot) {
  EXPECT_EQ(mb::kSimilarityTolerance, 1e-4);
  EXPECT_FALSE(mb::isNonUniform({1.0f + 1.2e-5f, 1.0f - 0.6e-5f, 1.0f}));  // cow.glb's noise
  EXPECT_FALSE(mb::isNonUniform({2.0f, 2.0f * (1.0f + 9e-5f), 2.0f}));
  EXPECT_TRUE(mb::isNonUniform({2.0f, 2.0f * (1.0f + 1.2e-4f), 2.0f}));
  EXPECT_TRUE(mb::isNonUniform({1.01f, 1.0f, 1.0f}));
  EXPECT_FALSE(mb::isNonUniform({-3.0f, 3.0f, 3.0f}));  // a mirror is uniform in magnitude
  EXPECT_EQ(mb::classifyScale({1.0f, 1.0f + 5e-5f, 1.0f}), mb::ScaleClass::Uniform);
}
