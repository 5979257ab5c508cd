// `motorbench compare`: what it prints and writes (its console lines, metrics.json, diff.png,
// the heat map's legend, the LDR-FLIP map) is measured and says what it means, and its verdict
// follows the thresholds given (none given: not judged). Drawn pixels are checked against an
// independent count of the PNGs compare wrote; skinned frames are judged against their own
// skinning method's reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "harness/render/image_metrics.h"
#include "tests/support/cli_test_support.h"
#include "tests/support/png_pixels.h"
#include "tests/support/scene_test_gltf.h"
#include "tests/support/skin_test_files.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::quoted;
using mb::cli_test::readJson;
using mb::cli_test::runMb;

using mb::cli_test::nonBackground;

// One triangle on a node scaled to zero: every pipeline draws background only.
fs::path zeroScaleFile(const fs::path& dir) {
  mbtest::TestGltf g;
  const std::vector<float> pos = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const int acc = g.accessor(g.viewOf(pos), 5126, 3, "VEC3");
  g.doc["accessors"][acc]["min"] = {0, 0, 0};
  g.doc["accessors"][acc]["max"] = {1, 1, 0};
  g.meshPrimitive({{"POSITION", acc}});
  g.doc["nodes"][0]["scale"] = {0, 0, 0};
  const fs::path file = dir / "zero_scale.gltf";
  const mbtest::Bytes bytes = g.gltf();
  std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  return file;
}

// A skinned frame of pipelines that blend joints by different methods is judged by each one's
// own method: candy_wrapper's near half turn, where linear blend skinning collapses the ring
// (matrix) and motor blending keeps it, draws more than 1 % apart from matrix yet passes, with
// the thresholds given, against the motor-blend reference; both figures printed and in
// metrics.json. Counts checked against the PNGs compare wrote. A frame more than 1 % from its own
// method's reference fails ("wrong pose, scale or missing mesh"): tests/render
// test_render_skin_judgement.cpp, on the same judgement.
TEST(CliCompareText, SkinnedFrameIsJudgedAgainstItsOwnMethodsReference) {
  const fs::path dir = mb::cli_test::scratchDir("compare_skin_reference");
  const std::string frame = "compare skinned_tube --anim candy_wrapper --time 1.97 --size 64x64 ";
  const std::string thresholds = "--fail 2/255 --failpercent 0.1 ";
  const auto r = runMb(frame + thresholds + "--pipelines matrix,motor -o " + quoted(dir / "own"));
  EXPECT_EQ(r.rc, 0) << r.out;
  const int64_t m = nonBackground(dir / "own" / "matrix.png"), q = nonBackground(dir / "own" / "motor.png");
  ASSERT_GT(m, 0);
  ASSERT_GT(std::abs(double(q - m)), 0.01 * double(std::max(m, q))) << "the frame no longer separates the methods";
  EXPECT_TRUE(contains(r.out, "  motor against the motor-blend reference (its own method's: the same pose skinned on "
                              "the CPU by the motor blend (GLM dual quaternions), drawn by matrix): ")) << r.out;
  EXPECT_TRUE(contains(r.out, "  motor against matrix (the other method, measured, decides nothing): PSNR ")) << r.out;
  EXPECT_TRUE(contains(r.out, "drawn pixels motor " + std::to_string(q) + ", matrix " + std::to_string(m) + " (")) << r.out;
  EXPECT_TRUE(contains(r.out, "-> PASS (motor against the motor-blend reference: within the thresholds given)")) << r.out;
  EXPECT_FALSE(contains(r.out, "drawn-pixel check: FAIL")) << r.out;
  EXPECT_TRUE(contains(r.out, "differently by design")) << r.out;
  const auto j = readJson(dir / "own" / "metrics.json");
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j["verdict"]["text"], "pass");
  EXPECT_EQ(j["verdict"]["judgedAgainst"]["motor"], "motor-blend reference");
  EXPECT_EQ(j["skinJudgement"]["byOwnMethod"], true);
  ASSERT_EQ(j["skinJudgement"]["pipelines"].size(), 1u);
  const auto& judged = j["skinJudgement"]["pipelines"][0];
  EXPECT_EQ(judged["pipeline"], "motor");
  EXPECT_EQ(judged["reference"], "motor-blend reference");
  EXPECT_EQ(judged["vsMatrix"]["drawnPixels"], q);
  EXPECT_EQ(judged["vsMatrix"]["referenceDrawnPixels"], m);
  EXPECT_NEAR(judged["vsMatrix"]["drawnApartPercent"].get<double>(), 100.0 * std::abs(double(q - m)) / double(std::max(m, q)), 1e-9);
  EXPECT_GE(judged["vsMatrix"]["fractionOver2"].get<double>(), 0.001) << "over the thresholds against matrix";
  EXPECT_LE(judged["vsReference"]["drawnApartPercent"].get<double>(), 1.0);
  EXPECT_LE(judged["thresholds"]["failPercent"].get<double>(), 0.1);
  EXPECT_EQ(judged["thresholds"]["applied"], true);
  EXPECT_EQ(j["drawnCheck"]["kind"], "agree");
  EXPECT_EQ(j["skinningMethods"]["differByDesign"], true);
  // Without thresholds the drawn-pixel check alone judges, against the same reference.
  const auto plain = runMb(frame + "--pipelines matrix,motor -o " + quoted(dir / "plain"));
  EXPECT_EQ(plain.rc, 0) << plain.out;
  EXPECT_TRUE(contains(plain.out, "-> no threshold given (motor against the motor-blend reference: drawn pixels within 1 %")) << plain.out;
  // Neither pipeline matrix: each against its own method's reference, matrix drawn for the LBS one.
  const auto both = runMb(frame + thresholds + "--pipelines affine,motor -o " + quoted(dir / "both"));
  EXPECT_EQ(both.rc, 0) << both.out;
  EXPECT_TRUE(contains(both.out, "  affine against matrix (its own method's reference): identical")) << both.out;
  EXPECT_TRUE(contains(both.out, "-> PASS (affine against matrix, motor against the motor-blend reference: within")) << both.out;
  // One method: the two images against each other, no reference but each other.
  const auto same = runMb(frame + "--pipelines matrix,affine -o " + quoted(dir / "same"));
  ASSERT_EQ(same.rc, 0) << same.out;
  EXPECT_EQ(nonBackground(dir / "same" / "matrix.png"), nonBackground(dir / "same" / "affine.png"));
  EXPECT_FALSE(contains(same.out, "drawn-pixel check")) << same.out;
  EXPECT_FALSE(contains(same.out, "reference")) << same.out;
  fs::remove_all(dir);
}

// A skinned mesh drawn by two nodes cannot be pre-skinned for the motor blend's reference
// (PreSkinnedScene::why): compare says so and judges motor against matrix, the strict reading,
// so the frame that separates the methods fails as the two images' drawn pixels differ.
TEST(CliCompareText, WithoutItsOwnReferenceASkinnedFrameIsJudgedAgainstMatrixAndSaysWhy) {
  const fs::path dir = mb::cli_test::scratchDir("compare_skin_no_reference");
  const fs::path file = mbtest::twiceDrawnTube(dir);
  const auto r = runMb("compare " + quoted(file) + " --anim candy_wrapper --time 1.97 --size 64x64 -o " + quoted(dir / "c"));
  EXPECT_EQ(r.rc, 1) << r.out;
  EXPECT_TRUE(contains(r.out, "motor's own method's reference could not be made (a skinned mesh drawn by more than one "
                              "node), so it is judged against matrix (the strict reading)")) << r.out;
  EXPECT_TRUE(contains(r.out, "  motor not judged against the motor-blend reference (a skinned mesh drawn by more than "
                              "one node); against matrix: ")) << r.out;
  EXPECT_TRUE(contains(r.out, "drawn-pixel check: FAIL: drawn-pixel counts more than 1 % apart (matrix ")) << r.out;
  const auto j = readJson(dir / "c" / "metrics.json");
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j["skinJudgement"]["byOwnMethod"], false);
  EXPECT_EQ(j["skinJudgement"]["pipelines"][0]["judged"], false);
  EXPECT_EQ(j["skinJudgement"]["pipelines"][0]["why"], "a skinned mesh drawn by more than one node");
  EXPECT_EQ(j["verdict"]["judgedAgainst"]["motor"], "matrix");
  fs::remove_all(dir);
}

// A frame where neither pipeline drew a pixel is not a pass: with a threshold it is an error
// naming both pipelines, and metrics.json's verdict says "nothing drawn".
TEST(CliCompareText, NothingDrawnInEitherImageIsNotAPass) {
  const fs::path dir = mb::cli_test::scratchDir("compare_empty");
  const fs::path file = zeroScaleFile(dir);
  const auto r = runMb("compare " + quoted(file) + " --failpercent 0.1 -o " + quoted(dir / "c"));
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "neither matrix nor motor drew any pixel")) << r.out;
  EXPECT_FALSE(contains(r.out, "PASS")) << r.out;
  const auto j = readJson(dir / "c" / "metrics.json");
  ASSERT_FALSE(j.is_discarded()) << r.out;
  EXPECT_EQ(j["drawnPixels"]["matrix"], 0);
  EXPECT_EQ(j["drawnPixels"]["motor"], 0);
  EXPECT_EQ(j["verdict"]["text"], "nothing drawn");
  EXPECT_EQ(j["verdict"]["failed"], true);
  EXPECT_EQ(nonBackground(dir / "c" / "matrix.png"), 0);
  // Without a threshold nothing is judged: exit 0, but said.
  const auto plain = runMb("compare " + quoted(file) + " -o " + quoted(dir / "p"));
  EXPECT_EQ(plain.rc, 0) << plain.out;
  EXPECT_TRUE(contains(plain.out, "warning: neither matrix nor motor drew any pixel")) << plain.out;
  EXPECT_TRUE(contains(plain.out, "not judged")) << plain.out;
  // render says so too (the image is written: it is what was asked for).
  const auto one = runMb("render " + quoted(file) + " -o " + quoted(dir / "r.png"));
  EXPECT_EQ(one.rc, 0) << one.out;
  EXPECT_TRUE(contains(one.out, "0 drawn pixels")) << one.out;
  EXPECT_TRUE(contains(one.out, "warning: nothing drawn")) << one.out;
  fs::remove_all(dir);
}

// Drawn pixels printed and in metrics.json equal a count of the written images; identical
// images say "identical" (as the report), not "PSNR inf dB"; update phases not timed are null.
TEST(CliCompareText, DrawnPixelsIdenticalAndUntimedPhases) {
  const fs::path dir = mb::cli_test::scratchDir("compare_identical");
  // affine is bit-identical to matrix at rest (README, "Which pipeline for what").
  const auto r = runMb("compare normal_torus --pipelines matrix,affine --size 96x64 --failpercent 0 -o " + quoted(dir));
  EXPECT_EQ(r.rc, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "identical: every byte of the two images agrees")) << r.out;
  EXPECT_FALSE(contains(r.out, "inf")) << r.out;
  EXPECT_TRUE(contains(r.out, "-> PASS")) << r.out;
  const auto j = readJson(dir / "metrics.json");
  ASSERT_FALSE(j.is_discarded());
  const int64_t drawn = nonBackground(dir / "matrix.png");
  EXPECT_GT(drawn, 0);
  EXPECT_LT(drawn, 96 * 64);
  EXPECT_EQ(j["drawnPixels"]["matrix"], drawn);
  EXPECT_EQ(j["drawnPixels"]["affine"], nonBackground(dir / "affine.png"));
  EXPECT_EQ(j["drawnPixels"]["total"], 96 * 64);
  EXPECT_TRUE(contains(r.out, "drawn pixels (not background): matrix " + std::to_string(drawn) + ", affine ")) << r.out;
  for (const auto& stats : j["stats"]) {
    EXPECT_GT(stats["updateMs"].get<double>(), 0.0);
    for (const char* phase : {"updateSamplingMs", "updateBlendingMs", "updateConversionMs", "updateHierarchyMs",
                              "updatePaletteMs"})
      EXPECT_TRUE(stats[phase].is_null()) << phase << " = " << stats[phase] << " (not timed by compare)";
  }
  fs::remove_all(dir);
}

// A skinned file compared between a linear-blend and a motor pipeline: a note says the two
// skinning methods differ by design, every channel difference reads in both units (0..1 and
// steps of 255), and a --hardfail failure against the motor-blend reference names the max error
// its line printed.
TEST(CliCompareText, SkinningMethodsAndOneUnitForEveryDifference) {
  const fs::path dir = mb::cli_test::scratchDir("compare_skin");
  const std::string frame = "compare skinned_tube --anim candy_wrapper --time 0.5 --size 128x96 ";
  const auto r = runMb(frame + "--failpercent 0.1 --hardfail 0.01 -o " + quoted(dir));
  EXPECT_EQ(r.rc, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "matrix blends joints by linear blend skinning, motor by motor blending")) << r.out;
  EXPECT_TRUE(contains(r.out, "differently by design")) << r.out;
  const auto j = readJson(dir / "metrics.json");
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j["skinningMethods"]["differByDesign"], true);
  // Every channel difference reads "N/255 (F of full scale)", F = N / 255, the max error in the
  // metrics lines and in a --hardfail reason alike.
  const std::regex both("([0-9.]+)/255 \\(([0-9.e-]+) of full scale\\)");
  int seen = 0;
  for (auto it = std::sregex_iterator(r.out.begin(), r.out.end(), both); it != std::sregex_iterator(); ++it, ++seen)
    EXPECT_NEAR(std::stod((*it)[1]) / 255.0, std::stod((*it)[2]), 1e-3 * std::stod((*it)[2]) + 1e-9) << (*it)[0];
  EXPECT_GE(seen, 5) << r.out;  // RMSE, mean error, max error; the max errors against both references
  const double maxError = j["metrics"]["maxError"];
  char expect[64];
  std::snprintf(expect, sizeof expect, "max error %.0f/255", maxError * 255.0);
  EXPECT_TRUE(contains(r.out, expect)) << expect << "\n" << r.out;
  // --hardfail below one byte step fails against the reference, with the max error its line printed.
  const auto hard = runMb(frame + "--hardfail 0.001 -o " + quoted(dir / "h"));
  EXPECT_EQ(hard.rc, 1) << hard.out;
  const std::string own = "  motor against the motor-blend reference (";
  ASSERT_TRUE(contains(hard.out, own)) << hard.out;
  const std::string line = hard.out.substr(hard.out.find("max error ", hard.out.find(own)) + 10);
  const std::string text = line.substr(0, line.find(";"));
  EXPECT_TRUE(contains(hard.out, "-> FAIL (motor against its own method's reference (motor-blend reference): max error " +
                                     text + " exceeds --hardfail 0.255/255 (0.001 of full scale))"))
      << hard.out;
  EXPECT_GT(j["skinJudgement"]["pipelines"][0]["vsReference"]["maxError"].get<double>(), 0.0)
      << "the reference and motor agree to the byte: --hardfail 0.001 would pass";
  fs::remove_all(dir);
}

// Without a threshold the verdict says "not judged"; --hardfail alone judges the largest
// difference with its own reason; malformed or out-of-range thresholds are refused; the help
// states the unit of --fail (0..1, a channel difference / 255) and of --failpercent.
TEST(CliMessages, CompareVerdictAndThresholds) {
  const fs::path dir = mb::cli_test::scratchDir("messages_verdict");
  const auto plain = runMb("compare normal_torus -o " + quoted(dir / "a"));
  ASSERT_EQ(plain.rc, 0) << plain.out;
  EXPECT_TRUE(contains(plain.out, "-> no threshold given, not judged")) << plain.out;
  EXPECT_FALSE(contains(plain.out, "FAIL")) << plain.out;
  const auto j = mb::cli_test::readJson(dir / "a" / "metrics.json");
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j["verdict"]["text"], "no threshold given");
  EXPECT_TRUE(j["verdict"]["reason"].is_null());
  // The two pipelines differ a little on this scene (precondition of the --hardfail checks).
  const double maxError = j["metrics"]["maxError"];
  ASSERT_GT(maxError, 0.0) << "matrix and motor agree exactly: the --hardfail checks below say nothing";

  // --hardfail alone judges the largest difference only: above it passes, below it fails with
  // the --hardfail reason (not the default --fail one).
  const auto pass = runMb("compare normal_torus --hardfail " + std::to_string(maxError * 2) + " -o " +
                          quoted(dir / "b"));
  EXPECT_EQ(pass.rc, 0) << pass.out;
  EXPECT_TRUE(contains(pass.out, "-> PASS")) << pass.out;
  const auto fail = runMb("compare normal_torus --hardfail " + std::to_string(maxError / 2) + " -o " +
                          quoted(dir / "c"));
  EXPECT_EQ(fail.rc, 1) << fail.out;
  EXPECT_TRUE(contains(fail.out, "-> FAIL (max error")) << fail.out;
  EXPECT_TRUE(contains(fail.out, "exceeds --hardfail")) << fail.out;
  EXPECT_FALSE(contains(fail.out, "of pixels differ")) << fail.out;

  for (const std::string& bad : {"--fail -1", "--failpercent 500", "--hardfail 2", "--fail abc"}) {
    const auto r = runMb("compare normal_torus -o " + quoted(dir / "d") + " " + bad);
    EXPECT_EQ(r.rc, 2) << bad << "\n" << r.out;
    EXPECT_TRUE(contains(r.out, bad.substr(0, bad.find(' ')) + ": expected")) << r.out;
  }
  EXPECT_FALSE(fs::exists(dir / "d"));
  const auto help = runMb("compare --help");
  EXPECT_TRUE(contains(help.out, "--fail F(0..1)")) << help.out;
  EXPECT_TRUE(contains(help.out, "--failpercent P(0..100)")) << help.out;
  EXPECT_TRUE(contains(help.out, "channel difference / 255")) << help.out;
  fs::remove_all(dir);
}

// --fail 1/255 as the help writes it (1/0 refused); LDR-FLIP printed, mapped and in
// metrics.json beside PSNR. (The legend's numbers: CliCompare.CompareWritesTheHeatMapLegend.)
TEST(CliCompare, CompareTakesFractionsAndWritesFlip) {
  const fs::path dir = mb::cli_test::scratchDir("traps_compare");
  const auto r = runMb("compare normal_torus --size 64x64 --fail 1/255 --failpercent 100 -o " + quoted(dir));
  ASSERT_EQ(r.rc, 0) << r.out;
  const auto j = mb::cli_test::readJson(dir / "metrics.json");
  ASSERT_FALSE(j.is_discarded());
  EXPECT_DOUBLE_EQ(j["thresholds"]["fail"].get<double>(), 1.0 / 255.0);
  EXPECT_EQ(runMb("compare normal_torus --size 16x16 --fail 1/0 -o " + quoted(dir / "x")).rc, 2);
  // FLIP: the line, the JSON beside psnr, the map of the frame's size.
  EXPECT_TRUE(contains(r.out, "(LDR-FLIP, 0..1, 67 pixels per degree; map: flip.png)")) << r.out;
  const auto& flip = j["metrics"]["flip"];
  ASSERT_TRUE(flip.is_object()) << j["metrics"].dump();
  EXPECT_GE(flip["mean"].get<double>(), 0.0);
  EXPECT_LE(flip["max"].get<double>(), 1.0);
  EXPECT_LE(flip["mean"].get<double>(), flip["max"].get<double>());
  EXPECT_EQ(j["flipMap"], "flip.png");
  auto map = mb::readImage((dir / "flip.png").string());
  ASSERT_TRUE(map) << map.error();
  EXPECT_EQ(map->width, 64);
  EXPECT_EQ(map->height, 64);
  fs::remove_all(dir);
}

// compare writes diff_legend.png beside diff.png: one colour block per stop of the heat map's
// scale, its number of steps under it, the colours those of metrics.json's diffLegend and of the
// documented scale, and diff.png's worst pixel in its stop's colour.
TEST(CliCompare, CompareWritesTheHeatMapLegend) {
  const fs::path dir = mb::cli_test::scratchDir("visibility_legend");
  const auto r = runMb("compare normal_torus -o " + quoted(dir));
  ASSERT_EQ(r.rc, 0) << r.out;
  const auto j = mb::cli_test::readJson(dir / "metrics.json");
  ASSERT_FALSE(j.is_discarded());
  const auto& stops = j["diffLegend"]["stops"];
  ASSERT_EQ(stops.size(), 7u);
  auto legend = mb::readImage((dir / "diff_legend.png").string());
  ASSERT_TRUE(legend) << legend.error();
  ASSERT_EQ(legend->width, 32 * 7);
  ASSERT_EQ(legend->height, 32 + 16);  // the blocks, then their numbers
  auto pixel = [&](const mb::RgbaImage& img, int x, int y) {
    const uint8_t* p = &img.rgba[(size_t(y) * size_t(img.width) + size_t(x)) * 4];
    return std::vector<int>{p[0], p[1], p[2]};
  };
  // The scale the heat map's documentation states: 1 step blue, 4 red, 16 yellow, 64 white.
  const std::map<int, std::vector<int>> stated = {{1, {0, 0, 255}}, {4, {255, 0, 0}}, {16, {255, 255, 0}}, {64, {255, 255, 255}}};
  for (size_t i = 0; i < stops.size(); ++i) {
    const std::vector<int> block = pixel(*legend, int(i) * 32 + 16, 16);
    EXPECT_EQ(block, stops[i]["rgb"].get<std::vector<int>>()) << "block " << i;
    const int steps = stops[i]["steps"];
    if (stated.count(steps)) EXPECT_EQ(block, stated.at(steps)) << steps << " steps";
  }
  // Each block's number of steps written under it: light text on the dark strip.
  for (size_t i = 0; i < stops.size(); ++i) {
    int light = 0;
    for (int y = 32; y < 48; ++y)
      for (int x = int(i) * 32; x < int(i) * 32 + 32; ++x) light += pixel(*legend, x, y)[0] > 160;
    EXPECT_GT(light, 5) << "no number under block " << i;
  }
  // The diff's worst pixel has the legend colour of its difference when that is a stop.
  const int steps = int(std::lround(j["metrics"]["maxError"].get<double>() * 255));
  auto diff = mb::readImage((dir / "diff.png").string());
  ASSERT_TRUE(diff);
  for (const auto& s : stops)
    if (s["steps"] == steps)
      EXPECT_EQ(pixel(*diff, j["metrics"]["maxErrorPixel"]["x"], j["metrics"]["maxErrorPixel"]["y"]),
                s["rgb"].get<std::vector<int>>());
  fs::remove_all(dir);
}

}  // namespace
