// The issue-16 pipelines' measured uploads against the matrix and motor pipelines: bytes per
// vertex on a normal-mapped primitive (48/48/28/36/28/28), floats per transform and per joint,
// the bias rule's frame count, and hybrid's matrices equal to GLM's TRS.
#include <gtest/gtest.h>

#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "harness/render/render_frame.h"
#include "pipelines/hybrid/hybrid_pipeline.h"
#include "pipelines/motor/companion.h"
#include "pipelines/scene/loader.h"

using namespace mb;

namespace {

Frame render(const Scene& scene, const std::string& pipeline) {
  FrameSettings s;
  s.width = s.height = 64;
  auto f = renderFrame(scene, pipeline, s);
  EXPECT_TRUE(f) << pipeline << ": " << f.error();
  return f ? f.take() : Frame{};
}

Scene load(const std::string& name) {
  auto scene = loadScene(name);
  EXPECT_TRUE(scene) << scene.error();
  return scene ? scene.take() : Scene{};
}

}  // namespace

TEST(VariantStats, BytesPerVertexOnANormalMappedScene) {
  const Scene scene = load("normal_torus");
  const std::pair<const char*, uint64_t> expected[] = {{"matrix", 48}, {"affine", 48}, {"qtangent", 28},
                                                       {"motor", 36},  {"motor_q", 28}, {"hybrid", 28}};
  for (const auto& [name, bytes] : expected) {
    const PipelineStats s = render(scene, name).stats;
    ASSERT_GT(s.vertices, 0u) << name;
    EXPECT_EQ(s.vertexBytes, bytes * s.vertices) << name;
    // Every primitive of normal_torus is normal-mapped: all of it is the normal-mapped share.
    EXPECT_EQ(s.normalMappedVertexBytes, s.vertexBytes) << name;
    EXPECT_EQ(s.normalMappedVertices, s.vertices) << name;
    std::printf("normal_torus %-8s %llu B/vertex, %.1f floats/transform\n", name,
                (unsigned long long)(s.vertexBytes / s.vertices), s.floatsPerTransform);
  }
}

TEST(VariantStats, FloatsPerTransformAndPerJoint) {
  const Scene box = load("textured_box");
  EXPECT_DOUBLE_EQ(render(box, "affine").stats.floatsPerTransform, 21.0);  // mat4x3 + mat3
  EXPECT_DOUBLE_EQ(render(box, "hybrid").stats.floatsPerTransform, 21.0);
  EXPECT_DOUBLE_EQ(render(box, "motor_q").stats.floatsPerTransform, 8.0);
  const Scene tube = load("skinned_tube");
  EXPECT_DOUBLE_EQ(render(tube, "matrix").stats.floatsPerJoint, 32.0);
  EXPECT_DOUBLE_EQ(render(tube, "affine").stats.floatsPerJoint, 12.0);
  EXPECT_DOUBLE_EQ(render(tube, "qtangent").stats.floatsPerJoint, 12.0);
  EXPECT_DOUBLE_EQ(render(tube, "hybrid").stats.floatsPerJoint, 12.0);
  EXPECT_DOUBLE_EQ(render(tube, "motor_q").stats.floatsPerJoint, 8.0);
}

TEST(VariantStats, BiasRuleFramesAreCounted) {
  const Scene box = load("textured_box");  // axis-aligned faces: half-turn frames
  const PipelineStats motor = render(box, "motor").stats, q = render(box, "motor_q").stats;
  EXPECT_GT(q.zeroScalarFrames, 0);
  EXPECT_EQ(q.zeroScalarFrames, motor.zeroScalarFrames);
  EXPECT_GE(q.biasedFrames, q.zeroScalarFrames);
  EXPECT_EQ(q.biasedFrames, motor.biasedFrames);  // the same rule on the float rotors
  EXPECT_GT(render(box, "qtangent").stats.biasedFrames, 0);
  EXPECT_EQ(render(box, "affine").stats.biasedFrames, 0);  // float frames need no bias
}

TEST(VariantStats, HybridMatrixEqualsGlmTrs) {
  const glm::vec3 t(1.5f, -2.0f, 0.25f), s(2.0f, 0.5f, 3.0f);
  const glm::quat q = glm::normalize(glm::quat(0.8f, 0.3f, -0.4f, 0.2f));
  const glm::mat4 expected = glm::translate(glm::mat4(1.0f), t) * glm::mat4_cast(q) *
                             glm::scale(glm::mat4(1.0f), s);
  const glm::mat4x3 got = hybrid::toMatrix(companion::motorFromTRS(t, q), s);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(got[c][r], expected[c][r], 1e-5f) << c << "," << r;
}
