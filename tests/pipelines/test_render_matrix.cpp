// The matrix pipeline under CTest: built-in scenes render (non-empty, bit-identical twice,
// measured stats), and synthetic scenes check texturing, the normal-map TBN convention and
// mirrored nodes.
#include <gtest/gtest.h>

#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"

using namespace mb;

namespace {

constexpr int kSize = 128;

Frame render(const Scene& scene, const AnimState& anim = {}) {
  FrameSettings s;
  s.anim = anim;
  s.width = s.height = kSize;
  auto f = renderFrame(scene, "matrix", s);
  EXPECT_TRUE(f) << f.error();
  return f ? f.take() : Frame{};
}

// Fraction of pixels that are not the background colour.
double coverage(const RgbaImage& img) {
  size_t covered = 0;
  for (size_t p = 0; p < img.rgba.size(); p += 4) {
    bool bg = true;
    for (int c = 0; c < 3; ++c)
      bg = bg && std::abs(int(img.rgba[p + c]) - int(kBackground[c] * 255.0f + 0.5f)) <= 1;
    covered += bg ? 0 : 1;
  }
  return double(covered) / double(img.rgba.size() / 4);
}

// A camera-facing quad (two triangles, z = 0, side 2) with normal (0,0,1), tangent +X.
Primitive quad(glm::vec3 normal = {0, 0, 1}, float handedness = 1.0f) {
  Primitive p;
  p.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  p.normals.assign(4, glm::normalize(normal));
  p.tangents.assign(4, glm::vec4(1, 0, 0, handedness));
  p.uv0 = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  p.indices = {0, 1, 2, 0, 2, 3};
  p.material = 0;
  return p;
}

// One node with `p`, a grey dielectric material, and (optionally) a 1x1 texture of colour
// `texel` used as normal map or base colour.
Scene quadScene(Primitive p, const uint8_t* texel = nullptr, bool asNormalMap = true) {
  Scene s;
  s.source = "synthetic quad";
  Material m;
  m.baseColorFactor = {0.6f, 0.6f, 0.6f, 1.0f};
  m.metallicFactor = 0.0f;
  m.roughnessFactor = 0.5f;
  if (texel) {
    s.images.push_back({"texel", 1, 1, {texel[0], texel[1], texel[2], 255}});
    s.textures.push_back({0, -1});
    (asNormalMap ? m.normal : m.baseColor).texture = 0;
  }
  s.materials.push_back(m);
  s.meshes.push_back({"quad", {std::move(p)}});
  Node n;
  n.mesh = 0;
  s.nodes.push_back(n);
  s.roots = {0};
  return s;
}

int maxDifference(const RgbaImage& a, const RgbaImage& b) {
  auto m = compareImages(a, b);
  EXPECT_TRUE(m);
  return m ? int(std::lround(m->maxError * 255.0)) : 255;
}

}  // namespace

class BuiltinScene : public ::testing::TestWithParam<std::string> {};

TEST_P(BuiltinScene, RendersNonEmptyDeterministicWithMeasuredStats) {
  auto scene = loadScene(GetParam());
  ASSERT_TRUE(scene) << scene.error();
  AnimState anim;
  if (!scene->animations.empty()) {
    anim.anim = 0;
    anim.time = 0.5f * scene->animations[0].duration;
  }
  Frame a = render(*scene, anim), b = render(*scene, anim);
  ASSERT_EQ(a.image.rgba.size(), size_t(kSize * kSize * 4));
  EXPECT_EQ(a.image.rgba, b.image.rgba) << "two renders differ";
  double cov = coverage(a.image);
  EXPECT_GT(cov, 0.02) << "almost nothing drawn";
  EXPECT_LT(cov, 0.98) << "framing lost the background";
  const PipelineStats& s = a.stats;
  const FileStats f = computeFileStats(*scene);
  if (f.patches > 0) {
    // Bezier patches: one refinement pattern of uv pairs (level N: (N+1)^2), drawn instanced
    // per patch, is not a vertex format (patchPatternBytes, not vertices); the control points go
    // to a buffer texture (16 x vec3 per patch). The teapot has no other primitive.
    const uint64_t n = uint64_t(scene->patchLevel) + 1;
    EXPECT_EQ(s.patchPatternBytes, n * n * 8);
    EXPECT_EQ(s.vertices, 0u);
    EXPECT_EQ(s.vertexBytes, 0u);
    EXPECT_EQ(s.patchBytes, uint64_t(f.patches) * 16 * 12);
  } else {
    EXPECT_DOUBLE_EQ(s.floatsPerVertex, 12.0);
    EXPECT_EQ(s.vertexBytes, s.vertices * 48);
    EXPECT_EQ(s.patchBytes, 0u);
  }
  if (f.instancedNodes == f.meshNodes && f.instances > 0) {
    // Every node instanced (instanced_grid): no per-draw transform; the same two mat4 (32
    // floats) per instance instead.
    EXPECT_DOUBLE_EQ(s.floatsPerTransform, 0.0);
    EXPECT_EQ(s.instances, uint64_t(f.instances));
    EXPECT_EQ(s.instanceBytes, s.instances * 32 * 4);
  } else {
    EXPECT_DOUBLE_EQ(s.floatsPerTransform, 32.0);
    EXPECT_EQ(s.instances, 0u);
  }
  EXPECT_GT(s.draws, 0);
  EXPECT_GT(s.indexBytes, 0u);
  if (!scene->skins.empty()) {
    EXPECT_DOUBLE_EQ(s.floatsPerJoint, 32.0);
    EXPECT_GT(s.skinBytesPerFrame, 0u);
    EXPECT_GT(s.skinVertexBytes, 0u);
  }
  EXPECT_FALSE(a.glRenderer.empty());
}

INSTANTIATE_TEST_SUITE_P(Matrix, BuiltinScene, ::testing::ValuesIn(builtinSceneNames()),
                         [](const auto& info) { return info.param; });

TEST(MatrixRender, BaseColourTextureIsSampled) {
  const uint8_t red[3] = {255, 0, 0};
  Frame f = render(quadScene(quad(), red, false));
  const uint8_t* centre = &f.image.rgba[(size_t(kSize / 2) * kSize + kSize / 2) * 4];
  EXPECT_GT(int(centre[0]), 2 * int(centre[1]) + 20);
  EXPECT_GT(int(centre[0]), 2 * int(centre[2]) + 20);
}

TEST(MatrixRender, FlatNormalMapChangesNothing) {
  const uint8_t flat[3] = {128, 128, 255};
  Frame plain = render(quadScene(quad()));
  Frame mapped = render(quadScene(quad(), flat));
  EXPECT_LE(maxDifference(plain.image, mapped.image), 2);  // 128 decodes to 0.0039, not 0
}

TEST(MatrixRender, NormalMapTiltFollowsTangentAndBitangent) {
  // Tangent-space (0.6, 0, 0.8) must equal a geometric normal tilted towards the tangent (+X);
  // (0, 0.6, 0.8) with handedness -1 one tilted towards -Y (bitangent = w * cross(n, t)).
  const uint8_t towardsT[3] = {204, 128, 230};
  const uint8_t towardsB[3] = {128, 204, 230};
  Frame mapT = render(quadScene(quad(), towardsT));
  Frame geoT = render(quadScene(quad({0.6f, 0.0f, 0.8f})));
  Frame flat = render(quadScene(quad()));
  EXPECT_LE(maxDifference(mapT.image, geoT.image), 3);
  EXPECT_GT(maxDifference(mapT.image, flat.image), 10);  // the tilt is visible at all
  Frame mapB = render(quadScene(quad({0, 0, 1}, -1.0f), towardsB));
  Frame geoB = render(quadScene(quad({0.0f, -0.6f, 0.8f}, -1.0f)));
  EXPECT_LE(maxDifference(mapB.image, geoB.image), 3);
}

TEST(MatrixRender, MirroredNodeKeepsFrontFaces) {
  // A quad mirrored in X (scale -1, 1, 1) covers the same pixels: its winding flips with the
  // negative determinant, so back-face culling must not remove it.
  Scene plain = quadScene(quad());
  Scene mirrored = quadScene(quad());
  mirrored.nodes[0].local.scale = {-1, 1, 1};
  Frame a = render(plain), b = render(mirrored);
  EXPECT_GT(coverage(a.image), 0.05);
  EXPECT_NEAR(coverage(b.image), coverage(a.image), 0.01);
}

TEST(MatrixRender, UnknownAndPlaceholderPipelinesAreErrors) {
  auto scene = loadScene("textured_box");
  ASSERT_TRUE(scene) << scene.error();
  FrameSettings s;
  s.width = s.height = 16;
  auto unknown = renderFrame(*scene, "nope", s);
  ASSERT_FALSE(unknown);
  EXPECT_NE(unknown.error().find("registered: matrix"), std::string::npos) << unknown.error();
}
