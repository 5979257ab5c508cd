// Vertex hygiene: skin-weight renormalisation and reduction, normal/position/tangent
// fallbacks, and generated tangents against the analytic tangents of the built-in torus.
#include <gtest/gtest.h>

#include <cmath>

#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/repair/hygiene.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/repair/skin_weights.h"
#include "pipelines/scene/repair/tangents.h"
#include "tests/support/scene_test_gltf.h"

namespace {

mb::InfluenceReport reduce(std::vector<uint32_t> j, std::vector<float> w, glm::u16vec4* oj, glm::vec4* ow,
                           uint32_t jointCount = 100) {
  mb::InfluenceReport r;
  mb::reduceInfluences(j.data(), w.data(), int(j.size()), jointCount, oj, ow, &r);
  return r;
}

mb::Primitive builtinPrimitive(const std::string& name) {
  auto s = mb::loadScene(name);
  EXPECT_TRUE(s.ok()) << s.error();
  return s ? s->meshes[0].primitives[0] : mb::Primitive{};
}

}  // namespace

TEST(SceneHygiene, WeightsAreL1Renormalised) {
  glm::u16vec4 j;
  glm::vec4 w;
  auto r = reduce({3, 5, 0, 0}, {0.2f, 0.6f, 0, 0}, &j, &w);
  EXPECT_TRUE(r.renormalised);
  EXPECT_FALSE(r.truncated);
  EXPECT_EQ(j, glm::u16vec4(5, 3, 0, 0));  // largest first
  EXPECT_FLOAT_EQ(w.x, 0.75f);
  EXPECT_FLOAT_EQ(w.y, 0.25f);
  EXPECT_FLOAT_EQ(w.x + w.y + w.z + w.w, 1.0f);
  r = reduce({1, 2, 0, 0}, {0.5f, 0.5f, 0, 0}, &j, &w);
  EXPECT_FALSE(r.renormalised);  // already summed to 1
}

TEST(SceneHygiene, MoreThanFourInfluencesKeepTheLargest) {
  glm::u16vec4 j;
  glm::vec4 w;
  auto r = reduce({0, 1, 2, 3, 4, 5, 6, 7}, {0.05f, 0.3f, 0.05f, 0.2f, 0.1f, 0.1f, 0.15f, 0.05f}, &j, &w);
  EXPECT_TRUE(r.truncated);
  EXPECT_EQ(j, glm::u16vec4(1, 3, 6, 4));  // 0.3, 0.2, 0.15, then the first 0.1 (authored order)
  EXPECT_NEAR(w.x, 0.3f / 0.75f, 1e-6f);
  EXPECT_NEAR(w.w, 0.1f / 0.75f, 1e-6f);
  EXPECT_NEAR(w.x + w.y + w.z + w.w, 1.0f, 1e-6f);
}

TEST(SceneHygiene, ZeroSumAndInvalidWeightsFallBack) {
  glm::u16vec4 j;
  glm::vec4 w;
  auto r = reduce({4, 5, 6, 7}, {0, 0, 0, 0}, &j, &w);
  EXPECT_TRUE(r.zeroSum);
  EXPECT_EQ(j, glm::u16vec4(0));
  EXPECT_EQ(w, glm::vec4(1, 0, 0, 0));
  r = reduce({1, 2, 9, 0}, {NAN, -1.0f, 0.5f, 0}, &j, &w, 5);  // NaN/negative dropped, joint 9 >= 5
  EXPECT_TRUE(r.zeroSum);
  EXPECT_EQ(r.jointsOutOfRange, 1);
}

TEST(SceneHygiene, LoaderMergesJointsSetsAndCounts) {
  // One triangle, two influence sets (8 influences), weights summing to 2.
  mbtest::TestGltf g;
  int pos = g.accessor(g.viewOf(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}), 5126, 3, "VEC3");
  g.doc["accessors"][size_t(pos)]["min"] = {0, 0, 0};
  g.doc["accessors"][size_t(pos)]["max"] = {1, 1, 0};
  std::vector<uint8_t> j0(12), j1(12);
  std::vector<float> w0, w1;
  for (int v = 0; v < 3; ++v)
    for (int c = 0; c < 4; ++c) {
      j0[size_t(4 * v + c)] = uint8_t(c);
      j1[size_t(4 * v + c)] = uint8_t(4 + c);
      w0.push_back(0.1f * float(c + 1));  // 0.1 0.2 0.3 0.4
      w1.push_back(c == 0 ? 1.0f : 0.0f);
    }
  int aj0 = g.accessor(g.viewOf(j0), 5121, 3, "VEC4"), aj1 = g.accessor(g.viewOf(j1), 5121, 3, "VEC4");
  int aw0 = g.accessor(g.viewOf(w0), 5126, 3, "VEC4"), aw1 = g.accessor(g.viewOf(w1), 5126, 3, "VEC4");
  g.meshPrimitive({{"POSITION", pos}, {"JOINTS_0", aj0}, {"JOINTS_1", aj1}, {"WEIGHTS_0", aw0}, {"WEIGHTS_1", aw1}});
  g.doc["nodes"][0]["skin"] = 0;
  g.doc["nodes"].push_back(nlohmann::json::object());
  g.doc["skins"] = {{{"joints", {1, 1, 1, 1, 1, 1, 1, 1}}}};
  auto s = mb::loadGltfMemory(g.gltf(), "skin.gltf");
  ASSERT_TRUE(s.ok()) << s.error();
  const auto& p = s->meshes[0].primitives[0];
  ASSERT_EQ(p.joints.size(), 3u);
  EXPECT_EQ(p.joints[0], glm::u16vec4(4, 3, 2, 1));
  EXPECT_NEAR(p.weights[0].x, 1.0f / 1.9f, 1e-6f);
  EXPECT_NEAR(p.weights[0].w, 0.2f / 1.9f, 1e-6f);
  EXPECT_EQ(s->stats.weightsRenormalised, 3);
  EXPECT_EQ(s->stats.influencesTruncated, 3);  // 5 non-zero influences per vertex
}

TEST(SceneHygiene, NormalAndPositionFallbacks) {
  mb::Primitive p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {NAN, 0, 0}};
  p.normals = {{0, 0, 0}, {0, 0, 2}, {NAN, 0, 1}, {0, 0, 1}};
  p.indices = {0, 1, 2};
  mb::LoadStats st;
  EXPECT_EQ(mb::fixPositions(p.positions), 1);
  EXPECT_EQ(p.positions[3], glm::vec3(0));
  mb::fixNormals(p, st);
  EXPECT_EQ(st.badNormalsReplaced, 2);
  EXPECT_EQ(st.normalsRenormalised, 1);
  EXPECT_EQ(p.normals[0], glm::vec3(0, 0, 1));  // face normal
  EXPECT_EQ(p.normals[1], glm::vec3(0, 0, 1));
  EXPECT_EQ(p.normals[2], glm::vec3(0, 0, 1));
  p.tangents = {{0, 0, 0, 1}, {0, 0, 1, 1}, {2, 0, 0.5f, 0}, {1, 0, 0, -3}};
  mb::fixTangents(p, st);
  EXPECT_EQ(st.badTangentsReplaced, 3);  // zero, parallel to n, w = 0
  EXPECT_EQ(p.tangents[2], glm::vec4(1, 0, 0, 1));  // orthogonalised, w +1
  EXPECT_EQ(p.tangents[3], glm::vec4(1, 0, 0, -1));
  for (const auto& t : p.tangents) EXPECT_NEAR(glm::dot(glm::vec3(t), glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
}

TEST(SceneHygiene, GeneratedTangentsMatchAnalyticTorus) {
  mb::Primitive analytic = builtinPrimitive("normal_torus");
  ASSERT_TRUE(analytic.hadTangents);
  int mirrored = 0;
  for (const auto& t : analytic.tangents) mirrored += t.w < 0;
  EXPECT_EQ(mirrored * 2, int(analytic.tangents.size()));  // half the torus has w = -1

  mb::Primitive gen = analytic;
  gen.tangents.clear();
  mb::LoadStats st;
  mb::generateTangents(gen, 0, st);
  EXPECT_EQ(st.degenerateUvTriangles, 0);
  ASSERT_EQ(gen.indices.size(), analytic.indices.size());
  float worst = 1.0f;
  for (size_t c = 0; c < gen.indices.size(); ++c) {  // compare per triangle corner
    const glm::vec4& a = analytic.tangents[analytic.indices[c]];
    const glm::vec4& g = gen.tangents[gen.indices[c]];
    ASSERT_EQ(a.w, g.w) << "corner " << c;
    worst = std::min(worst, glm::dot(glm::vec3(a), glm::vec3(g)));
    EXPECT_NEAR(glm::dot(glm::vec3(g), gen.normals[gen.indices[c]]), 0.0f, 1e-5f);
  }
  EXPECT_GT(worst, 0.998f);  // within ~3.6 degrees (one-sided differences at the uv seams)
}

TEST(SceneHygiene, GeneratedTangentsMatchBoxFramesExactly) {
  mb::Primitive analytic = builtinPrimitive("textured_box");
  mb::Primitive gen = analytic;
  gen.tangents.clear();
  mb::LoadStats st;
  mb::generateTangents(gen, 0, st);
  EXPECT_EQ(st.tangentSplitVertices, 0);
  for (size_t v = 0; v < gen.tangents.size(); ++v) {
    EXPECT_NEAR(glm::distance(gen.tangents[v], analytic.tangents[v]), 0.0f, 1e-5f) << v;
  }
}

TEST(SceneHygiene, LoaderGeneratesTangentsForNormalMapsWithoutTangent) {
  // Two triangles sharing an edge with mirrored u: the shared vertices must be split.
  mbtest::TestGltf g;
  int pos = g.accessor(g.viewOf(std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0, 2, 0, 0}), 5126, 4, "VEC3");
  g.doc["accessors"][size_t(pos)]["min"] = {0, 0, 0};
  g.doc["accessors"][size_t(pos)]["max"] = {2, 1, 0};
  int uv = g.accessor(g.viewOf(std::vector<float>{0, 0, 1, 0, 1, 1, 0, 0}), 5126, 4, "VEC2");
  int nrm = g.accessor(g.viewOf(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}), 5126, 4, "VEC3");
  int idx = g.accessor(g.viewOf(std::vector<uint16_t>{0, 1, 2, 1, 3, 2}), 5123, 6, "SCALAR");
  g.meshPrimitive({{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}}, idx);
  g.doc["meshes"][0]["primitives"][0]["material"] = 0;
  g.doc["materials"] = {{{"normalTexture", {{"index", 0}}}}};
  g.doc["textures"] = {{{"source", 0}}};
  g.doc["images"] = {{{"uri", "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8/5+hHgAHggJ/PchI7wAAAABJRU5ErkJggg=="}}};
  auto s = mb::loadGltfMemory(g.gltf(), "mirror.gltf");
  ASSERT_TRUE(s.ok()) << s.error();
  const auto& p = s->meshes[0].primitives[0];
  EXPECT_TRUE(p.generatedTangents);
  EXPECT_EQ(s->stats.tangentsGenerated, 1);
  EXPECT_EQ(s->stats.tangentSplitVertices, 2);  // vertices 1 and 2 are used by both sides
  EXPECT_EQ(p.positions.size(), 6u);
  EXPECT_EQ(p.tangents[p.indices[0]], glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(p.tangents[p.indices[4]], glm::vec4(-1, 0, 0, -1));  // u decreases along +x
}
