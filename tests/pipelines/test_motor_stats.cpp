// Motor vs matrix pipeline stats, read from what each pipeline actually uploaded: on the
// same primitive 36 against 48 bytes per vertex, 8 against 32 floats per
// transform and per joint; the motor pipeline's fallbacks are counted; it renders
// deterministically. Image equivalence itself is tests/render/test_render_equivalence.cpp.
#include <gtest/gtest.h>

#include "harness/render/render_frame.h"
#include "pipelines/scene/loader.h"

using namespace mb;

namespace {

Frame render(const Scene& scene, const std::string& pipeline, const AnimState& anim = {}) {
  FrameSettings s;
  s.anim = anim;
  s.width = s.height = 96;
  auto f = renderFrame(scene, pipeline, s);
  EXPECT_TRUE(f) << f.error();
  return f ? f.take() : Frame{};
}

Scene load(const std::string& name) {
  auto scene = loadScene(name);
  EXPECT_TRUE(scene) << scene.error();
  return scene ? scene.take() : Scene{};
}

}  // namespace

TEST(MotorStats, RigidPrimitiveBytesAndFloatsAgainstMatrix) {
  const Scene scene = load("textured_box");
  const PipelineStats motor = render(scene, "motor").stats;
  const PipelineStats matrix = render(scene, "matrix").stats;
  ASSERT_GT(motor.vertices, 0u);
  ASSERT_EQ(motor.vertices, matrix.vertices);
  EXPECT_EQ(motor.vertexBytes / motor.vertices, 36u);
  EXPECT_EQ(matrix.vertexBytes / matrix.vertices, 48u);
  EXPECT_DOUBLE_EQ(motor.floatsPerVertex, 9.0);
  EXPECT_DOUBLE_EQ(motor.floatsPerTransform, 8.0);
  EXPECT_DOUBLE_EQ(matrix.floatsPerTransform, 32.0);
  EXPECT_EQ(motor.indexBytes, matrix.indexBytes);
  EXPECT_EQ(motor.draws, matrix.draws);
  EXPECT_GT(motor.zeroScalarFrames, 0);  // the box's half-turn frames
  std::printf("textured_box: motor %llu B/vertex, %.0f floats/transform; matrix %llu B/vertex, "
              "%.0f floats/transform\n",
              (unsigned long long)(motor.vertexBytes / motor.vertices), motor.floatsPerTransform,
              (unsigned long long)(matrix.vertexBytes / matrix.vertices), matrix.floatsPerTransform);
}

TEST(MotorStats, SkinnedPrimitiveFloatsPerJointAgainstMatrix) {
  const Scene scene = load("skinned_tube");
  const PipelineStats motor = render(scene, "motor", AnimState{0, 0.5f}).stats;
  const PipelineStats matrix = render(scene, "matrix", AnimState{0, 0.5f}).stats;
  EXPECT_DOUBLE_EQ(motor.floatsPerJoint, 8.0);
  EXPECT_DOUBLE_EQ(matrix.floatsPerJoint, 32.0);
  EXPECT_EQ(motor.skinBytesPerFrame * 4, matrix.skinBytesPerFrame);
  EXPECT_EQ(motor.skinVertexBytes, matrix.skinVertexBytes);
  EXPECT_EQ(motor.vertexBytes * 4, matrix.vertexBytes * 3);
  std::printf("skinned_tube: motor %.0f floats/joint (%llu palette bytes), matrix %.0f (%llu)\n",
              motor.floatsPerJoint, (unsigned long long)motor.skinBytesPerFrame,
              matrix.floatsPerJoint, (unsigned long long)matrix.skinBytesPerFrame);
}

TEST(MotorStats, ScaledHierarchyCountsItsFallbacks) {
  const Scene scene = load("scaled_hierarchy");
  const Frame f = render(scene, "motor");
  EXPECT_EQ(f.stats.nonUniformScaleNodes, 1);  // the stretched leaf: residual scale
  EXPECT_EQ(f.stats.negativeScaleNodes, 1);    // the mirrored node: negative uniform scale
  EXPECT_EQ(f.stats.shearMatrixNodes, 0);
  EXPECT_GE(f.stats.conversionMs, 0.0);
}

TEST(MotorStats, RendersDeterministically) {
  const Scene scene = load("skinned_tube");
  const Frame a = render(scene, "motor", AnimState{1, 1.0f});
  const Frame b = render(scene, "motor", AnimState{1, 1.0f});
  EXPECT_EQ(a.image.rgba, b.image.rgba);
}
