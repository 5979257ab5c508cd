// Morph targets in the pipelines. The matrix pipeline against the Sample Viewer's
// morph done by hand on the CPU (base + sum of weighted deltas, in target order, then drawn
// as an unmorphed mesh): the same pixels exactly. Every other pipeline against the matrix one
// on the same morphed scene.
#include <gtest/gtest.h>

#include <cmath>

#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "pipelines/pipeline.h"
#include "pipelines/scene/animation.h"
#include "pipelines/scene/loader.h"
#include "tests/support/render_options.h"

using namespace mb;

namespace {

constexpr int kSize = 128;
constexpr int kGrid = 6;  // kGrid x kGrid vertices

// A normal-mapped grid in the z = 0 plane (normal +z, tangent +x) with two targets: a bump
// (z = 0.5 (1 - r^2) with its normal and tangent deltas) and a shear of x by y (positions
// only). The normal texel is tilted so that the tangent frame shows in the shading.
Scene morphGrid(std::vector<float> weights) {
  Scene s;
  s.source = "synthetic morph grid";
  Primitive p;
  MorphTarget bump, shear;
  for (int j = 0; j < kGrid; ++j)
    for (int i = 0; i < kGrid; ++i) {
      const float x = -1.0f + 2.0f * float(i) / (kGrid - 1), y = -1.0f + 2.0f * float(j) / (kGrid - 1);
      p.positions.push_back({x, y, 0.0f});
      p.normals.push_back({0, 0, 1});
      p.tangents.push_back({1, 0, 0, 1});
      p.uv0.push_back({0.5f * (x + 1), 0.5f * (1 - y)});
      bump.positions.push_back({0, 0, 0.5f * (1 - 0.5f * (x * x + y * y))});
      bump.normals.push_back({0.5f * x, 0.5f * y, 0});  // -grad z
      bump.tangents.push_back({0, 0, -0.5f * x});
      shear.positions.push_back({0.3f * y, 0, 0});
    }
  for (int j = 0; j + 1 < kGrid; ++j)
    for (int i = 0; i + 1 < kGrid; ++i) {
      const uint32_t a = uint32_t(j * kGrid + i), b = a + 1, c = a + kGrid, d = c + 1;
      p.indices.insert(p.indices.end(), {a, b, d, a, d, c});
    }
  p.targets = {bump, shear};
  p.material = 0;
  p.hadTangents = true;
  Material m;
  m.baseColorFactor = {0.7f, 0.6f, 0.5f, 1.0f};
  m.metallicFactor = 0.0f;
  m.roughnessFactor = 0.4f;
  s.images.push_back({"normal", 1, 1, {200, 150, 230, 255}});
  s.textures.push_back({0, -1});
  m.normal.texture = 0;
  s.materials.push_back(m);
  s.meshes.push_back({"grid", {std::move(p)}, {0.0f, 0.0f}});
  Node n;
  n.mesh = 0;
  n.local.rotation = glm::angleAxis(-0.6f, glm::vec3(1, 0, 0));
  n.weights = std::move(weights);
  s.nodes.push_back(n);
  s.roots = {0};
  return s;
}

// The Sample Viewer's morph by hand: every attribute plus its weighted deltas, target by target;
// the targets then removed.
Scene morphedByHand(Scene s) {
  const std::vector<float> w = s.nodes[0].weights;
  for (Primitive& p : s.meshes[0].primitives) {
    for (size_t t = 0; t < p.targets.size(); ++t) {
      const MorphTarget& d = p.targets[t];
      if (w[t] == 0.0f) continue;
      for (size_t v = 0; v < p.positions.size(); ++v) {
        p.positions[v] += w[t] * d.positions[v];
        if (!d.normals.empty()) p.normals[v] += w[t] * d.normals[v];
        if (!d.tangents.empty()) p.tangents[v] += glm::vec4(w[t] * d.tangents[v], 0.0f);
      }
    }
    p.targets.clear();
  }
  s.meshes[0].weights.clear();
  s.nodes[0].weights.clear();
  return s;
}

Frame render(const Scene& scene, const std::string& pipeline) {
  FrameSettings fs;
  fs.width = fs.height = kSize;
  auto f = renderFrame(scene, pipeline, fs);
  EXPECT_TRUE(f) << f.error();
  return f ? f.take() : Frame{};
}

Frame renderWith(const Scene& scene, const std::string& pipeline, const PipelineOptions& options) {
  return mbtest::renderWithOptions(scene, pipeline, options, AnimState{}, kSize);
}

ImageMetrics compare(const Frame& a, const Frame& b) {
  auto m = compareImages(a.image, b.image);
  EXPECT_TRUE(m) << m.error();
  return m ? *m : ImageMetrics{};
}

}  // namespace

TEST(MorphPipelines, MatrixEqualsTheSampleViewerMorphByHand) {
  const Scene morph = morphGrid({0.6f, 0.3f});
  const Frame gpu = render(morph, "matrix"), hand = render(morphedByHand(morph), "matrix");
  const ImageMetrics m = compare(gpu, hand);
  EXPECT_EQ(m.maxError, 0.0) << "psnr " << m.psnr;
  // The morph shows: the unmorphed grid draws other pixels.
  EXPECT_GT(compare(gpu, render(morphGrid({0.0f, 0.0f}), "matrix")).maxError, 0.1);
  // Measured bytes: 2 targets x 36 vertices x (position, normal, tangent) deltas.
  EXPECT_EQ(gpu.stats.morphTargetVertices, 2u * kGrid * kGrid);
  EXPECT_EQ(gpu.stats.morphBytes, 2u * kGrid * kGrid * 9 * 4);
  EXPECT_EQ(gpu.stats.morphDraws, 1);
  EXPECT_EQ(hand.stats.morphDraws, 0);
}

TEST(MorphPipelines, ZeroWeightsDrawTheBaseMeshUnmorphed) {
  const Scene rest = morphGrid({0.0f, 0.0f});
  const Frame a = render(rest, "matrix");
  EXPECT_EQ(a.stats.morphDraws, 0);
  EXPECT_EQ(compare(a, render(morphedByHand(rest), "matrix")).maxError, 0.0);
}

// The motor pipelines morph the rotor by method (a) (frame) or (b) (rotor deltas): both draw the
// morphed grid as the matrix pipeline does, (a) to within the rotor round trip's rounding.
TEST(MorphPipelines, MotorMethodsAgainstMatrix) {
  const Scene morph = morphGrid({0.6f, 0.3f});
  const Frame matrix = render(morph, "matrix");
  for (const char* pipeline : {"motor", "motor_q"}) {
    const Frame frame = renderWith(morph, pipeline, {SkinSpace::PipelineDefault, MorphMethod::Frame});
    const Frame rotor = renderWith(morph, pipeline, {SkinSpace::PipelineDefault, MorphMethod::Rotor});
    const ImageMetrics a = compare(matrix, frame), b = compare(matrix, rotor);
    EXPECT_GE(a.psnr, 50.0) << pipeline << " frame method";
    EXPECT_GE(b.psnr, 40.0) << pipeline << " rotor method";
    EXPECT_EQ(frame.stats.morphDraws, 1) << pipeline;
    // Measured: 9 floats per vertex per target (frame), 7 (rotor).
    EXPECT_EQ(frame.stats.morphBytes, frame.stats.morphTargetVertices * 9 * 4) << pipeline;
    EXPECT_EQ(rotor.stats.morphBytes, rotor.stats.morphTargetVertices * 7 * 4) << pipeline;
    std::printf("%s vs matrix: frame %.1f dB, rotor %.1f dB\n", pipeline, a.psnr, b.psnr);
  }
}

// Every pipeline morphs the grid (tests/pipelines/test_morph_every_pipeline.cpp compares the
// images): one morphing draw, and the frame method's deltas as uploaded, measured: 2 targets x 36
// vertices x 9 floats (position, normal, tangent), the compact rotors included (they morph by
// the frame method); the flat grid splits no motor_cf vertex.
TEST(MorphPipelines, EveryPipelineUploadsTheFrameDeltas) {
  const Scene morph = morphGrid({0.6f, 0.3f});
  for (const std::string& pipeline : pipelineNames()) {
    const Frame f = render(morph, pipeline);
    EXPECT_EQ(f.stats.morphDraws, 1) << pipeline;
    EXPECT_EQ(f.stats.morphTargetVertices, 2u * kGrid * kGrid) << pipeline;
    EXPECT_EQ(f.stats.morphBytes, 2u * kGrid * kGrid * 9 * 4) << pipeline;
    EXPECT_EQ(f.stats.morphNotDrawnNodes, 0) << pipeline;
  }
}

// The built-in morph scene with its weights animated (t = 1.4 s: weights (1, 0.4)): every
// morphing pipeline against matrix; the frame method exact to 50 dB, the rotor method measured.
TEST(MorphPipelines, BuiltinMorphTorusAnimated) {
  auto scene = loadScene("morph_torus");
  ASSERT_TRUE(scene) << scene.error();
  const AnimState st{0, 1.4f};
  auto weights = sampleMorphWeights(*scene, st)[0];
  ASSERT_EQ(weights.size(), 2u);
  EXPECT_FLOAT_EQ(weights[0], 1.0f);
  EXPECT_NEAR(weights[1], 0.4f, 1e-6f);
  const Frame matrix = mbtest::renderWithOptions(*scene, "matrix", {}, st, kSize);
  EXPECT_EQ(matrix.stats.morphDraws, 1);
  EXPECT_GT(compare(matrix, mbtest::renderWithOptions(*scene, "matrix", {}, AnimState{}, kSize)).maxError, 0.1);
  for (const char* pipeline : {"motor", "motor_q", "affine"}) {
    const Frame f = mbtest::renderWithOptions(*scene, pipeline, {}, st, kSize);
    EXPECT_EQ(f.stats.morphDraws, 1) << pipeline;
    const double psnr = compare(matrix, f).psnr;
    EXPECT_GE(psnr, 50.0) << pipeline;
    std::printf("morph_torus t 1.4 %s vs matrix: %.1f dB\n", pipeline, psnr);
  }
  const Frame rotor = mbtest::renderWithOptions(*scene, "motor", {SkinSpace::PipelineDefault, MorphMethod::Rotor}, st, kSize);
  std::printf("morph_torus t 1.4 motor rotor method vs matrix: %.1f dB\n", compare(matrix, rotor).psnr);
}
