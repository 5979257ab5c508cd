// The drawn-pixel check compare and the report share
// (harness/render/drawn_check.h), on synthetic frames whose drawn pixels are set by hand: one
// image empty fails with the reason, counts more than 1 % apart fail, the skinning-method note
// only where the counts agree on a skinned frame. And the fallback lines and JSON render/compare
// print and the report keeps (harness/render/frame_notes.h), on hand-set PipelineStats.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "harness/render/counter_glossary.h"
#include "harness/render/drawn_check.h"
#include "harness/render/frame_notes.h"
#include "harness/render/render_frame.h"

namespace {

using mb::DrawnCheck;

// A 100x20 frame of the clear colour (0.2, 0.2, 0.22 as bytes: 51, 51, 56) whose first `drawn`
// pixels are red: a frame that drew exactly `drawn` pixels.
mb::RgbaImage frame(int drawn) {
  mb::RgbaImage img{100, 20, {}};
  for (int i = 0; i < img.width * img.height; ++i)
    img.rgba.insert(img.rgba.end(), {uint8_t(i < drawn ? 200 : 51), 51, uint8_t(i < drawn ? 10 : 56), 255});
  return img;
}

TEST(DrawnCheck, SyntheticFramesCountAsDrawn) {
  EXPECT_EQ(mb::drawnPixels(frame(0)), 0);
  EXPECT_EQ(mb::drawnPixels(frame(1000)), 1000);
}

TEST(DrawnCheck, OneEmptyImageFailsNamingWhichDrewNothing) {
  const DrawnCheck c = mb::checkDrawn("matrix", frame(24), "motor", frame(0), false, false);
  EXPECT_EQ(c.kind, DrawnCheck::Kind::OneEmpty);
  EXPECT_TRUE(c.failed);
  EXPECT_FALSE(c.skinningMethodNote);
  EXPECT_EQ(c.reason, "motor drew nothing (0 pixels) where matrix drew 24: one image is empty");
  // Either side; a skinned frame with differing methods fails alike, and carries no note.
  const DrawnCheck other = mb::checkDrawn("matrix", frame(0), "motor", frame(1353), true, true);
  EXPECT_TRUE(other.failed);
  EXPECT_FALSE(other.skinningMethodNote);
  EXPECT_EQ(other.reason, "matrix drew nothing (0 pixels) where motor drew 1353: one image is empty");
  const nlohmann::json j = mb::toJson(other);
  EXPECT_EQ(j["kind"], "one empty");
  EXPECT_EQ(j["failed"], true);
  EXPECT_EQ(j["reason"], other.reason);
  EXPECT_EQ(j["skinningMethodNote"], false);
}

TEST(DrawnCheck, CountsMoreThanOnePercentApartFail) {
  // 1000 vs 1020: 20 / 1020 = 1.96 % of the larger count.
  const DrawnCheck c = mb::checkDrawn("matrix", frame(1000), "motor", frame(1020), true, true);
  EXPECT_EQ(c.kind, DrawnCheck::Kind::CountsApart);
  EXPECT_TRUE(c.failed);
  EXPECT_FALSE(c.skinningMethodNote);
  EXPECT_NEAR(c.apartPercent, 100.0 * 20.0 / 1020.0, 1e-9);
  EXPECT_EQ(c.reason, "drawn-pixel counts more than 1 % apart (matrix 1000, motor 1020: 1.96 %): the two pipelines "
                      "did not draw the same shape");
  // 62 vs 618 (the FBX armature of the issue): fails, the same rule.
  EXPECT_TRUE(mb::checkDrawn("matrix", 618, "motor", 62, true, true).failed);
}

TEST(DrawnCheck, SkinnedCountsWithinOnePercentAllowTheMethodNote) {
  // 1000 vs 1005: 0.5 %.
  const DrawnCheck c = mb::checkDrawn("matrix", frame(1000), "motor", frame(1005), true, true);
  EXPECT_EQ(c.kind, DrawnCheck::Kind::Agree);
  EXPECT_FALSE(c.failed);
  EXPECT_TRUE(c.skinningMethodNote);
  EXPECT_TRUE(c.reason.empty());
  EXPECT_TRUE(mb::toJson(c)["reason"].is_null());
  // The bound is 1 % of the larger count: 1000 vs 1010 agrees (10 <= 10.1), 1000 vs 1011 does not.
  EXPECT_FALSE(mb::checkDrawn("a", 1000, "b", 1010, false, false).failed);
  EXPECT_TRUE(mb::checkDrawn("a", 1000, "b", 1011, false, false).failed);
  // No note without skinned primitives drawn, or where both blend alike.
  EXPECT_FALSE(mb::checkDrawn("matrix", 1000, "motor", 1005, false, true).skinningMethodNote);
  EXPECT_FALSE(mb::checkDrawn("matrix", 1000, "affine", 1005, true, false).skinningMethodNote);
}

TEST(DrawnCheck, BothEmptyIsNothingDrawnNotAFailure) {
  // compare keeps its own rule for it (exit 2 with a threshold, a warning without).
  const DrawnCheck c = mb::checkDrawn("matrix", frame(0), "motor", frame(0), true, true);
  EXPECT_EQ(c.kind, DrawnCheck::Kind::NothingDrawn);
  EXPECT_FALSE(c.failed);
  EXPECT_FALSE(c.skinningMethodNote);
  EXPECT_EQ(mb::toJson(c)["kind"], "nothing drawn");
}

TEST(FrameNotes, EveryExactFallbackCounterIsSerialisedExplainedAndPrinted) {
  mb::PipelineStats s;
  s.linearFallbackDraws = 3;
  s.skinFallbackDraws = 2;
  s.skinFallbackJoints = 53;
  s.fallbackVertices = 123456;
  const nlohmann::json all = mb::toJson(s);
  EXPECT_EQ(all["linearFallbackDraws"], 3);
  EXPECT_EQ(all["skinFallbackDraws"], 2);
  EXPECT_EQ(all["skinFallbackJoints"], 53);
  EXPECT_EQ(all["fallbackVertices"], 123456);
  const nlohmann::json fb = mb::pipelineFallbackJson(s);
  EXPECT_EQ(fb.size(), mb::pipelineFallbackKeys().size());
  for (const std::string& k : mb::pipelineFallbackKeys()) {
    EXPECT_TRUE(all.contains(k)) << k;
    EXPECT_EQ(fb[k], all[k]) << k;
    EXPECT_NE(mb::findCounter("PipelineStats", k), nullptr) << k << " has no glossary entry";
  }
  const std::vector<std::string> lines = mb::pipelineFallbackLines("motor", s);
  ASSERT_EQ(lines.size(), 4u);  // the zero counters print nothing
  EXPECT_EQ(lines[0].rfind("motor fallback: linearFallbackDraws 3 draws: ", 0), 0u) << lines[0];
  EXPECT_EQ(lines[1].rfind("motor fallback: skinFallbackDraws 2 draws: ", 0), 0u) << lines[1];
  EXPECT_EQ(lines[2].rfind("motor fallback: skinFallbackJoints 53 joints: ", 0), 0u) << lines[2];
  EXPECT_EQ(lines[3].rfind("motor fallback: fallbackVertices 123456 vertices: ", 0), 0u) << lines[3];
  EXPECT_TRUE(mb::pipelineFallbackLines("matrix", mb::PipelineStats{}).empty());
}

TEST(FrameNotes, UnsupportedLinesAreTheScenesList) {
  mb::Scene scene;
  scene.unsupported = {"mesh 0 primitive 0: 1 morph targets ignored (base geometry rendered)",
                       "node 0: extension EXT_x ignored"};
  const std::vector<std::string> lines = mb::unsupportedLines(scene);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "unsupported (not drawn): mesh 0 primitive 0: 1 morph targets ignored (base geometry rendered)");
  EXPECT_EQ(lines[1], "unsupported (not drawn): node 0: extension EXT_x ignored");
  EXPECT_TRUE(mb::unsupportedLines(mb::Scene{}).empty());
}

}  // namespace
