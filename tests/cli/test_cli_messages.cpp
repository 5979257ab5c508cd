// Messages a user can act on. Each test runs a command as a user typed it and asserts the
// message and the exit status.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "harness/render/image_metrics.h"
#include "pipelines/scene/builtin_scenes.h"
#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::corpusDir;
using mb::cli_test::quoted;
using mb::cli_test::runMb;

// "`inspect /nonexistent.glb` exits 0."
TEST(CliMessages, InspectOfAMissingFileExitsNonZero) {
  const auto r = runMb("inspect /nonexistent.glb");
  EXPECT_EQ(r.rc, 1) << r.out;
  EXPECT_TRUE(contains(r.out, "/nonexistent.glb: no such file")) << r.out;
  EXPECT_TRUE(contains(r.out, "1 of 1 input(s) failed")) << r.out;
  // Every file is still reported: the good one after the bad one is listed too.
  const auto both = runMb("inspect /nonexistent.glb normal_torus");
  EXPECT_EQ(both.rc, 1) << both.out;
  EXPECT_TRUE(contains(both.out, "normal_torus\n  geometry")) << both.out;
  EXPECT_EQ(runMb("inspect normal_torus").rc, 0);
}

// "A folder given as SCENE says 'no such file'." "Unknown scene names do not list the built-ins."
TEST(CliMessages, FolderFileAndUnknownBuiltinAreToldApart) {
  const fs::path dir = mb::cli_test::scratchDir("messages_scene");
  const auto folder = runMb("render " + quoted(dir) + " -o " + quoted(dir / "x.png"));
  EXPECT_EQ(folder.rc, 2) << folder.out;
  EXPECT_TRUE(contains(folder.out, dir.string() + ": is a folder")) << folder.out;
  EXPECT_FALSE(contains(folder.out, "no such file")) << folder.out;
  for (const char* cmd : {"render", "compare"}) {
    const auto unknown = runMb(std::string(cmd) + " normal_tours -o " + quoted(dir / "x.png"));
    EXPECT_EQ(unknown.rc, 2) << unknown.out;
    EXPECT_TRUE(contains(unknown.out, "normal_tours: no such file, and not a built-in scene")) << unknown.out;
    for (const std::string& name : mb::builtinSceneNames()) EXPECT_TRUE(contains(unknown.out, name)) << unknown.out;
  }
  const auto time = runMb("time normal_tours");
  EXPECT_EQ(time.rc, 2) << time.out;
  EXPECT_TRUE(contains(time.out, "not a built-in scene (built-in: normal_torus")) << time.out;
  fs::remove_all(dir);
}

// "`-o` to a folder or a name without extension gives an OpenImageIO message; a missing parent
// folder is not created (compare creates it, render does not)."
TEST(CliMessages, RenderOutputPathsAreCheckedAndParentsCreated) {
  const fs::path dir = mb::cli_test::scratchDir("messages_output");
  const auto toFolder = runMb("render normal_torus -o " + quoted(dir));
  EXPECT_EQ(toFolder.rc, 2) << toFolder.out;
  EXPECT_TRUE(contains(toFolder.out, "-o " + dir.string() + ": is a folder; give a file name such as")) << toFolder.out;
  const auto noExt = runMb("render normal_torus -o " + quoted(dir / "frame"));
  EXPECT_EQ(noExt.rc, 2) << noExt.out;
  EXPECT_TRUE(contains(noExt.out, "no file extension")) << noExt.out;
  const auto badExt = runMb("render normal_torus -o " + quoted(dir / "frame.xyz"));
  EXPECT_EQ(badExt.rc, 2) << badExt.out;
  EXPECT_TRUE(contains(badExt.out, "'.xyz' is not an image format")) << badExt.out;
  // Checked before rendering: no "pipeline:" / frame lines were printed.
  EXPECT_FALSE(contains(badExt.out, "camera:")) << badExt.out;
  const fs::path nested = dir / "new" / "deeper" / "x.png";
  const auto ok = runMb("render normal_torus --size 32x24 -o " + quoted(nested));
  EXPECT_EQ(ok.rc, 0) << ok.out;
  auto img = mb::readImage(nested.string());
  ASSERT_TRUE(img) << img.error();
  EXPECT_EQ(img->width, 32);
  EXPECT_EQ(img->height, 24);
  // compare's -o is a folder: an existing file there is an error, not an overwrite.
  const auto cmpFile = runMb("compare normal_torus -o " + quoted(nested));
  EXPECT_EQ(cmpFile.rc, 2) << cmpFile.out;
  EXPECT_TRUE(contains(cmpFile.out, "is a file; compare writes a folder")) << cmpFile.out;
  fs::remove_all(dir);
}

// "`--size` is checked differently by render and report (report rejects 0x0 with 'expected
// WxH'; `--size 640` silently means 640x640)." Now one rule and one message everywhere.
TEST(CliMessages, SizeIsOneRuleInEveryCommand) {
  const fs::path dir = mb::cli_test::scratchDir("messages_size");
  const std::string rule = "expected WIDTHxHEIGHT, both whole numbers in 1..16384";
  for (const char* size : {"0x0", "640"}) {
    for (const std::string& cmd : {"render normal_torus -o " + quoted(dir / "x.png"),
                                   "compare normal_torus -o " + quoted(dir / "c"), "report normal_torus -o " +
                                   quoted(dir / "r"), std::string("time normal_torus")}) {
      const auto r = runMb(cmd + " --size " + size);
      EXPECT_EQ(r.rc, 2) << cmd << " --size " << size << "\n" << r.out;
      EXPECT_TRUE(contains(r.out, "--size: " + rule + " (e.g. 640x480; a square is 640x640), got '" + size + "'"))
          << cmd << "\n" << r.out;
    }
  }
  EXPECT_FALSE(fs::exists(dir / "r"));
  fs::remove_all(dir);
}

// "Times outside an animation are clamped silently; negative times are accepted."
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

// "`check` run outside the repository suggests `--update` (which would create goldens in the
// wrong place) instead of `--golden DIR`."
TEST(CliMessages, CheckOutsideACheckoutPointsToGolden) {
  const fs::path dir = mb::cli_test::scratchDir("messages_check");
  for (const char* args : {"check", "check --update"}) {
    std::string out;
    const int rc = mb::cli_test::runCommand("cd " + quoted(dir) + " && " + mb::cli_test::motorbench() + args, &out);
    EXPECT_EQ(rc, 2) << args << "\n" << out;
    EXPECT_TRUE(contains(out, "pass --golden DIR")) << out;
    EXPECT_FALSE(contains(out, "run check --update")) << out;
    EXPECT_FALSE(contains(out, "`motorbench check --update` creates it")) << out;
  }
  EXPECT_FALSE(fs::exists(dir / "tests")) << "check --update created goldens outside a checkout";
  fs::remove_all(dir);
}

// "compare's verdict text reads like a failure when no threshold was given; `--hardfail` alone
// reports the default `--fail` reason; `--fail -1` and `--failpercent 500` are accepted;
// `--fail`'s unit (0..1) is undocumented."
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

// "`--bench-json` with a missing file runs the whole report and exits 0."
TEST(CliMessages, ReportBenchJsonMissingFailsBeforeTheRun) {
  const fs::path dir = mb::cli_test::scratchDir("messages_benchjson");
  const auto r = runMb("report normal_torus -o " + quoted(dir / "r") + " --bench-json " + quoted(dir / "missing.json"));
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "--bench-json " + (dir / "missing.json").string() + ": no such file")) << r.out;
  EXPECT_FALSE(contains(r.out, "[1/1]")) << "the run started:\n" << r.out;
  EXPECT_FALSE(fs::exists(dir / "r" / "report.json"));
  fs::remove_all(dir);
}

// "an empty folder yields an empty report with no warning" (and inspect says nothing either).
TEST(CliMessages, EmptyFolderIsWarnedAbout) {
  const fs::path dir = mb::cli_test::scratchDir("messages_empty");
  fs::create_directories(dir / "empty");
  const auto inspect = runMb("inspect " + quoted(dir / "empty"));
  EXPECT_EQ(inspect.rc, 1) << inspect.out;
  EXPECT_TRUE(contains(inspect.out, "warning: " + (dir / "empty").string() + ": folder holds no .gltf or .glb files"))
      << inspect.out;
  const auto time = runMb("time " + quoted(dir / "empty"));
  EXPECT_EQ(time.rc, 2) << time.out;
  EXPECT_TRUE(contains(time.out, "folder holds no .gltf or .glb files")) << time.out;
  const auto report = runMb("report " + quoted(dir / "empty") + " -o " + quoted(dir / "r") +
                            " --no-bench --no-isa --no-plots --frames 0");
  EXPECT_TRUE(contains(report.out, "motorbench report: warning: " + (dir / "empty").string() +
                                       ": folder holds no .gltf or .glb files"))
      << report.out;
  fs::remove_all(dir);
}

}  // namespace
