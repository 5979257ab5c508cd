// The curved-space commands end to end: `motorbench compare s3_tiling`
// and `compare h3_tiling` pick their space's pair and reach PSNR >= 50 dB, a glTF pipeline on a
// curved scene (and the other way round) is an error naming both, `drift` writes its JSON.
#include <gtest/gtest.h>

#include "tests/support/cli_test_support.h"

using namespace mb::cli_test;

TEST(CliCurved, CompareEachSpaceAtFiftyDecibels) {
  const auto dir = scratchDir("curved_compare");
  for (const char* scene : {"s3_tiling", "h3_tiling"}) {
    std::string out;
    const auto d = dir / scene;
    const int rc = runCommand(motorbench() + "compare " + scene + " --time 2.7 --size 256x192 -o " + quoted(d), &out);
    ASSERT_EQ(rc, 0) << out;
    const nlohmann::json j = readJson(d / "metrics.json");
    ASSERT_FALSE(j.is_discarded()) << out;
    const std::string prefix = std::string(scene).substr(0, 3);
    EXPECT_EQ(j["pipelines"][0], prefix + "matrix");
    EXPECT_EQ(j["pipelines"][1], prefix + "motor");
    const auto& m = j["metrics"];
    if (!m["identical"].get<bool>()) EXPECT_GE(m["psnr"].get<double>(), 50.0) << scene;
    EXPECT_EQ(j["stats"][0]["floatsPerTransform"], 16.0);
    EXPECT_EQ(j["stats"][1]["floatsPerTransform"], 8.0);
  }
}

TEST(CliCurved, PipelinesRefuseTheOtherKindOfScene) {
  const auto dir = scratchDir("curved_refuse");
  std::string out;
  EXPECT_EQ(runCommand(motorbench() + "render s3_tiling --pipeline motor -o " + quoted(dir / "a.png"), &out), 2);
  EXPECT_NE(out.find("s3_tiling: pipeline motor draws Euclidean glTF scenes"), std::string::npos) << out;
  out.clear();
  EXPECT_EQ(runCommand(motorbench() + "render textured_box --pipeline h3_motor -o " + quoted(dir / "b.png"), &out), 2);
  EXPECT_NE(out.find("pipeline h3_motor draws hyperbolic (H3) scenes"), std::string::npos) << out;
  out.clear();
  EXPECT_EQ(runCommand(motorbench() + "scenes s3_tiling -o " + quoted(dir), &out) != 0, true) << out;
}

TEST(CliCurved, DriftWritesBothSpaces) {
  const auto dir = scratchDir("curved_drift");
  std::string out;
  ASSERT_EQ(runCommand(motorbench() + "drift --steps 2000 --json " + quoted(dir / "d.json"), &out), 0) << out;
  const nlohmann::json j = readJson(dir / "d.json");
  ASSERT_FALSE(j.is_discarded()) << out;
  ASSERT_EQ(j["spaces"].size(), 2u);
  for (const auto& s : j["spaces"]) {
    EXPECT_LT(s["matrix"]["renormalised"].get<double>(), 1e-5);
    EXPECT_LT(s["motor"]["renormalised"].get<double>(), 1e-5);
  }
  out.clear();
  EXPECT_EQ(runCommand(motorbench() + "drift --steps 0", &out), 2) << out;
}
