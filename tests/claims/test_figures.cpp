// The figures layer: the statistics against hand-worked values, a figure's JSON form
// read back by name, and report.json's figures on a hand-made set of scenes, each recomputed
// here from the scenes' own numbers.
#include <gtest/gtest.h>

#include <cmath>

#include "harness/document/report_figures.h"
#include "harness/figures/figure.h"

namespace {

using json = nlohmann::json;
namespace figures = mb::figures;

TEST(Figures, QuartilesByLinearInterpolation) {
  // 1 2 3 4: positions 0.75, 1.5, 2.25 -> 1.75, 2.5, 3.25 (by hand).
  const figures::Quartiles q = figures::quartilesOf({4, 1, 3, 2});
  EXPECT_EQ(q.n, 4);
  EXPECT_DOUBLE_EQ(q.q1, 1.75);
  EXPECT_DOUBLE_EQ(q.median, 2.5);  // the mean of the middle two, not the upper one
  EXPECT_DOUBLE_EQ(q.q3, 3.25);
  EXPECT_DOUBLE_EQ(figures::quartilesOf({5, NAN, 1, 3}).median, 3);  // NaN dropped
  EXPECT_EQ(figures::quartilesOf({}).n, 0);
}

TEST(Figures, PairedRatiosSkipFramesWithoutABaseline) {
  const std::vector<double> r = figures::pairedRatios({2, 0, 4}, {1, 5, 6});
  ASSERT_EQ(r.size(), 2u);
  EXPECT_DOUBLE_EQ(r[0], 0.5);
  EXPECT_DOUBLE_EQ(r[1], 1.5);
}

TEST(Figures, JsonFormIsReadBackByName) {
  figures::Figure f;
  f.name = "frame_time.motor_over_matrix";
  f.unit = "x";
  f.statistic = "median of per-frame paired ratios";
  f.scope = "whole frame";
  f.device = "CPU rasterizer";
  f.tolerance = "10 %";
  f.definition = "motor / matrix";
  f = figures::withQuartiles(f, figures::quartilesOf({0.9, 1.0, 1.1}));
  json run = {{"figures", json::object()}};
  figures::put(run["figures"], f);
  EXPECT_TRUE(run["figures"][f.name].contains("disturbed"));  // room for the disturbance mark
  const auto back = figures::figureNamed(run, f.name);
  ASSERT_TRUE(back);
  EXPECT_DOUBLE_EQ(back->value, 1.0);
  EXPECT_DOUBLE_EQ(*back->q1, 0.95);
  EXPECT_DOUBLE_EQ(*back->q3, 1.05);
  EXPECT_EQ(back->n, 3);
  EXPECT_EQ(back->statistic, f.statistic);
  EXPECT_EQ(figures::figureText(*back),
            "1x [IQR 0.95..1.05] (median of per-frame paired ratios; n = 3; whole frame; CPU rasterizer; tolerance 10 %)");
  EXPECT_FALSE(figures::figureNamed(run, "no.such.figure"));
}

json scene(const std::string& id, double paired, double ofMedians, double bytesMotor) {
  return {{"id", id},
          {"timing", {{"width", 512}, {"height", 512}, {"paired_ratio_motor_matrix", paired},
                      {"ratio_motor_matrix", ofMedians},
                      {"paired_ratio_spread", {{"q1", paired - 0.01}, {"q3", paired + 0.02}, {"n", 30}}},
                      {"vertexBound", {{"skipped", "not vertex-bound"}}}}},
          {"pipelines", {{"matrix", {{"memory", {{"bytesPerVertex", 48}}}}},
                         {"motor", {{"memory", {{"bytesPerVertex", bytesMotor}}}}}}}};
}

TEST(Figures, ReportFrameTimeIsTheMedianOfThePairedRatiosNotOfTheMedians) {
  const std::vector<json> scenes = {scene("a", 0.80, 0.50, 36), scene("b", 0.90, 0.60, 36), scene("c", 1.10, 2.00, 40),
                                    {{"id", "s3"}, {"space", "spherical (S3)"}, {"timing", {{"paired_ratio_motor_matrix", 9.0}}}}};
  const json machine = {{"gl", {{"renderer", "llvmpipe"}, {"realGpu", false}}}, {"cpu", "X"}, {"logicalCores", 2}};
  const json settings = {{"pipelines", {"matrix", "motor"}}};
  const json f = mb::document::reportFigures(machine, settings, scenes, json::object(), json::object());
  // The three Euclidean scenes' paired ratios 0.8, 0.9, 1.1: median 0.9, quartiles 0.85 and 1.0;
  // the curved scene is not a Euclidean frame time.
  const auto all = figures::figureNamed(f, "frame_time.motor_over_matrix");
  ASSERT_TRUE(all);
  EXPECT_DOUBLE_EQ(all->value, 0.9);
  EXPECT_EQ(all->n, 3);
  EXPECT_NEAR(*all->q1, 0.85, 1e-12);
  EXPECT_NEAR(*all->q3, 1.0, 1e-12);
  EXPECT_NE(all->device.find("CPU rasterizer (llvmpipe)"), std::string::npos);
  const auto b = figures::figureNamed(f, "frame_time.b.motor_over_matrix");
  ASSERT_TRUE(b);
  EXPECT_DOUBLE_EQ(b->value, 0.9);
  EXPECT_NEAR(*b->q1, 0.89, 1e-12);
  EXPECT_EQ(b->n, 30);
  EXPECT_FALSE(figures::figureNamed(f, "frame_time.s3.motor_over_matrix"));
  const auto vb = figures::figureNamed(f, "frame_time_vertex_bound.a.motor_over_matrix");
  ASSERT_TRUE(vb);
  EXPECT_TRUE(std::isnan(vb->value));
  EXPECT_EQ(vb->why, "not vertex-bound");
  // Bytes per vertex: the motor's 36, 36, 40 -> 36.
  EXPECT_DOUBLE_EQ(figures::figureNamed(f, "bytes_per_vertex.motor")->value, 36);
  EXPECT_DOUBLE_EQ(figures::figureNamed(f, "bytes_per_vertex.matrix")->value, 48);
}

}  // namespace
