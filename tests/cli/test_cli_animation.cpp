// Animated comparisons in the report: an animated scene gets one looping GIF
// per compared pipeline, 24 frames of [baseline | pipeline | diff] side by side over one loop of
// its first animation; a scene without animation gets none.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <filesystem>

#include "tests/support/cli_test_support.h"

namespace mb::cli_test {
namespace {

namespace fs = std::filesystem;

TEST(AnimatedComparison, ReportHasOneLoopPerAnimatedScene) {
  const fs::path dir = scratchDir("animated");
  std::string out;
  ASSERT_EQ(runCommand(motorbench() + "report skinned_tube textured_box --frames 0 --no-bench --no-isa --no-plots --size 64x48 -o " +
                           quoted(dir), &out), 0) << out;
  const nlohmann::json r = readJson(dir / "report.json");
  ASSERT_FALSE(r.is_discarded());
  const nlohmann::json& tube = r["scenes"][0];
  ASSERT_EQ(tube["id"], "skinned_tube");
  const nlohmann::json& a = tube["animated"]["motor"];
  ASSERT_TRUE(a.contains("file")) << a.dump();
  EXPECT_EQ(a["frames"], 24);
  EXPECT_GT(a["maxPixelsOver2"].get<double>(), 0.0);  // LBS and motor skinning part on the bend
  EXPECT_TRUE(r["scenes"][1]["animated"].is_null());  // textured_box has no animation

  auto in = OIIO::ImageInput::open((dir / a["file"].get<std::string>()).string());
  ASSERT_TRUE(in) << OIIO::geterror();
  EXPECT_EQ(in->spec().width, 3 * 64);
  EXPECT_EQ(in->spec().height, 48);
  int subimages = 0;
  while (in->seek_subimage(subimages, 0)) ++subimages;
  EXPECT_EQ(subimages, 24);
  in->close();
  EXPECT_NE(readText(dir / "report.md").find(a["file"].get<std::string>()), std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mb::cli_test
