// LDR-FLIP beside PSNR in check (console line, check.json, summary.html, the
// failure's FLIP map) and in report.json (each compared frame's metrics, the map beside the
// diff): the figures are those of harness/render/flip.h on the very images written.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "harness/render/flip.h"
#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::quoted;
using mb::cli_test::runMb;

TEST(CliFlip, CheckReportsFlipBesidePsnrAndMapsAFailure) {
  const fs::path root = mb::cli_test::scratchDir("flip_check");
  fs::copy(fs::path(MB_SOURCE_DIR) / "tests" / "golden", root / "golden", fs::copy_options::recursive);
  // One pixel of one golden moved by 60 steps in green: a failure, with its images written.
  const fs::path png = root / "golden" / "textured_box.rest.matrix.png";
  auto img = mb::readImage(png.string());
  ASSERT_TRUE(img) << img.error();
  uint8_t& g = img->rgba[(size_t(img->height / 2) * size_t(img->width) + size_t(img->width / 2)) * 4 + 1];
  g = uint8_t(g >= 128 ? g - 60 : g + 60);
  ASSERT_TRUE(mb::writeImage(png.string(), *img));
  const auto r = runMb("check --golden " + quoted(root / "golden") + " --scenes textured_box --pipelines matrix --out " +
                       quoted(root / "out"));
  ASSERT_EQ(r.rc, 1) << r.out;
  EXPECT_TRUE(contains(r.out, "FAIL  textured_box.rest.matrix.png")) << r.out;
  EXPECT_TRUE(contains(r.out, "; FLIP mean ")) << r.out;
  const auto j = mb::cli_test::readJson(root / "out" / "check.json");
  ASSERT_FALSE(j.is_discarded()) << r.out;
  const nlohmann::json* item = nullptr;
  for (const auto& e : j["images"])
    if (e["file"] == "textured_box.rest.matrix.png") item = &e;
  ASSERT_NE(item, nullptr) << j.dump();
  EXPECT_EQ((*item)["flipMap"], "textured_box.rest.matrix.flip.png");
  ASSERT_TRUE(fs::exists(root / "out" / "textured_box.rest.matrix.flip.png"));
  // The figures are FLIP of the two images check wrote (golden = reference).
  auto expected = mb::readImage((root / "out" / (*item)["expected"].get<std::string>()).string());
  auto actual = mb::readImage((root / "out" / (*item)["actual"].get<std::string>()).string());
  ASSERT_TRUE(expected && actual);
  auto flip = mb::computeFlip(*expected, *actual);
  ASSERT_TRUE(flip) << flip.error();
  const auto& f = (*item)["metrics"]["flip"];
  EXPECT_GT(flip->max, 0.0);
  EXPECT_DOUBLE_EQ(f["mean"].get<double>(), flip->mean);
  EXPECT_DOUBLE_EQ(f["max"].get<double>(), flip->max);
  EXPECT_DOUBLE_EQ(f["weightedMedian"].get<double>(), flip->weightedMedian);
  EXPECT_TRUE(contains(mb::cli_test::readText(root / "out" / "summary.html"), "textured_box.rest.matrix.flip.png"));
  fs::remove_all(root);
}

TEST(CliFlip, ReportHasFlipForEveryComparedFrame) {
  const fs::path dir = mb::cli_test::scratchDir("flip_report");
  const auto r = runMb("report skinned_tube --pipelines matrix,motor,motor_q --frames 0 --no-bench --no-isa --no-plots "
                       "--size 64x48 -o " + quoted(dir));
  ASSERT_EQ(r.rc, 0) << r.out;
  const auto j = mb::cli_test::readJson(dir / "report.json");
  ASSERT_FALSE(j.is_discarded()) << r.out;
  const auto& frames = j["scenes"][0]["frames"];
  ASSERT_FALSE(frames.empty());
  for (const auto& frame : frames)
    for (const char* p : {"motor", "motor_q"}) {
      const auto& f = frame["metrics"][p]["flip"];
      ASSERT_TRUE(f.is_object()) << p << ": " << frame["metrics"].dump();
      EXPECT_TRUE(frame["metrics"][p].contains("psnr"));  // beside PSNR
      const fs::path map = dir / frame["flipMaps"][p].get<std::string>();
      auto a = mb::readImage((dir / frame["images"]["matrix"].get<std::string>()).string());
      auto b = mb::readImage((dir / frame["images"][p].get<std::string>()).string());
      ASSERT_TRUE(a && b && fs::exists(map)) << map;
      auto flip = mb::computeFlip(*a, *b);
      ASSERT_TRUE(flip);
      EXPECT_DOUBLE_EQ(f["mean"].get<double>(), flip->mean) << p;
      EXPECT_DOUBLE_EQ(f["max"].get<double>(), flip->max) << p;
    }
  fs::remove_all(dir);
}

}  // namespace
