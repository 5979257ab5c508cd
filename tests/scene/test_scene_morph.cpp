// Morph targets in the loader: POSITION / NORMAL / TANGENT deltas (dense and sparse), the
// mesh's default weights, node weights, and animated weights with LINEAR, STEP and CUBICSPLINE
// sampled at hand-derived values; deltas follow vertices through the loader's splits; bad
// counts fail with a message; inspect's counts.
#include <gtest/gtest.h>

#include "pipelines/scene/animation.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"
#include "tests/support/scene_test_gltf.h"

using mbtest::TestGltf;

namespace {

constexpr int kUShort = 5123, kFloat = 5126;

int floats(TestGltf& g, const std::vector<float>& v, const char* type, size_t count) {
  return g.accessor(g.viewOf(v), kFloat, count, type);
}

// A triangle (0,0,0) (1,0,0) (0,1,0) with normal +z and two targets: target 0 dense POSITION
// (0,0,i+1) and NORMAL (0.5,0,0) deltas, target 1 a sparse POSITION (no bufferView: zeros) whose
// one entry moves vertex 2 by (1,1,1). Mesh weights (0.25, 0.5); node weights when given.
TestGltf morphTriangle(const std::vector<float>& nodeWeights = {}) {
  TestGltf g;
  int pos = floats(g, {0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
  int nrm = floats(g, {0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
  int d0 = floats(g, {0, 0, 1, 0, 0, 2, 0, 0, 3}, "VEC3", 3);
  int n0 = floats(g, {0.5f, 0, 0, 0.5f, 0, 0, 0.5f, 0, 0}, "VEC3", 3);
  int d1 = g.accessor(-1, kFloat, 3, "VEC3");
  int sparseIdx = g.viewOf(std::vector<uint16_t>{2, 0});  // padded to 4 bytes
  int sparseVal = g.viewOf(std::vector<float>{1, 1, 1});
  g.doc["accessors"][size_t(d1)]["sparse"] = {{"count", 1},
                                              {"indices", {{"bufferView", sparseIdx}, {"componentType", kUShort}}},
                                              {"values", {{"bufferView", sparseVal}}}};
  g.meshPrimitive({{"POSITION", pos}, {"NORMAL", nrm}});
  g.doc["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", d0}, {"NORMAL", n0}}, {{"POSITION", d1}}};
  g.doc["meshes"][0]["weights"] = {0.25, 0.5};
  if (!nodeWeights.empty()) g.doc["nodes"][0]["weights"] = nodeWeights;
  return g;
}

// Adds an animation driving node 0's two weights with `interpolation` over `times`, `values`
// packed as glTF stores them (per key: 2 weights; CUBICSPLINE: in-tangents, values, out-tangents).
void addWeightsAnimation(TestGltf& g, const char* interpolation, const std::vector<float>& times,
                         const std::vector<float>& values) {
  int in = floats(g, times, "SCALAR", times.size());
  int out = floats(g, values, "SCALAR", values.size());
  g.doc["animations"].push_back({{"samplers", {{{"input", in}, {"output", out}, {"interpolation", interpolation}}}},
                                 {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "weights"}}}}}}});
}

mb::Result<mb::Scene> load(const TestGltf& g) { return mb::loadGltfMemory(g.gltf(), "morph.gltf", ""); }

std::vector<float> weightsAt(const mb::Scene& s, int anim, float t) {
  std::vector<std::vector<float>> w;
  mb::sampleMorphWeights(s, anim, t, w);
  return w.at(0);
}

}  // namespace

TEST(SceneMorph, DenseAndSparseDeltasAndMeshWeights) {
  auto s = load(morphTriangle());
  ASSERT_TRUE(s.ok()) << s.error();
  const mb::Primitive& p = s->meshes[0].primitives[0];
  ASSERT_EQ(p.targets.size(), 2u);
  EXPECT_EQ(p.targets[0].positions, (std::vector<glm::vec3>{{0, 0, 1}, {0, 0, 2}, {0, 0, 3}}));
  EXPECT_EQ(p.targets[0].normals, (std::vector<glm::vec3>(3, glm::vec3(0.5f, 0, 0))));
  EXPECT_TRUE(p.targets[0].tangents.empty());
  EXPECT_EQ(p.targets[1].positions, (std::vector<glm::vec3>{{0, 0, 0}, {0, 0, 0}, {1, 1, 1}}));
  EXPECT_TRUE(p.targets[1].normals.empty());
  EXPECT_EQ(s->meshes[0].weights, (std::vector<float>{0.25f, 0.5f}));
  EXPECT_EQ(weightsAt(*s, -1, 0.0f), (std::vector<float>{0.25f, 0.5f}));  // rest: the mesh's
  for (const std::string& u : s->unsupported) EXPECT_EQ(u.find("morph"), std::string::npos) << u;
}

TEST(SceneMorph, NodeWeightsOverrideTheMesh) {
  auto s = load(morphTriangle({1.0f, 0.0f}));
  ASSERT_TRUE(s.ok()) << s.error();
  EXPECT_EQ(weightsAt(*s, -1, 0.0f), (std::vector<float>{1.0f, 0.0f}));
  auto bad = load(morphTriangle({1.0f}));  // one weight for two targets: listed, mesh's used
  ASSERT_TRUE(bad.ok()) << bad.error();
  EXPECT_EQ(weightsAt(*bad, -1, 0.0f), (std::vector<float>{0.25f, 0.5f}));
  ASSERT_FALSE(bad->unsupported.empty());
  EXPECT_NE(bad->unsupported.back().find("1 morph weights for 2 targets"), std::string::npos);
}

TEST(SceneMorph, AnimatedWeightsLinearStepCubic) {
  TestGltf g = morphTriangle();
  addWeightsAnimation(g, "LINEAR", {0, 2}, {0, 1, 1, 0});
  addWeightsAnimation(g, "STEP", {0, 1}, {0.2f, 0.4f, 0.6f, 0.8f});
  // Keys at 0 and 1: v0 (0, 1) with out-tangent (2, 0); v1 (1, 0) with in-tangent (0, -3).
  addWeightsAnimation(g, "CUBICSPLINE", {0, 1}, {9, 9, 0, 1, 2, 0, /**/ 0, -3, 1, 0, 9, 9});
  auto s = load(g);
  ASSERT_TRUE(s.ok()) << s.error();
  ASSERT_EQ(s->animations.size(), 3u);
  EXPECT_EQ(s->animations[0].channels.at(0).path, mb::AnimPath::Weights);
  EXPECT_EQ(weightsAt(*s, 0, 0.5f), (std::vector<float>{0.25f, 0.75f}));  // u = 1/4
  EXPECT_EQ(weightsAt(*s, 0, 5.0f), (std::vector<float>{1.0f, 0.0f}));    // clamped to the last key
  EXPECT_EQ(weightsAt(*s, 1, 0.99f), (std::vector<float>{0.2f, 0.4f}));
  EXPECT_EQ(weightsAt(*s, 1, 1.0f), (std::vector<float>{0.6f, 0.8f}));
  // u = 1/2: h00 = 1/2, h10 = 1/8, h01 = 1/2, h11 = -1/8 (dt = 1).
  // w0 = 0 + 2/8 + 1/2 + 0 = 0.75; w1 = 1/2 + 0 + 0 + 3/8 = 0.875.
  std::vector<float> c = weightsAt(*s, 2, 0.5f);
  EXPECT_FLOAT_EQ(c[0], 0.75f);
  EXPECT_FLOAT_EQ(c[1], 0.875f);
  // A weights channel moves no node: the TRS pose stays the rest pose.
  EXPECT_TRUE(mb::animatedNodes(*s)[0].empty());
  // Blending two animations mixes their weights linearly.
  mb::AnimState st{0, 0.5f, 1, 1.0f, 0.5f};
  auto blended = mb::sampleMorphWeights(*s, st)[0];
  EXPECT_FLOAT_EQ(blended[0], 0.5f * 0.25f + 0.5f * 0.6f);
  EXPECT_FLOAT_EQ(blended[1], 0.5f * 0.75f + 0.5f * 0.8f);
  mb::FileStats f = mb::computeFileStats(*s);
  EXPECT_EQ(f.morphTargets, 2);
  EXPECT_EQ(f.morphMeshes, 1);
  EXPECT_EQ(f.weightsChannels, 3);
}

TEST(SceneMorph, DeltasFollowUnweldedVertices) {
  // Two triangles sharing an edge, no NORMAL: flat normals unweld the 4 vertices into 6
  // corners; the target's delta on vertex 3 must reach both corners that were vertex 3.
  TestGltf g;
  int pos = floats(g, {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, "VEC3", 4);
  int d = floats(g, {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 5}, "VEC3", 4);
  int idx = g.accessor(g.viewOf(std::vector<uint16_t>{0, 1, 3, 0, 3, 2}), kUShort, 6, "SCALAR");
  g.meshPrimitive({{"POSITION", pos}}, idx);
  g.doc["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", d}}};
  auto s = load(g);
  ASSERT_TRUE(s.ok()) << s.error();
  const mb::Primitive& p = s->meshes[0].primitives[0];
  ASSERT_EQ(p.positions.size(), 6u);
  ASSERT_EQ(p.targets.at(0).positions.size(), 6u);
  for (size_t v = 0; v < 6; ++v)
    EXPECT_EQ(p.targets[0].positions[v].z, p.positions[v] == glm::vec3(1, 1, 0) ? 5.0f : 0.0f) << v;
  EXPECT_EQ(s->meshes[0].weights, (std::vector<float>{0.0f}));  // not authored: zeros
}

TEST(SceneMorph, BadCountsFailWithTheReason) {
  TestGltf shortDelta = morphTriangle();
  shortDelta.doc["accessors"][2]["count"] = 2;
  auto a = load(shortDelta);
  ASSERT_FALSE(a.ok());
  EXPECT_NE(a.error().find("POSITION delta accessor 2 has 2 elements, POSITION has 3"), std::string::npos) << a.error();
  TestGltf weights = morphTriangle();
  weights.doc["meshes"][0]["weights"] = {0.5};
  auto b = load(weights);
  ASSERT_FALSE(b.ok());
  EXPECT_NE(b.error().find("1 weights for 2 morph targets"), std::string::npos) << b.error();
  TestGltf keys = morphTriangle();
  addWeightsAnimation(keys, "LINEAR", {0, 1}, {0, 1, 1});  // 3 values for 2 keys x 2 targets
  auto c = load(keys);
  ASSERT_FALSE(c.ok());
  EXPECT_NE(c.error().find("not a multiple of 2 targets"), std::string::npos) << c.error();
}
