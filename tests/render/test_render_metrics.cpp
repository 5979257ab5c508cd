// Image metrics against values computed by hand on tiny synthetic images, idiff thresholds,
// the diff heat map and PNG round trips.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "harness/render/image_metrics.h"
#include "tests/support/rgba_images.h"

using namespace mb;

namespace {

using test_images::at;
using test_images::solid;

// 2x2 grey images; b differs by 1 step at (1,0) R, 3 steps at (0,1) G, 10 steps at (1,1) B.
struct Pair {
  RgbaImage a = solid(2, 2, 100, 100, 100), b = solid(2, 2, 100, 100, 100);
  Pair() {
    at(b, 1, 0, 0) = 101;
    at(b, 0, 1, 1) = 103;
    at(b, 1, 1, 2) = 110;
  }
};

}  // namespace

TEST(ImageMetrics, HandComputedValues) {
  Pair p;
  auto m = compareImages(p.a, p.b);
  ASSERT_TRUE(m) << m.error();
  // 16 channel values; squared step differences 1 + 9 + 100 = 110.
  const double rmse = std::sqrt(110.0 / 16.0) / 255.0;
  EXPECT_NEAR(m->rmse, rmse, 1e-7);
  EXPECT_NEAR(m->psnr, 20.0 * std::log10(1.0 / rmse), 1e-4);
  EXPECT_NEAR(m->psnr, 39.7574, 1e-3);
  EXPECT_NEAR(m->meanError, 14.0 / 16.0 / 255.0, 1e-7);
  EXPECT_NEAR(m->maxError, 10.0 / 255.0, 1e-6);
  EXPECT_EQ(m->maxX, 1);
  EXPECT_EQ(m->maxY, 1);
  EXPECT_EQ(m->maxChannel, 2);
  EXPECT_DOUBLE_EQ(m->fractionOver1, 0.5);   // 3 and 10 steps; exactly 1 step is not "over"
  EXPECT_DOUBLE_EQ(m->fractionOver2, 0.5);
  EXPECT_DOUBLE_EQ(m->fractionOver4, 0.25);  // only the 10-step pixel
}

TEST(ImageMetrics, IdenticalAndMismatchedSizes) {
  RgbaImage a = solid(3, 2, 1, 2, 3);
  auto m = compareImages(a, a);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->rmse, 0.0);
  EXPECT_TRUE(std::isinf(m->psnr));
  EXPECT_EQ(m->fractionOver1, 0.0);
  auto bad = compareImages(a, solid(2, 3, 1, 2, 3));
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("3x2 vs 2x3"), std::string::npos) << bad.error();
  EXPECT_TRUE(judge(a, solid(2, 3, 1, 2, 3), {}).failed);
}

TEST(ImageMetrics, IdiffThresholdSemantics) {
  Pair p;
  // Defaults (fail 1e-6, 0 %): any difference fails.
  EXPECT_TRUE(judge(p.a, p.b, {}).failed);
  EXPECT_FALSE(judge(p.a, p.a, {}).failed);
  // fail 0.01 (2.55 steps): 2 of 4 pixels fail = 50 %. idiff fails only when MORE than
  // failpercent of the pixels fail.
  Verdict v50 = judge(p.a, p.b, {0.01, 50.0});
  EXPECT_FALSE(v50.failed) << v50.reason;
  EXPECT_DOUBLE_EQ(v50.failPercent, 50.0);
  Verdict v49 = judge(p.a, p.b, {0.01, 49.0});
  EXPECT_TRUE(v49.failed);
  EXPECT_NE(v49.reason.find("50.0000%"), std::string::npos) << v49.reason;
  // hardfail: the 10-step (0.039) difference exceeds 0.03 even though failpercent allows all.
  Verdict hard = judge(p.a, p.b, {0.01, 100.0, 0.03});
  EXPECT_TRUE(hard.failed);
  EXPECT_NE(hard.reason.find("hardfail"), std::string::npos) << hard.reason;
  EXPECT_FALSE(judge(p.a, p.b, {0.01, 100.0, 0.05}).failed);
}

TEST(ImageMetrics, DiffHeatmapColours) {
  RgbaImage a = solid(3, 1, 200, 200, 200), b = a;
  at(b, 1, 0, 0) = 201;  // 1 step -> blue
  at(b, 2, 0, 1) = 0;    // 200 steps -> white
  RgbaImage h = diffHeatmap(a, b);
  ASSERT_EQ(h.width, 3);
  EXPECT_EQ(at(h, 0, 0, 0), 50);  // unchanged: the grey of a, dimmed to a quarter
  EXPECT_EQ(at(h, 0, 0, 2), 50);
  EXPECT_EQ(at(h, 1, 0, 0), 0);
  EXPECT_EQ(at(h, 1, 0, 1), 0);
  EXPECT_EQ(at(h, 1, 0, 2), 255);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(at(h, 2, 0, c), 255);
}

TEST(ImageIo, PngRoundTripAndErrors) {
  Pair p;
  auto path = std::filesystem::temp_directory_path() / ("mb_test_render_metrics_" + std::to_string(::getpid()) + ".png");
  Status w = writeImage(path.string(), p.b);
  ASSERT_TRUE(w) << w.error();
  auto back = readImage(path.string());
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->width, 2);
  EXPECT_EQ(back->rgba, p.b.rgba);
  std::filesystem::remove(path);
  auto missing = readImage("/nonexistent/dir/x.png");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("/nonexistent/dir/x.png"), std::string::npos);
  RgbaImage broken{4, 4, {1, 2, 3}};
  Status bad = writeImage("/tmp/never.png", broken);
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("4x4"), std::string::npos);
}
