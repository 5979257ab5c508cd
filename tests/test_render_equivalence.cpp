// Matrix vs motor image equivalence (issue 4 acceptance): on every rigid built-in scene and on
// the skinned scenes in their bind pose, PSNR >= 50 dB and at most 0.1 % of the pixels differ
// by more than 2/255. Skipped while the motor pipeline is a placeholder.
#include <gtest/gtest.h>

#include <cmath>

#include "harness/image_metrics.h"
#include "harness/render_frame.h"
#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/loader.h"

using namespace mb;

namespace {

bool motorAvailable() { return createPipeline("motor") != nullptr; }

ImageMetrics compareAt(const Scene& scene, const AnimState& anim, int size) {
  FrameSettings s;
  s.anim = anim;
  s.width = s.height = size;
  auto a = renderFrame(scene, "matrix", s);
  auto b = renderFrame(scene, "motor", s);
  EXPECT_TRUE(a) << a.error();
  EXPECT_TRUE(b) << b.error();
  if (!a || !b) return {};
  auto m = compareImages(a->image, b->image);
  EXPECT_TRUE(m) << m.error();
  return m ? *m : ImageMetrics{};
}

}  // namespace

class Equivalence : public ::testing::TestWithParam<std::string> {};

TEST_P(Equivalence, MotorMatchesMatrixAtRestPose) {
  if (!motorAvailable()) GTEST_SKIP() << "motor pipeline is still a placeholder";
  auto scene = loadScene(GetParam());
  ASSERT_TRUE(scene) << scene.error();
  // Rest pose: rigid scenes as authored, skinned ones in their bind pose.
  ImageMetrics m = compareAt(*scene, AnimState{}, 128);
  EXPECT_GE(m.psnr, 50.0) << GetParam();
  EXPECT_LE(m.fractionOver2, 0.001) << GetParam();
}

TEST_P(Equivalence, AnimatedFramesStayClose) {
  // Animated poses differ by design on skinned meshes (linear blend vs motor skinning), so only
  // rigid animation is held to the tight bound; skinned poses must still render comparably.
  if (!motorAvailable()) GTEST_SKIP() << "motor pipeline is still a placeholder";
  auto scene = loadScene(GetParam());
  ASSERT_TRUE(scene) << scene.error();
  if (scene->animations.empty()) GTEST_SKIP() << "no animation";
  AnimState anim{0, 0.4f * scene->animations[0].duration};
  ImageMetrics m = compareAt(*scene, anim, 128);
  if (scene->skins.empty()) {
    EXPECT_GE(m.psnr, 50.0) << GetParam();
    EXPECT_LE(m.fractionOver2, 0.001) << GetParam();
  } else {
    EXPECT_GE(m.psnr, 20.0) << GetParam();
  }
}

INSTANTIATE_TEST_SUITE_P(MatrixVsMotor, Equivalence, ::testing::ValuesIn(builtinSceneNames()),
                         [](const auto& info) { return info.param; });
