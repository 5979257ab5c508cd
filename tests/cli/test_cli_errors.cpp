// Errors about inputs name the input and the reason: a missing file, a folder given as a
// scene, an unknown built-in name (with the list of built-in scenes, the curved ones
// included), a folder holding no glTF files.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pipelines/scene/builtin_scenes.h"
#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::quoted;
using mb::cli_test::runMb;

// A missing file is named with the reason, counted as a failed input (exit 1), and the inputs
// after it are still inspected.
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

// A folder given as a scene is named as a folder; an unknown name says it is neither a file nor
// a built-in scene and lists the built-in names.
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

// inspect's list of built-in names includes the curved scenes.
TEST(CliInputText, BuiltinListNamesTheCurvedScenes) {
  const auto r = runMb("inspect normal_tours");
  EXPECT_EQ(r.rc, 1) << r.out;
  EXPECT_TRUE(contains(r.out, "not a built-in scene (built-in: normal_torus")) << r.out;
  EXPECT_TRUE(contains(r.out, "s3_tiling, h3_tiling)")) << r.out;
}

// A folder without .gltf or .glb files is warned about by inspect, time and report.
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
