// The small traps, each as a new user met it: `time` without --pipelines and
// --anim (and silently blending two animations), ratios from one frame with no mark, `bench
// --out` into a missing folder exiting 1 in silence, an unwritable output folder found only
// after the work, a silent `ops`, `help isa` without options, `help help` unknown, `--fail
// 1/255` refused, a legend without numbers; and compare's LDR-FLIP line, map and JSON.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>

#include "harness/render/image_metrics.h"
#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::quoted;
using mb::cli_test::runMb;

// An existing folder this process cannot create a file in (root included: sysfs refuses new
// files); empty when the machine has none.
std::string unwritableFolder() {
  for (const char* dir : {"/sys/kernel", "/proc/self"}) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) continue;
    const std::string probe = std::string(dir) + "/motorbench_probe";
    FILE* f = std::fopen(probe.c_str(), "w");
    if (!f) return dir;
    std::fclose(f);
    fs::remove(probe, ec);
  }
  return "";
}

TEST(CliTraps, TimeTimesThePipelinesAndTheOneAnimationAsked) {
  const fs::path dir = mb::cli_test::scratchDir("traps_time");
  const auto r = runMb("time skinned_tube --pipelines matrix,motor --anim candy_wrapper --frames 6 --warmup 1 "
                       "--size 32x32 --json " + quoted(dir / "t.json"));
  ASSERT_EQ(r.rc, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "skinned_tube: timing animation 2 'candy_wrapper' (3 of ")) << r.out;
  const auto j = mb::cli_test::readJson(dir / "t.json");
  ASSERT_FALSE(j.is_discarded()) << r.out;
  const auto& row = j["results"][0];
  EXPECT_EQ(row["animation"]["index"], 2) << row.dump();
  std::vector<std::string> timed;
  for (const auto& [name, p] : row["pipelines"].items()) timed.push_back(name);  // an object by name
  EXPECT_EQ(timed, (std::vector<std::string>{"matrix", "motor"})) << row.dump();
  // Without --anim: animation 0, said, with the hint that there are others.
  const auto plain = runMb("time skinned_tube --pipelines matrix --frames 1 --warmup 0 --size 16x16");
  EXPECT_EQ(plain.rc, 0) << plain.out;
  EXPECT_TRUE(contains(plain.out, ": timing animation 0 ")) << plain.out;
  EXPECT_TRUE(contains(plain.out, "--anim picks another")) << plain.out;
  // A wrong name is refused before any scene is timed; a wrong animation names the scene's.
  const auto wrong = runMb("time textured_box --pipelines matrix,motr");
  EXPECT_EQ(wrong.rc, 2) << wrong.out;
  EXPECT_TRUE(contains(wrong.out, "--pipelines motr: unknown pipeline")) << wrong.out;
  EXPECT_FALSE(contains(wrong.out, "machine:")) << wrong.out;
  const auto noAnim = runMb("time skinned_tube --pipelines matrix --anim nope --frames 1 --warmup 0 --size 16x16");
  EXPECT_EQ(noAnim.rc, 2) << noAnim.out;
  EXPECT_TRUE(contains(noAnim.out, "--anim nope: no such name")) << noAnim.out;
  fs::remove_all(dir);
}

TEST(CliTraps, OneFrameMarksItsRatiosTooFewFrames) {
  const auto one = runMb("time textured_box --pipelines matrix,motor --frames 1 --warmup 0 --size 16x16");
  ASSERT_EQ(one.rc, 0) << one.out;
  EXPECT_TRUE(contains(one.out, "too few frames (1 < 5)")) << one.out;
  const auto five = runMb("time textured_box --pipelines matrix,motor --frames 5 --warmup 0 --size 16x16");
  ASSERT_EQ(five.rc, 0) << five.out;
  EXPECT_FALSE(contains(five.out, "too few frames")) << five.out;
}

TEST(CliTraps, BenchOutIntoAMissingFolderCreatesIt) {
  const fs::path dir = mb::cli_test::scratchDir("traps_bench");
  const fs::path out = dir / "not" / "yet" / "bench.json";
  const auto r = runMb("bench --out " + quoted(out) + " --benchmark_filter='^compose/motor$' --benchmark_min_time=0.01");
  EXPECT_EQ(r.rc, 0) << r.out;
  EXPECT_TRUE(fs::exists(out)) << r.out;
  EXPECT_FALSE(mb::cli_test::readJson(out).is_discarded());
  fs::remove_all(dir);
}

TEST(CliTraps, AnUnwritableOutputFolderIsRefusedBeforeTheWork) {
  const std::string dir = unwritableFolder();
  if (dir.empty()) GTEST_SKIP() << "no folder here refuses new files";
  struct Case { std::string args, option; };
  for (const Case& c : {Case{"time textured_box --frames 2 --json " + dir + "/t.json", "--json"},
                        Case{"drift --steps 10 --json " + dir + "/d.json", "--json"},
                        Case{"claims --json " + dir + "/c.json", "--json"},
                        Case{"bench --out " + dir + "/b.json", "--out"}}) {
    const auto r = runMb(c.args);
    EXPECT_EQ(r.rc, 2) << c.args << "\n" << r.out;
    EXPECT_TRUE(contains(r.out, c.option + " " + dir + "/")) << r.out;
    EXPECT_TRUE(contains(r.out, "cannot write into folder " + dir)) << r.out;
    EXPECT_FALSE(contains(r.out, "machine:")) << r.out;  // time's header: nothing was measured
    EXPECT_FALSE(contains(r.out, "Camera drift")) << r.out;
  }
}

// ops says where it is (its 4 progress steps): checked on the one full ops run of the suite,
// CliOps.PerVertexSectionHasBothWaysForEveryPipeline (tests/cli/test_cli_bench.cpp).

TEST(CliTraps, HelpIsaAndHelpHelp) {
  const auto isa = runMb("help isa");
  EXPECT_EQ(isa.rc, 0) << isa.out;
  for (const char* part : {"\noptions:\n", "--family F,...", "--json FILE", "--isa-text DIR", "--device", "--jobs N",
                           "\nexample:\n  motorbench isa "})
    EXPECT_TRUE(contains(isa.out, part)) << part << "\n" << isa.out;
  const auto help = runMb("help help");
  EXPECT_EQ(help.rc, 0) << help.out;
  EXPECT_TRUE(contains(help.out, "usage: motorbench help <command>")) << help.out;
  EXPECT_TRUE(contains(help.out, "commands:")) << help.out;
}

// --fail 1/255 as the help writes it (1/0 refused); LDR-FLIP printed, mapped and in
// metrics.json beside PSNR. (The legend's numbers: test_cli_visibility.)
TEST(CliTraps, CompareTakesFractionsAndWritesFlip) {
  const fs::path dir = mb::cli_test::scratchDir("traps_compare");
  const auto r = runMb("compare normal_torus --size 64x64 --fail 1/255 --failpercent 100 -o " + quoted(dir));
  ASSERT_EQ(r.rc, 0) << r.out;
  const auto j = mb::cli_test::readJson(dir / "metrics.json");
  ASSERT_FALSE(j.is_discarded());
  EXPECT_DOUBLE_EQ(j["thresholds"]["fail"].get<double>(), 1.0 / 255.0);
  EXPECT_EQ(runMb("compare normal_torus --size 16x16 --fail 1/0 -o " + quoted(dir / "x")).rc, 2);
  // FLIP: the line, the JSON beside psnr, the map of the frame's size.
  EXPECT_TRUE(contains(r.out, "(LDR-FLIP, 0..1, 67 pixels per degree; map: flip.png)")) << r.out;
  const auto& flip = j["metrics"]["flip"];
  ASSERT_TRUE(flip.is_object()) << j["metrics"].dump();
  EXPECT_GE(flip["mean"].get<double>(), 0.0);
  EXPECT_LE(flip["max"].get<double>(), 1.0);
  EXPECT_LE(flip["mean"].get<double>(), flip["max"].get<double>());
  EXPECT_EQ(j["flipMap"], "flip.png");
  auto map = mb::readImage((dir / "flip.png").string());
  ASSERT_TRUE(map) << map.error();
  EXPECT_EQ(map->width, 64);
  EXPECT_EQ(map->height, 64);
  fs::remove_all(dir);
}

}  // namespace
