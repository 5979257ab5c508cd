// `motorbench time`: it times the pipelines and the one animation asked (each scene in its own
// worker, folders taken, a bad scene not stopping the others), prints every pipeline with a spread
// [q1-q3] beside every ratio, "noise" where that spread crosses 1, "too few frames" for ratios of
// one frame, "< 1: motor faster" above the table, scene names that cannot shift the columns, and
// never "scenes timed" for a scene that failed; its JSON holds every ratio with its spread, the
// vertex-bound configuration where a scene is vertex-bound and the Bezier bytes table. Never
// asserts a timing.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include "harness/timing/timing_text.h"
#include "pipelines/pipeline.h"
#include "pipelines/scene/builtin_scenes.h"
#include "tests/support/cli_test_support.h"

#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using mb::cli_test::contains;
using mb::cli_test::exe;
using mb::cli_test::motorbench;
using mb::cli_test::quoted;
using mb::cli_test::readJson;
using mb::cli_test::runCommand;
using mb::cli_test::runMb;
using mb::cli_test::scratchFile;
using mb::cli_test::writeBytes;
namespace timing = mb::timing;

TEST(CliTime, TexturedBoxPrintsARatio) {
  const fs::path json = scratchFile("time.json");
  std::string log;
  const int rc = runCommand(
      exe() + "time textured_box --frames 3 --warmup 1 --json '" + json.string() + "'", &log);
  ASSERT_EQ(rc, 0) << log;
  EXPECT_NE(log.find("motor/matrix"), std::string::npos) << log;
  EXPECT_NE(log.find("GL_RENDERER"), std::string::npos) << log;
  const nlohmann::json j = readJson(json);
  ASSERT_FALSE(j.is_discarded()) << log;
  ASSERT_TRUE(j.contains("machine"));
  ASSERT_TRUE(j.contains("results"));
  bool ratio = false;
  for (const auto& r : j["results"])
    if (r.contains("ratio_motor_over_matrix") && r["ratio_motor_over_matrix"].is_number()) ratio = true;
  EXPECT_TRUE(ratio) << j.dump(2);
  fs::remove(json);
}

TEST(CliTime, TimeTimesThePipelinesAndTheOneAnimationAsked) {
  const fs::path dir = mb::cli_test::scratchDir("traps_time");
  const auto r = runMb("time skinned_tube --pipelines matrix,motor --anim candy_wrapper --frames 6 --warmup 1 "
                       "--size 32x32 --json " + quoted(dir / "t.json"));
  ASSERT_EQ(r.rc, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "skinned_tube: timing animation 2 'candy_wrapper' (3 of ")) << r.out;
  const auto j = mb::cli_test::readJson(dir / "t.json");
  ASSERT_FALSE(j.is_discarded()) << r.out;
  const auto& row = j["results"][0];
  EXPECT_EQ(row["animation"]["index"], 2) << row.dump();
  std::vector<std::string> timed;
  for (const auto& [name, p] : row["pipelines"].items()) timed.push_back(name);  // an object by name
  EXPECT_EQ(timed, (std::vector<std::string>{"matrix", "motor"})) << row.dump();
  // Without --anim: animation 0, said, with the hint that there are others.
  const auto plain = runMb("time skinned_tube --pipelines matrix --frames 1 --warmup 0 --size 16x16");
  EXPECT_EQ(plain.rc, 0) << plain.out;
  EXPECT_TRUE(contains(plain.out, ": timing animation 0 ")) << plain.out;
  EXPECT_TRUE(contains(plain.out, "--anim picks another")) << plain.out;
  // A wrong name is refused before any scene is timed; a wrong animation names the scene's.
  const auto wrong = runMb("time textured_box --pipelines matrix,motr");
  EXPECT_EQ(wrong.rc, 2) << wrong.out;
  EXPECT_TRUE(contains(wrong.out, "--pipelines motr: unknown pipeline")) << wrong.out;
  EXPECT_FALSE(contains(wrong.out, "machine:")) << wrong.out;
  const auto noAnim = runMb("time skinned_tube --pipelines matrix --anim nope --frames 1 --warmup 0 --size 16x16");
  EXPECT_EQ(noAnim.rc, 2) << noAnim.out;
  EXPECT_TRUE(contains(noAnim.out, "--anim nope: no such name")) << noAnim.out;
  fs::remove_all(dir);
}

TEST(CliTime, EachSceneInItsOwnWorkerAndABadSceneDoesNotStopTheOthers) {
  const fs::path json = scratchFile("time_two.json");
  std::string log;
  const int rc = runCommand(exe() + "time no_such_scene_or_file.glb textured_box normal_torus --frames 2 "
                             "--warmup 0 --size 32x32 --json '" + json.string() + "'", &log);
  EXPECT_EQ(rc, 2) << log;
  EXPECT_NE(log.find("no_such_scene_or_file.glb"), std::string::npos) << log;
  EXPECT_NE(log.find("\ntextured_box "), std::string::npos) << log;
  EXPECT_NE(log.find("\nnormal_torus "), std::string::npos) << log;
  const nlohmann::json j = readJson(json);
  ASSERT_FALSE(j.is_discarded()) << log;
  ASSERT_EQ(j["results"].size(), 3u) << j.dump(2);
  EXPECT_EQ(j["results"][0]["scene"], "no_such_scene_or_file.glb");
  EXPECT_TRUE(j["results"][0].contains("error"));
  EXPECT_EQ(j["results"][1]["scene"], "textured_box");
  EXPECT_EQ(j["results"][2]["scene"], "normal_torus");
  for (size_t i : {1u, 2u}) {
    EXPECT_FALSE(j["results"][i].contains("error")) << j["results"][i].dump(2);
    EXPECT_EQ(j["results"][i]["width"], 32) << j["results"][i].dump(2);
  }
  fs::remove(json);
}

// time takes a folder and times the glTF files found under it.
TEST(CliTime, TimeAcceptsAFolder) {
  const fs::path dir = mb::cli_test::scratchDir("visibility_time");
  auto glb = mb::builtinSceneGlb("textured_box");
  ASSERT_TRUE(glb);
  fs::create_directories(dir / "scenes" / "sub");
  writeBytes(dir / "scenes" / "sub" / "box.glb", *glb);
  const auto r = runMb("time " + quoted(dir / "scenes") + " --frames 2 --warmup 0 --best-of 1 --size 32x32 --json " +
                       quoted(dir / "t.json"));
  ASSERT_EQ(r.rc, 0) << r.out;
  const auto j = mb::cli_test::readJson(dir / "t.json");
  ASSERT_FALSE(j.is_discarded());
  ASSERT_EQ(j["results"].size(), 1u) << j.dump(1);
  EXPECT_EQ(j["results"][0]["scene"], (dir / "scenes" / "sub" / "box.glb").string());
  fs::remove_all(dir);
}

TEST(CliTime, RejectsBadInput) {
  std::string log;
  EXPECT_EQ(runCommand(exe() + "time no_such_scene_or_file.glb --frames 2", &log), 2) << log;
  log.clear();
  EXPECT_EQ(runCommand(exe() + "time textured_box --frames 0", &log), 2) << log;
  log.clear();
  EXPECT_EQ(runCommand(exe() + "time textured_box --size 0x5", &log), 2) << log;
}

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

TEST(CliTime, OneFrameMarksItsRatiosTooFewFrames) {
  const auto one = runMb("time textured_box --pipelines matrix,motor --frames 1 --warmup 0 --size 16x16");
  ASSERT_EQ(one.rc, 0) << one.out;
  EXPECT_TRUE(contains(one.out, "too few frames (1 < 5)")) << one.out;
  const auto five = runMb("time textured_box --pipelines matrix,motor --frames 5 --warmup 0 --size 16x16");
  ASSERT_EQ(five.rc, 0) << five.out;
  EXPECT_FALSE(contains(five.out, "too few frames")) << five.out;
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

// A scene that failed is counted as done with its reason, never as timed.
TEST(CliTimeText, AFailedSceneIsNotCountedAsTimed) {
  const auto r = runMb("time nope.glb");
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_FALSE(contains(r.out, "timed)")) << r.out;
  EXPECT_TRUE(contains(r.out, "1/1 scenes done (nope.glb: failed")) << r.out;
  EXPECT_TRUE(contains(r.out, "nope.glb: no such file")) << r.out;
}

// The tiny-viewport configuration runs only where it is vertex-bound (>= 10 drawn vertices per
// pixel): at 8x8 (640 vertices needed) the crowd draws 108,800 (256 instances x 425) and the
// torus 2,178, the textured box 24.
TEST(CliTime, VertexBoundConfigurationOnlyForScenesDrawingManyVerticesPerPixel) {
  const fs::path json = scratchFile("time_vbound.json");
  std::string log;
  const int rc = runCommand(exe() + "time textured_box normal_torus crowd --frames 2 --warmup 0 --size 32x32 --tiny 8x8 "
                             "--json '" + json.string() + "'", &log);
  ASSERT_EQ(rc, 0) << log;
  const nlohmann::json j = readJson(json);
  ASSERT_FALSE(j.is_discarded()) << log;
  std::vector<std::string> rows;
  for (const auto& r : j["results"]) rows.push_back(r.value("scene", "?") + "/" + r.value("config", "?"));
  EXPECT_EQ(rows, (std::vector<std::string>{"textured_box/normal", "normal_torus/normal", "normal_torus/vertex-bound",
                                      "crowd/normal", "crowd/vertex-bound"}))
      << j.dump(2);
  fs::remove(json);
}

TEST(CliTimeJson, BezierBytesTableIsInTheJson) {
  const fs::path dir = mb::cli_test::scratchDir("time_bytes");
  std::string log;
  ASSERT_EQ(runCommand(motorbench() + "time teapot --level 2,4 --frames 1 --warmup 0 --size 32x32 --json " +
                           quoted(dir / "t.json"), &log), 0) << log;
  const json j = readJson(dir / "t.json");
  ASSERT_FALSE(j.is_discarded()) << log;
  ASSERT_EQ(j["patchMemory"].size(), 1u) << j["patchMemory"].dump();
  EXPECT_EQ(j["patchMemory"][0]["scene"], "teapot");
  const json& rows = j["patchMemory"][0]["rows"];
  ASSERT_FALSE(rows.empty());
  int levels2 = 0, levels4 = 0;
  for (const json& row : rows) {
    const int n = row["level"];
    (n == 2 ? levels2 : levels4) += 1;
    // 32 patches x 16 control points x RGB32F; one pattern of (N+1)^2 uv (2 floats) and
    // 2 N^2 triangles of 32-bit indices; pre-tessellated: (N+1)^2 vertices per patch.
    EXPECT_EQ(row["controlPointBytes"], 32 * 16 * 12);
    EXPECT_EQ(row["instancedBytes"], 32 * 16 * 12 + (n + 1) * (n + 1) * 8 + 2 * n * n * 3 * 4) << row.dump();
    EXPECT_EQ(row["pretessellatedVertices"], 32 * (n + 1) * (n + 1));
    EXPECT_GT(row["pretessellatedBytes"].get<double>(), row["instancedBytes"].get<double>()) << row.dump();
  }
  EXPECT_EQ(levels2, levels4);
  EXPECT_GT(levels2, 0);
  fs::remove_all(dir);
}

}  // namespace
