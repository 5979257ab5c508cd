// --gpu / MB_GPU end to end, on Mesa's EGL software device (what CI has; a real GPU takes the
// same EGL device path): render names the device, an absent device is exit 2 with the list of
// devices, time --json records the device, check on the device gets llvmpipe's goldens.
#include <gtest/gtest.h>

#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using namespace mb::cli_test;

TEST(CliGpu, RenderOnEglDeviceZeroNamesTheDevice) {
  const fs::path dir = scratchDir("gpu_render");
  std::string out;
  const int rc = runCommand(motorbench() + "render normal_torus --gpu 0 -o " + quoted(dir / "x.png"), &out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_TRUE(fs::exists(dir / "x.png")) << out;
  EXPECT_NE(out.find("on egl-device 0, software"), std::string::npos) << out;
  EXPECT_NE(out.find("llvmpipe"), std::string::npos) << out;
}

TEST(CliGpu, AbsentDeviceIsExit2WithTheDevicesSeen) {
  const fs::path dir = scratchDir("gpu_absent");
  std::string out;
  const int rc = runCommand(motorbench() + "render normal_torus --gpu 7 -o " + quoted(dir / "x.png"), &out);
  EXPECT_EQ(rc, 2) << out;
  EXPECT_NE(out.find("GPU 7"), std::string::npos) << out;
  EXPECT_NE(out.find("no such EGL device; devices seen: 0 software"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(CliGpu, MalformedValueIsExit2) {
  std::string out;
  EXPECT_EQ(runCommand(motorbench() + "time normal_torus --gpu fast", &out), 2) << out;
  EXPECT_NE(out.find("--gpu fast: expected auto, llvmpipe or an EGL device index"), std::string::npos) << out;
}

// The option wins over MB_GPU; MB_GPU alone is read.
TEST(CliGpu, OptionWinsOverEnvironment) {
  const fs::path dir = scratchDir("gpu_env");
  std::string out;
  EXPECT_EQ(runCommand("MB_GPU=7 " + motorbench() + "render normal_torus -o " + quoted(dir / "a.png"), &out), 2) << out;
  EXPECT_NE(out.find("GPU 7"), std::string::npos) << out;
  EXPECT_EQ(runCommand("MB_GPU=7 " + motorbench() + "render normal_torus --gpu 0 -o " + quoted(dir / "b.png"), &out), 0)
      << out;
  EXPECT_NE(out.find("egl-device 0"), std::string::npos) << out;
}

// time's worker processes inherit the device; --json records it as report.json's machine.gl.
TEST(CliGpu, TimeJsonRecordsTheDevice) {
  const fs::path dir = scratchDir("gpu_time");
  std::string out;
  const int rc = runCommand(motorbench() + "time textured_box --frames 2 --warmup 1 --best-of 1 --size 32x32 --gpu 0 --json " +
                                quoted(dir / "t.json"),
                            &out);
  ASSERT_EQ(rc, 0) << out;
  const nlohmann::json j = readJson(dir / "t.json");
  ASSERT_FALSE(j.is_discarded()) << out;
  const nlohmann::json& gl = j["machine"]["gl"];
  EXPECT_EQ(gl["backend"], "egl-device 0");
  EXPECT_EQ(gl["kind"], "cpu-rasterizer");
  EXPECT_EQ(gl["realGpu"], false);
  EXPECT_EQ(gl["device"]["index"], 0);
  EXPECT_EQ(gl["device"]["software"], true);
  EXPECT_TRUE(gl["device"]["drm"].is_null());
  EXPECT_NE(gl["renderer"].get<std::string>().find("llvmpipe"), std::string::npos);
  ASSERT_FALSE(j["results"].empty());
  EXPECT_EQ(j["results"][0]["frameTimeSource"], "wall-clock");
  EXPECT_NE(out.find("device egl-device 0, software"), std::string::npos) << out;
}

// check on Mesa's EGL device: llvmpipe, so llvmpipe's goldens and their exact thresholds.
TEST(CliGpu, CheckOnEglDeviceUsesLlvmpipesGoldens) {
  const fs::path dir = scratchDir("gpu_check");
  std::string out;
  const int rc = runCommand("cd " + quoted(MB_SOURCE_DIR) + " && " + motorbench() +
                                "check --scenes textured_box --pipelines matrix,motor --gpu 0 --out " + quoted(dir),
                            &out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("goldens: tests/golden (llvmpipe's; drawn on llvmpipe"), std::string::npos) << out;
  EXPECT_NE(out.find("on egl-device 0, software)"), std::string::npos) << out;
  const nlohmann::json j = readJson(dir / "check.json");
  ASSERT_FALSE(j.is_discarded()) << out;
  ASSERT_FALSE(j["images"].empty());
  for (const auto& im : j["images"]) EXPECT_EQ(im["level"], "exact") << im["file"];
  EXPECT_EQ(j["golden"], "tests/golden");
}

}  // namespace
