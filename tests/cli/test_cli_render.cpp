// `motorbench render`: `--pipelines A,B,...|all -o DIR` draws the same frame with several
// pipelines in one process, DIR/<pipeline>.png each, each image the frame renderFrame draws for
// that pipeline, and a bad list is refused before anything is loaded or written; a Bezier patch
// file (.bpt) renders in both pipelines, and malformed ones (generated from the teapot:
// truncated, wrong degree, text in numbers, 10^9 patches claimed) exit 2 with a message naming
// the file and the line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "pipelines/scene/loader.h"
#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::motorbench;
using mb::cli_test::quoted;
using mb::cli_test::readText;
using mb::cli_test::runCommand;
using mb::cli_test::runMb;
using mb::cli_test::scratchDir;

std::set<std::string> filesIn(const fs::path& dir) {
  std::set<std::string> names;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) names.insert(e.path().filename().string());
  return names;
}

std::string teapot() { return readText(std::string(MB_SOURCE_DIR) + "/pipelines/scene/data/teapot.bpt"); }

std::string replaceLine(const std::string& text, int line, const std::string& with) {
  std::istringstream in(text);
  std::string out, l;
  for (int n = 1; std::getline(in, l); ++n) out += (n == line ? with : l) + "\n";
  return out;
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

TEST(CliBpt, RendersAPatchFileWithBothPipelines) {
  fs::path dir = scratchDir("cli_bpt_ok");
  std::ofstream(dir / "pot.bpt") << teapot();
  for (const char* p : {"matrix", "motor"}) {
    std::string out;
    int rc = runCommand(motorbench() + "render " + quoted(dir / "pot.bpt") + " --pipeline " + p + " --size 96x72 -o " +
                            quoted(dir / (std::string(p) + ".png")),
                        &out);
    EXPECT_EQ(rc, 0) << out;
    EXPECT_TRUE(fs::exists(dir / (std::string(p) + ".png"))) << out;
  }
  fs::remove_all(dir);
}

TEST(CliBpt, MalformedFilesExit2NamingTheLine) {
  fs::path dir = scratchDir("cli_bpt_bad");
  const std::string good = teapot();
  struct Case {
    std::string file, text, expect;
  } cases[] = {
      {"truncated.bpt", good.substr(0, good.size() / 3), "truncated.bpt: line 1: 32 patches claimed, but the file has"},
      {"degree.bpt", replaceLine(good, 36, "4 4"), "degree.bpt: line 36: patch 3 of 32: degrees 4 4 not supported"},
      {"text.bpt", replaceLine(good, 40, "0.5 spout 1.0"), "text.bpt: line 40: patch 3 of 32, control point 4 of 16: 'spout' is not a number"},
      {"billion.bpt", replaceLine(good, 1, "1000000000"), "billion.bpt: line 1: 1000000000 patches claimed; the limit is"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.file);
    std::ofstream(dir / c.file) << c.text;
    std::string out;
    int rc = runCommand(motorbench() + "render " + quoted(dir / c.file) + " --pipeline motor -o " + quoted(dir / "x.png"), &out);
    EXPECT_EQ(rc, 2) << out;
    EXPECT_NE(out.find(c.expect), std::string::npos) << out;
    EXPECT_FALSE(fs::exists(dir / "x.png"));
  }
  fs::remove_all(dir);
}

}  // namespace
