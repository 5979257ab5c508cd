// Messages about inputs say what is wrong and never advise harm: a wrong
// --golden folder is named with what a golden folder holds (not "check --update"); inspect of
// files that all failed prints no "0/0 files (0.0 %)"; an empty shard says so; the built-in list
// names the curved scenes.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::quoted;
using mb::cli_test::runMb;

// "`check --golden <wrong folder>` advises `check --update`".
TEST(CliInputText, WrongGoldenFolderIsNamedWithoutAdvisingUpdate) {
  const fs::path dir = mb::cli_test::scratchDir("input_golden");
  const auto r = runMb("check --golden " + quoted(dir) + " --scenes normal_torus --out " + quoted(dir / "out"));
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "--golden " + dir.string() + ": not a golden folder (no golden.json there)")) << r.out;
  EXPECT_TRUE(contains(r.out, "one PNG per scene, pose and pipeline")) << r.out;
  EXPECT_FALSE(contains(r.out, "run check --update")) << r.out;
  EXPECT_FALSE(contains(r.out, "--update` creates it")) << r.out;
  EXPECT_FALSE(fs::exists(dir / "golden.json"));
  fs::remove_all(dir);
}

// "`inspect broken/` prints '0/0 files (0.0 %)'".
TEST(CliInputText, InspectOfOnlyBrokenFilesPrintsNoZeroOverZero) {
  const fs::path dir = mb::cli_test::scratchDir("input_broken");
  std::ofstream(dir / "a.gltf") << "{ not json";
  std::ofstream(dir / "b.glb") << "not a glb";
  const auto r = runMb("inspect " + quoted(dir));
  EXPECT_EQ(r.rc, 1) << r.out;
  EXPECT_TRUE(contains(r.out, "aggregate over 2 files: 0 loaded, 2 failed")) << r.out;
  EXPECT_FALSE(contains(r.out, "0/0 files")) << r.out;
  EXPECT_TRUE(contains(r.out, "- (no file loaded)")) << r.out;
  fs::remove_all(dir);
}

// "an empty shard exits 0 silently".
TEST(CliInputText, AnEmptyShardSaysSo) {
  const fs::path dir = mb::cli_test::scratchDir("input_shard");
  const auto r = runMb("inspect normal_torus textured_box --shard 3/3 --json " + quoted(dir / "s3.json"));
  EXPECT_EQ(r.rc, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "shard 3/3 holds none of the 2 input(s) (more shards than inputs)")) << r.out;
  EXPECT_TRUE(fs::is_regular_file(dir / "s3.json"));
  const auto check = runMb("check --golden " + quoted(fs::path(MB_SOURCE_DIR) / "tests" / "golden") +
                           " --scenes normal_torus --pipelines matrix --shard 2/2 --out " + quoted(dir / "c"));
  EXPECT_EQ(check.rc, 0) << check.out;
  EXPECT_TRUE(contains(check.out, "shard 2/2 holds none of the 1 input(s)")) << check.out;
  const auto report = runMb("report normal_torus --shard 3/3 --frames 0 --no-bench --no-isa --no-plots -o " + quoted(dir / "r"));
  EXPECT_EQ(report.rc, 0) << report.out;
  EXPECT_TRUE(contains(report.out, "warning: shard 3/3 holds none of the 1 input(s)")) << report.out;
  fs::remove_all(dir);
}

// "inspect's built-in list omits s3_tiling/h3_tiling".
TEST(CliInputText, BuiltinListNamesTheCurvedScenes) {
  const auto r = runMb("inspect normal_tours");
  EXPECT_EQ(r.rc, 1) << r.out;
  EXPECT_TRUE(contains(r.out, "not a built-in scene (built-in: normal_torus")) << r.out;
  EXPECT_TRUE(contains(r.out, "s3_tiling, h3_tiling)")) << r.out;
}

}  // namespace
