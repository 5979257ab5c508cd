// `motorbench render SCENE --pipelines A,B,...|all -o DIR`: several pipelines draw the
// same frame in one process, DIR/<pipeline>.png each; each image is the frame renderFrame draws
// for that pipeline, and a bad list is refused before anything is loaded or written.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "pipelines/scene/loader.h"
#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::quoted;
using mb::cli_test::runMb;

std::set<std::string> filesIn(const fs::path& dir) {
  std::set<std::string> names;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) names.insert(e.path().filename().string());
  return names;
}

// skinned_tube posed: matrix and motor draw different pixel counts there (1480 vs 1481 at
// 160x120), so an image written under the other pipeline's name would not match.
TEST(CliRenderPipelines, EachNamedPipelineWritesItsOwnFrameToTheFolder) {
  const fs::path dir = mb::cli_test::scratchDir("render_pipelines") / "frames";
  const auto run = runMb("render skinned_tube --pipelines motor,matrix --size 160x120 --anim 0 --time 0.5 -o " + quoted(dir));
  ASSERT_EQ(run.rc, 0) << run.out;
  EXPECT_EQ(filesIn(dir), (std::set<std::string>{"matrix.png", "motor.png"})) << run.out;
  EXPECT_TRUE(contains(run.out, "pipelines: motor, matrix -> ")) << run.out;
  auto scene = mb::loadScene("skinned_tube");
  ASSERT_TRUE(scene) << scene.error();
  mb::FrameSettings s;
  s.width = 160;
  s.height = 120;
  s.anim.anim = 0;
  s.anim.time = s.anim.time2 = 0.5f;
  for (const char* p : {"motor", "matrix"}) {
    const fs::path file = dir / (std::string(p) + ".png");
    EXPECT_TRUE(contains(run.out, std::string("skinned_tube: ") + p + " 160x120")) << p << "\n" << run.out;
    EXPECT_TRUE(contains(run.out, "-> " + file.string() + " (")) << p << "\n" << run.out;
    auto written = mb::readImage(file.string());
    ASSERT_TRUE(written) << p << ": " << written.error();
    auto frame = mb::renderFrame(*scene, p, s);
    ASSERT_TRUE(frame) << p << ": " << frame.error();
    EXPECT_EQ(written->width, 160) << p;
    EXPECT_EQ(written->height, 120) << p;
    EXPECT_TRUE(written->rgba == frame->image.rgba) << p << ": the file is not this pipeline's frame";
  }
  fs::remove_all(dir.parent_path());
}

TEST(CliRenderPipelines, BadListsAreRefusedBeforeAnythingIsWritten) {
  const fs::path dir = mb::cli_test::scratchDir("render_pipelines_bad");
  const fs::path out = dir / "frames";
  struct Case {
    std::string args, message;
  };
  const Case cases[] = {
      {"normal_torus --pipeline matrix --pipelines motor", "--pipeline and --pipelines: give one"},
      {"normal_torus --pipelines matrix,Motor", "--pipelines Motor: unknown pipeline (registered: matrix, motor"},
      {"normal_torus --pipelines motor,matrix,motor", "motor given twice"},
      {"normal_torus --pipelines=", "--pipelines needs pipeline names (a,b,c) or all"},
      {"normal_torus --pipelines all,motor", "--pipelines all: unknown pipeline"},
      {"s3_tiling --pipelines s3_motor,motor", "--pipelines motor does not draw this scene's space (its pipelines: s3_matrix, s3_motor)"},
  };
  for (const Case& c : cases) {
    const auto run = runMb("render " + c.args + " -o " + quoted(out));
    EXPECT_EQ(run.rc, 2) << c.args << "\n" << run.out;
    EXPECT_TRUE(contains(run.out, c.message)) << c.args << "\n" << run.out;
    EXPECT_TRUE(filesIn(out).empty()) << c.args << ": wrote " << *filesIn(out).begin();
  }
  // A file-like name is refused: --pipelines writes a folder.
  const auto png = runMb("render normal_torus --pipelines matrix,motor -o " + quoted(dir / "x.png"));
  EXPECT_EQ(png.rc, 2) << png.out;
  EXPECT_TRUE(contains(png.out, "looks like a file name")) << png.out;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
  fs::remove_all(dir);
}

}  // namespace
