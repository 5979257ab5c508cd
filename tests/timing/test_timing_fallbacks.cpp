// `time` says when a ratio was taken with the motor family's exact fallback: each pipeline's
// tally over the measured frames (harness/timing/frame_timing.h FallbackTally), in the printed
// block and in the JSON. Cases: skinned_tube with one joint stretched 1 % (the skin fallback on
// every frame) and with exporter noise of 1.8e-5 on every joint (the fast path: no fallback).
#include <gtest/gtest.h>

#include <string>

#include "harness/timing/frame_timing.h"
#include "harness/timing/timing_text.h"
#include "pipelines/scene/loader.h"

namespace {

mb::Scene tubeWithJointScale(const glm::vec3& s) {
  auto scene = mb::loadScene("skinned_tube");
  EXPECT_TRUE(scene) << scene.error();
  if (!scene) return {};
  mb::Scene out = scene.take();
  // A joint's scale moves the vertices it bends; the fallback decision is what is tested here.
  out.nodes[size_t(out.skins[0].joints[1])].local.scale = s;
  return out;
}

mb::timing::ConfigTiming timed(const mb::Scene& scene) {
  mb::timing::Settings s;
  s.frames = 4, s.warmup = 1, s.bestOf = 1;
  s.width = s.height = 32;
  s.pipelines = {"matrix", "motor"};
  auto t = mb::timing::timeScene(scene, "tube", s);
  EXPECT_TRUE(t) << t.error();
  return t ? *t : mb::timing::ConfigTiming{};
}

const mb::timing::PipelineTiming* find(const mb::timing::ConfigTiming& c, const std::string& name) {
  for (const auto& p : c.pipelines)
    if (p.pipeline == name) return &p;
  return nullptr;
}

TEST(TimingFallbacks, AStretchedJointIsTalliedOnEveryFrameAndMarksTheRatios) {
  const mb::Scene scene = tubeWithJointScale({1.01f, 1.0f, 1.0f});
  const mb::timing::ConfigTiming c = timed(scene);
  const auto* motor = find(c, "motor");
  const auto* matrix = find(c, "matrix");
  ASSERT_TRUE(motor && matrix);
  EXPECT_EQ(motor->fallbacks.frames, 4);
  EXPECT_EQ(motor->fallbacks.skinDraws, 1);  // the tube: one skinned primitive
  EXPECT_EQ(motor->fallbacks.skinJoints, int(scene.skins[0].joints.size()));
  EXPECT_EQ(motor->fallbacks.vertices, motor->stats.drawnVertices);  // every vertex of the tube
  EXPECT_FALSE(matrix->fallbacks.any());
  const std::string text = mb::timing::timingBlock(c);
  EXPECT_NE(text.find("exact fallback"), std::string::npos) << text;
  EXPECT_NE(text.find("motor 0 rigid + 1 skinned draws"), std::string::npos) << text;
  EXPECT_NE(text.find(" fallback\n"), std::string::npos) << "the motor row's update ratio is marked\n" << text;
  const nlohmann::json j = mb::timing::toJson(c);
  EXPECT_EQ(j["pipelines"]["motor"]["ratios_with_fallback"], true);
  EXPECT_EQ(j["pipelines"]["motor"]["fallbacks"]["frames"], 4);
  EXPECT_EQ(j["pipelines"]["motor"]["fallbacks"]["skinFallbackDraws"], 1);
  EXPECT_EQ(j["pipelines"]["matrix"]["ratios_with_fallback"], false);
}

TEST(TimingFallbacks, ExporterNoiseTakesTheFastPath) {
  const mb::timing::ConfigTiming c = timed(tubeWithJointScale({1.0f + 1.2e-5f, 1.0f - 0.6e-5f, 1.0f}));
  const auto* motor = find(c, "motor");
  ASSERT_TRUE(motor);
  EXPECT_FALSE(motor->fallbacks.any());
  EXPECT_EQ(mb::timing::timingBlock(c).find("exact fallback"), std::string::npos);
  EXPECT_EQ(mb::timing::toJson(c)["pipelines"]["motor"]["ratios_with_fallback"], false);
}

}  // namespace
