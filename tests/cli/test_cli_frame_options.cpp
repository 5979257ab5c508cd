// Which frame render and compare draw, and that they say so: --anim, --time (alone it poses
// animation 0; past the end it is clamped and noted; negative or repeated it is refused) and
// --camera (a glTF camera by name or index), with the animation, time, camera, size and
// pipeline printed on stderr and recorded in compare's metrics.json.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "harness/render/image_metrics.h"
#include "pipelines/scene/loader.h"
#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::corpusDir;
using mb::cli_test::kCameraGltf;
using mb::cli_test::quoted;
using mb::cli_test::runMb;

bool sameImage(const fs::path& a, const fs::path& b) {
  auto x = mb::readImage(a.string()), y = mb::readImage(b.string());
  return x && y && x->width == y->width && x->height == y->height && x->rgba == y->rgba;
}

// render and compare print the animation, time, camera, size and pipeline they drew; a glTF
// camera is named by index, name and type, and an unknown one lists the file's cameras.
TEST(CliFrameOptions, RenderAndComparePrintAnimationTimeAndCamera) {
  const fs::path dir = mb::cli_test::scratchDir("visibility_frame");
  const auto r = runMb("render skinned_tube --anim 0 --time 0.25 --size 64x64 -o " + quoted(dir / "x.png"));
  ASSERT_EQ(r.rc, 0) << r.out;
  const std::string animName = [] {
    auto scene = mb::loadScene("skinned_tube");
    return scene && !scene->animations.empty() ? scene->animations[0].name : std::string("?");
  }();
  EXPECT_TRUE(contains(r.out, "motorbench render: animation 0 '" + animName + "' (1 of ")) << r.out;
  EXPECT_TRUE(contains(r.out, "at t = 0.25 s")) << r.out;
  EXPECT_TRUE(contains(r.out, "motorbench render: camera: automatic framing")) << r.out;
  EXPECT_TRUE(contains(r.out, "motorbench render: size: 64x64")) << r.out;
  EXPECT_TRUE(contains(r.out, "motorbench render: pipeline: matrix (the default)")) << r.out;
  const auto rest = runMb("compare skinned_tube --size 64x64 -o " + quoted(dir / "c"));
  ASSERT_EQ(rest.rc, 0) << rest.out;
  EXPECT_TRUE(contains(rest.out, "motorbench compare: rest pose (no --anim/--time; the scene has")) << rest.out;

  // A glTF camera by name: its index, name and type; an orthographic one on no node says what
  // is drawn instead.
  fs::path file = dir / "camera.gltf";
  std::ofstream(file) << kCameraGltf;
  const auto cam = runMb("render " + quoted(file) + " --camera Cam --size 64x64 -o " + quoted(dir / "cam.png"));
  ASSERT_EQ(cam.rc, 0) << cam.out;
  EXPECT_TRUE(contains(cam.out, "camera: glTF camera 0 'Cam' (perspective)")) << cam.out;
  const auto ortho = runMb("render " + quoted(file) + " --camera 1 --size 64x64 -o " + quoted(dir / "o.png"));
  ASSERT_EQ(ortho.rc, 0) << ortho.out;
  EXPECT_TRUE(contains(ortho.out, "camera: glTF camera 1 'Ortho' (orthographic, drawn as perspective) is on no node: "
                                  "automatic framing instead"))
      << ortho.out;
  const auto badCam = runMb("render " + quoted(file) + " --camera Nope -o " + quoted(dir / "n.png"));
  EXPECT_EQ(badCam.rc, 2) << badCam.out;
  EXPECT_TRUE(contains(badCam.out, "(names: 'Cam', 'Ortho')")) << badCam.out;
  fs::remove_all(dir);
}

// render --time without --anim poses animation 0 at that time, says so on stderr, and draws the
// same image as --anim 0 --time 1.5, not the rest pose; a scene without animations refuses it.
TEST(CliOptions, RenderTimeWithoutAnimPosesTheFirstAnimation) {
  const fs::path corpus = corpusDir();
  if (corpus.empty()) GTEST_SKIP() << "no ../shared/corpus";
  const fs::path dir = mb::cli_test::scratchDir("options_time");
  const std::string box = quoted(corpus / "BoxAnimated.gltf");
  const auto timed = runMb("render " + box + " --time 1.5 -o " + quoted(dir / "t.png"));
  ASSERT_EQ(timed.rc, 0) << timed.out;
  EXPECT_TRUE(contains(timed.out, "--time without --anim: using animation 0")) << timed.out;
  EXPECT_TRUE(contains(timed.out, "at t = 1.5 s")) << timed.out;
  ASSERT_EQ(runMb("render " + box + " -o " + quoted(dir / "rest.png")).rc, 0);
  ASSERT_EQ(runMb("render " + box + " --anim 0 --time 1.5 -o " + quoted(dir / "a0.png")).rc, 0);
  EXPECT_FALSE(sameImage(dir / "t.png", dir / "rest.png")) << "--time 1.5 drew the rest pose";
  EXPECT_TRUE(sameImage(dir / "t.png", dir / "a0.png")) << "--time alone must equal --anim 0 --time 1.5";
  // A scene without animations rejects --time instead of ignoring it.
  const auto still = runMb("render normal_torus --time 1.5 -o " + quoted(dir / "s.png"));
  EXPECT_EQ(still.rc, 2) << still.out;
  EXPECT_TRUE(contains(still.out, "has no animations")) << still.out;
  fs::remove_all(dir);
}

// compare --time without --anim poses animation 0, and metrics.json records that animation
// beside the time.
TEST(CliOptions, CompareTimeWithoutAnimRecordsThePosedAnimation) {
  const fs::path corpus = corpusDir();
  if (corpus.empty()) GTEST_SKIP() << "no ../shared/corpus";
  const fs::path dir = mb::cli_test::scratchDir("options_compare_time");
  const std::string box = quoted(corpus / "BoxAnimated.gltf");
  const auto r = runMb("compare " + box + " --time 0.5 -o " + quoted(dir / "c"));
  ASSERT_EQ(r.rc, 0) << r.out;
  const auto j = mb::cli_test::readJson(dir / "c" / "metrics.json");
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j["settings"]["anim"], 0);
  EXPECT_DOUBLE_EQ(j["settings"]["time"].get<double>(), 0.5);
  EXPECT_EQ(j["animation"]["index"], 0);
  ASSERT_EQ(runMb("render " + box + " --anim 0 --time 0.5 --pipeline matrix -o " + quoted(dir / "m.png")).rc, 0);
  EXPECT_TRUE(sameImage(dir / "c" / "matrix.png", dir / "m.png")) << "compare's frame is not the posed one";
  fs::remove_all(dir);
}

// A repeated --time is refused with the reason (one frame per run), and the usage line does not
// suggest repeating it.
TEST(CliOptions, RepeatedTimeIsRejected) {
  const fs::path dir = mb::cli_test::scratchDir("options_repeat");
  for (const char* cmd : {"render", "compare"}) {
    const auto r = runMb(std::string(cmd) + " skinned_tube --time 0.5 --time 1 -o " + quoted(dir / "x.png"));
    EXPECT_EQ(r.rc, 2) << r.out;
    EXPECT_TRUE(contains(r.out, "option --time given twice ('0.5', '1')")) << r.out;
    EXPECT_TRUE(contains(r.out, "once per time")) << r.out;
    const auto help = runMb(std::string(cmd) + " --help");
    EXPECT_FALSE(contains(help.out, "--time T ...")) << help.out;
  }
  fs::remove_all(dir);
}

// A negative --time is refused; a time past the end of the animation is clamped to its end and
// said, and metrics.json records the time drawn.
TEST(CliMessages, TimesPastTheEndAreNotedAndNegativeTimesRejected) {
  const fs::path dir = mb::cli_test::scratchDir("messages_times");
  const auto neg = runMb("render skinned_tube --anim 0 --time -1 -o " + quoted(dir / "n.png"));
  EXPECT_EQ(neg.rc, 2) << neg.out;
  EXPECT_TRUE(contains(neg.out, "--time: expected a time in seconds >= 0, got '-1'")) << neg.out;
  EXPECT_FALSE(fs::exists(dir / "n.png"));
  const auto late = runMb("compare skinned_tube --anim 0 --time 1000 -o " + quoted(dir / "c"));
  ASSERT_EQ(late.rc, 0) << late.out;
  EXPECT_TRUE(contains(late.out, "--time 1000 is past the end of animation 0")) << late.out;
  EXPECT_TRUE(contains(late.out, "clamped")) << late.out;
  const auto j = mb::cli_test::readJson(dir / "c" / "metrics.json");
  ASSERT_FALSE(j.is_discarded());
  // metrics.json records the time drawn: the animation's end.
  EXPECT_DOUBLE_EQ(j["settings"]["time"].get<double>(), j["animation"]["duration"].get<double>());
  EXPECT_LT(j["animation"]["duration"].get<double>(), 1000.0);
  fs::remove_all(dir);
}

}  // namespace
