// `motorbench time` prints every pipeline with a spread [q1-q3] beside
// every ratio, "noise" where that spread crosses 1, "< 1: motor faster" above the table, scene
// names that cannot shift the columns, and never "scenes timed" for a scene that failed.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include "harness/timing/timing_text.h"
#include "pipelines/pipeline.h"
#include "tests/support/cli_test_support.h"

#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::quoted;
using mb::cli_test::runMb;
namespace timing = mb::timing;

// Paired ratios motor/matrix of {1.1, 0.9, 1.2, 0.8, 1.0}: median 1.0, q1 0.9, q3 1.1 (linear
// quantiles of five sorted values: the 2nd and 4th) -> noise; all below 1 -> no noise.
TEST(CliTimeText, NoiseMarksARatioWhoseQuartilesCrossOne) {
  const std::vector<double> matrix = {1, 1, 1, 1, 1};
  const timing::RatioText mixed = timing::pairedRatio(matrix, {1.1, 0.9, 1.2, 0.8, 1.0});
  EXPECT_DOUBLE_EQ(mixed.spread.median, 1.0);
  EXPECT_DOUBLE_EQ(mixed.spread.q1, 0.9);
  EXPECT_DOUBLE_EQ(mixed.spread.q3, 1.1);
  EXPECT_TRUE(mixed.noise());
  EXPECT_EQ(mixed.text(), "1.000 [0.900-1.100] noise");
  const timing::RatioText faster = timing::pairedRatio({2, 2, 2, 2, 2}, {1.5, 1.6, 1.7, 1.8, 1.9});
  EXPECT_FALSE(faster.noise());
  EXPECT_EQ(faster.text(), "0.850 [0.800-0.900]");
  EXPECT_EQ(timing::pairedRatio({}, {}).text(), "-");
}

TEST(CliTimeText, BlockListsEveryPipelineWithSpreadsAndTheLegendSaysWhichWayIsFaster) {
  timing::ConfigTiming c;
  c.scene = "/a/very/long/path/to/some/folder/with/a/scene_name_longer_than_any_column.glb";
  c.config = "normal", c.width = 512, c.height = 512;
  for (const std::string& p : mb::pipelineNames()) {
    timing::PipelineTiming t;
    t.pipeline = p;
    t.frameMs = p == "matrix" ? std::vector<double>{2, 2, 2, 2, 2} : std::vector<double>{1.8, 1.9, 2.0, 2.1, 2.2};
    t.updateMs = {0.004, 0.004, 0.004, 0.004, 0.004};
    t.frame = timing::spreadOf(t.frameMs), t.update = timing::spreadOf(t.updateMs);
    c.pipelines.push_back(t);
  }
  const std::string block = timing::timingBlock(c);
  EXPECT_EQ(block.rfind(c.scene + " (normal 512x512)\n", 0), 0u) << block;
  const size_t column = block.find("frame/matrix [q1-q3]") - block.find("  pipeline");
  for (const std::string& p : mb::pipelineNames()) {
    const size_t row = block.find("\n  " + p + " ");
    ASSERT_NE(row, std::string::npos) << p << " missing:\n" << block;
    const std::string line = block.substr(row + 1, block.find('\n', row + 1) - row - 1);
    // The ratio column starts where its header does, whatever the scene's name.
    const std::string cell = line.substr(column);
    if (p == "matrix") EXPECT_EQ(cell.rfind("1 (baseline)", 0), 0u) << line;
    else EXPECT_EQ(cell.rfind("1.000 [0.950-1.050] noise", 0), 0u) << line;
  }
  EXPECT_TRUE(contains(timing::timingLegend(), "< 1: motor")) << timing::timingLegend();
}

// Update phases beside the whole update (Fox's motor once read 'sampling 32.78 us' beside 'whole update 3.85 us').
// Each phase line shows its sum beside the whole update, and says so when the phase blocks ran
// far slower than the timed update (phases then read as shares).
TEST(CliTimeText, PhasesShowTheirSumBesideTheWholeUpdate) {
  timing::ConfigTiming c;
  c.scene = "fox", c.config = "normal", c.width = 64, c.height = 64;
  for (double sampling : {0.0020, 0.03278}) {  // ms per call: below and far above the whole
    timing::PipelineTiming t;
    t.pipeline = sampling < 0.01 ? "matrix" : "motor";
    t.update = timing::spreadOf({0.00385});
    t.phases[0] = timing::spreadOf({sampling});
    t.phases[3] = timing::spreadOf({0.0010});
    c.pipelines.push_back(t);
  }
  const std::string block = timing::timingBlock(c);
  EXPECT_TRUE(contains(block, "    matrix     2.00/0.00/0.00/1.00/0.00 (sum 3.00; whole update 3.85)\n")) << block;
  EXPECT_TRUE(contains(block, "    motor      32.78/0.00/0.00/1.00/0.00 (sum 33.78; whole update 3.85) the phase blocks "
                              "ran slower than the timed update")) << block;
}

// `time` end to end: the legend line before the first block, every pipeline, spreads.
TEST(CliTimeText, TimePrintsEveryPipelineAndTheDirectionFirst) {
  const auto r = runMb("time normal_torus --frames 3 --warmup 1");
  ASSERT_EQ(r.rc, 0) << r.out;
  const size_t legend = r.out.find("< 1: motor");
  const size_t block = r.out.find("normal_torus (normal 512x512)");
  ASSERT_NE(legend, std::string::npos) << r.out;
  ASSERT_NE(block, std::string::npos) << r.out;
  EXPECT_LT(legend, block) << r.out;
  for (const std::string& p : mb::pipelineNames()) EXPECT_TRUE(contains(r.out, "\n  " + p + " ")) << p << "\n" << r.out;
  EXPECT_TRUE(contains(r.out, "motor/matrix frame: paired ")) << r.out;
  EXPECT_TRUE(contains(r.out, "time: 1/1 scenes done (normal_torus: timed)")) << r.out;
}

// --json carries each pipeline's ratio to matrix with its spread and noise mark, as the text:
// recomputed here from the per-frame samples the same file holds.
TEST(CliTimeText, JsonHasEveryRatioWithItsSpread) {
  const std::filesystem::path dir = mb::cli_test::scratchDir("time_ratio_json");
  const auto r = runMb("time normal_torus --frames 5 --warmup 1 --json " + quoted(dir / "t.json"));
  ASSERT_EQ(r.rc, 0) << r.out;
  std::ifstream in(dir / "t.json");
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  ASSERT_FALSE(j.is_discarded());
  const nlohmann::json& ps = j["results"][0]["pipelines"];
  const std::vector<double> base = ps["matrix"]["frame_samples_ms"].get<std::vector<double>>();
  for (const std::string& p : mb::pipelineNames()) {
    const nlohmann::json& ratio = ps[p]["frame_ratio_to_matrix"];
    ASSERT_TRUE(ratio.is_object()) << p;
    std::vector<double> own = ps[p]["frame_samples_ms"].get<std::vector<double>>(), per;
    ASSERT_EQ(own.size(), base.size());
    for (size_t i = 0; i < own.size(); ++i) per.push_back(own[i] / base[i]);
    std::sort(per.begin(), per.end());
    EXPECT_NEAR(ratio["median"].get<double>(), per[per.size() / 2], 1e-12) << p;  // 5 frames: the middle one
    EXPECT_LE(ratio["q1"].get<double>(), ratio["median"].get<double>()) << p;
    EXPECT_GE(ratio["q3"].get<double>(), ratio["median"].get<double>()) << p;
    EXPECT_NEAR(ratio["iqr"].get<double>(), ratio["q3"].get<double>() - ratio["q1"].get<double>(), 1e-12) << p;
    EXPECT_EQ(ratio["noise"].get<bool>(), ratio["q1"].get<double>() <= 1.0 && ratio["q3"].get<double>() >= 1.0) << p;
    EXPECT_TRUE(ps[p]["update_ratio_to_matrix"].is_object()) << p;
  }
  if (ps["matrix"]["frame_ratio_to_matrix"]["median"].is_number())
    EXPECT_DOUBLE_EQ(ps["matrix"]["frame_ratio_to_matrix"]["median"].get<double>(), 1.0);
  std::filesystem::remove_all(dir);
}

// "`time nope.glb` prints '1/1 scenes timed' before failing."
TEST(CliTimeText, AFailedSceneIsNotCountedAsTimed) {
  const auto r = runMb("time nope.glb");
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_FALSE(contains(r.out, "timed)")) << r.out;
  EXPECT_TRUE(contains(r.out, "1/1 scenes done (nope.glb: failed")) << r.out;
  EXPECT_TRUE(contains(r.out, "nope.glb: no such file")) << r.out;
}

}  // namespace
