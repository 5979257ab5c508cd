// Output paths are checked before the work, in every command that writes: missing folders are
// created (render, compare, time, bench, claims, inspect, merge), a folder that cannot be made or
// written into is refused before anything is loaded, drawn, timed or judged, and a file-like name
// for a folder output, a folder for a file output and a missing merge input are refused clearly.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "harness/render/image_metrics.h"
#include "tests/support/cli_parallel.h"
#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::quoted;
using mb::cli_test::Ran;
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

// render's -o: a folder, a name without extension or an unknown image format is refused before
// rendering, with the reason; missing parent folders are created; compare's -o on an existing
// file is refused, not overwritten.
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

// compare -o with a file-like name (out.png) is refused, suggesting a folder name; report -o on
// a file is refused before any scene is measured.
TEST(CliOutputs, CompareRefusesAFileLikeFolderName) {
  const fs::path dir = mb::cli_test::scratchDir("outputs_compare");
  const auto r = runMb("compare normal_torus -o " + quoted(dir / "out.png"));
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "-o " + (dir / "out.png").string() + ": looks like a file name, but this command "
                              "writes a folder (A.png, B.png, diff.png")) << r.out;
  EXPECT_TRUE(contains(r.out, "such as " + (dir / "out").string())) << r.out;
  EXPECT_FALSE(fs::exists(dir / "out.png"));
  EXPECT_FALSE(contains(r.out, "camera:")) << "rendered before refusing:\n" << r.out;
  // report -o on a file: refused before any scene is measured.
  std::ofstream(dir / "plain") << "x";
  const auto rep = runMb("report textured_box --no-bench --no-isa --frames 0 -o " + quoted(dir / "plain"));
  EXPECT_EQ(rep.rc, 2) << rep.out;
  EXPECT_TRUE(contains(rep.out, "is a file; this command writes a folder (report.json")) << rep.out;
  EXPECT_FALSE(contains(rep.out, "[1/1]")) << rep.out;
  fs::remove_all(dir);
}

// time --json creates missing folders, and refuses a file where a folder must be, or a folder
// as the file, before anything is timed.
TEST(CliOutputs, TimeCreatesTheJsonFolderAndRefusesBeforeTiming) {
  const fs::path dir = mb::cli_test::scratchDir("outputs_time");
  const fs::path json = dir / "t4" / "deeper" / "time.json";
  const auto ok = runMb("time normal_torus --frames 2 --warmup 0 --json " + quoted(json));
  EXPECT_EQ(ok.rc, 0) << ok.out;
  EXPECT_TRUE(fs::is_regular_file(json)) << ok.out;
  // A file where a folder must be: refused first, nothing timed.
  std::ofstream(dir / "plain") << "x";
  const auto bad = runMb("time normal_torus --frames 2 --warmup 0 --json " + quoted(dir / "plain" / "time.json"));
  EXPECT_EQ(bad.rc, 2) << bad.out;
  EXPECT_TRUE(contains(bad.out, "--json " + (dir / "plain" / "time.json").string() + ": ")) << bad.out;
  EXPECT_TRUE(contains(bad.out, "is a file, not a folder")) << bad.out;
  EXPECT_FALSE(contains(bad.out, "machine:")) << "timed before refusing:\n" << bad.out;
  const auto folder = runMb("time normal_torus --json " + quoted(dir) + "/");
  EXPECT_EQ(folder.rc, 2) << folder.out;
  EXPECT_TRUE(contains(folder.out, "is a folder; it writes one file")) << folder.out;
  fs::remove_all(dir);
}

TEST(CliOutputs, BenchOutIntoAMissingFolderCreatesIt) {
  const fs::path dir = mb::cli_test::scratchDir("traps_bench");
  const fs::path out = dir / "not" / "yet" / "bench.json";
  const auto r = runMb("bench --out " + quoted(out) + " --benchmark_filter='^compose/motor$' --benchmark_min_time=0.01");
  EXPECT_EQ(r.rc, 0) << r.out;
  EXPECT_TRUE(fs::exists(out)) << r.out;
  EXPECT_FALSE(mb::cli_test::readJson(out).is_discarded());
  fs::remove_all(dir);
}

// claims' -o and --json and inspect's --json are checked before judging or inspecting: missing
// folders made, a file where a folder must be or a folder as the file refused.
TEST(CliOutputs, ClaimsAndInspectCheckTheirFilesFirst) {
  const fs::path dir = mb::cli_test::scratchDir("outputs_claims");
  std::ofstream(dir / "plain") << "x";
  // A run's folder claims can judge (a report.json without figures: every row not measurable).
  fs::create_directories(dir / "run");
  std::ofstream(dir / "run" / "report.json") << R"({"figures": {}})";
  const std::string results = "claims --results " + quoted(dir / "run") + " ";
  for (const char* option : {"--json", "-o"}) {
    const auto r = runMb(results + option + " " + quoted(dir / "plain" / "x" / "claims.json"));
    EXPECT_EQ(r.rc, 2) << r.out;
    EXPECT_TRUE(contains(r.out, std::string(option) + " " + (dir / "plain").string())) << r.out;
    EXPECT_FALSE(contains(r.out, " rows; ")) << "judged before refusing:\n" << r.out;
  }
  // Missing folders are made, as render does.
  const auto made = runMb(results + "-o " + quoted(dir / "new" / "claims.md") + " --json " +
                          quoted(dir / "new" / "deeper" / "claims.json"));
  EXPECT_EQ(made.rc, 0) << made.out;
  EXPECT_TRUE(fs::is_regular_file(dir / "new" / "claims.md")) << made.out;
  EXPECT_TRUE(fs::is_regular_file(dir / "new" / "deeper" / "claims.json")) << made.out;
  // inspect: missing folders are made, a folder is refused.
  const fs::path json = dir / "new" / "dir" / "x.json";
  const auto ok = runMb("inspect normal_torus --json " + quoted(json));
  EXPECT_EQ(ok.rc, 0) << ok.out;
  EXPECT_TRUE(fs::is_regular_file(json)) << ok.out;
  const auto folder = runMb("inspect normal_torus --json " + quoted(dir / "new"));
  EXPECT_EQ(folder.rc, 2) << folder.out;
  EXPECT_TRUE(contains(folder.out, "is a folder; it writes one file")) << folder.out;
  EXPECT_FALSE(contains(folder.out, "geometry")) << "inspected before refusing:\n" << folder.out;
  fs::remove_all(dir);
}

// ops and isa write one --json file: a folder there, or a file where a folder must be, is refused
// before anything is counted or compiled.
TEST(CliOutputs, OpsAndIsaCheckTheirJsonFirst) {
  const fs::path dir = mb::cli_test::scratchDir("outputs_ops_isa");
  std::ofstream(dir / "plain") << "x";
  for (const char* command : {"ops", "isa"}) {
    const auto r = runMb(std::string(command) + " --json " + quoted(dir / "plain" / "x.json"));
    EXPECT_EQ(r.rc, 2) << command << "\n" << r.out;
    EXPECT_TRUE(contains(r.out, "--json " + (dir / "plain" / "x.json").string() + ": ")) << r.out;
    EXPECT_TRUE(contains(r.out, "is a file, not a folder")) << r.out;
    EXPECT_FALSE(contains(r.out, "Arithmetic per kernel")) << "counted before refusing:\n" << r.out;
    EXPECT_FALSE(contains(r.out, "instructions")) << "compiled before refusing:\n" << r.out;
    const auto folder = runMb(std::string(command) + " --json " + quoted(dir));
    EXPECT_EQ(folder.rc, 2) << folder.out;
    EXPECT_TRUE(contains(folder.out, "is a folder; it writes one file")) << folder.out;
  }
  fs::remove_all(dir);
}

// merge -o on a folder says why it cannot write there (it writes one file for inspect --json
// inputs); a missing input is named as not found.
TEST(CliOutputs, MergeSaysWhyItCannotWriteAndWhatIsMissing) {
  const fs::path dir = mb::cli_test::scratchDir("outputs_merge");
  for (int i : {1, 2}) {
    const auto s = runMb("inspect normal_torus textured_box --shard " + std::to_string(i) + "/2 --json " +
                         quoted(dir / ("s" + std::to_string(i) + ".json")));
    ASSERT_EQ(s.rc, 0) << s.out;
  }
  const std::string shards = quoted(dir / "s1.json") + " " + quoted(dir / "s2.json");
  const auto toFolder = runMb("merge " + shards + " -o " + quoted(dir) + "/");
  EXPECT_EQ(toFolder.rc, 2) << toFolder.out;
  EXPECT_TRUE(contains(toFolder.out, "is a folder; it writes one file")) << toFolder.out;
  EXPECT_TRUE(contains(toFolder.out, "merging inspect --json files writes one JSON file")) << toFolder.out;
  const auto merged = runMb("merge " + shards + " -o " + quoted(dir / "m" / "all.json"));
  EXPECT_EQ(merged.rc, 0) << merged.out;
  EXPECT_TRUE(fs::is_regular_file(dir / "m" / "all.json"));
  const auto missing = runMb("merge " + quoted(dir / "s1.json") + " " + quoted(dir / "nope") + " -o " +
                             quoted(dir / "x.json"));
  EXPECT_EQ(missing.rc, 2) << missing.out;
  EXPECT_TRUE(contains(missing.out, (dir / "nope").string() + ": not found")) << missing.out;
  EXPECT_FALSE(contains(missing.out, "every input must be")) << missing.out;
  fs::remove_all(dir);
}

// Each command that writes late checks its outputs first: a folder that cannot be made is refused
// before the scene is loaded or drawn.
TEST(CliOutputs, OutputPathsAreCheckedBeforeAnyWork) {
  const fs::path dir = mb::cli_test::scratchDir("traps_outputs");
  const std::string mb = mb::cli_test::motorbench();
  const std::vector<Ran> ran = mb::cli_test::runAll(
      dir, {mb + "render textured_box --size 16x16 -o /proc/nope/x.png",
            mb + "survey textured_box --size 16x16 -o /proc/nope/x.json",
            mb + "check --scenes normal_torus --pipelines matrix --golden " + quoted(fs::path(MB_SOURCE_DIR) / "tests/golden") +
                " --out /proc/nope"});
  const char* const options[] = {"-o /proc/nope/x.png", "-o /proc/nope/x.json", "--out /proc/nope"};
  for (size_t i = 0; i < ran.size(); ++i) {
    EXPECT_EQ(ran[i].rc, 2) << ran[i].out;
    EXPECT_TRUE(contains(ran[i].out, std::string(options[i]) + ": cannot create folder /proc/nope")) << ran[i].out;
    for (const char* work : {"camera:", "drawn pixels", "\"frames\"", "golden images"})
      EXPECT_FALSE(contains(ran[i].out, work)) << work << "\n" << ran[i].out;
  }
  fs::remove_all(dir);
}

TEST(CliOutputs, AnUnwritableOutputFolderIsRefusedBeforeTheWork) {
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

}  // namespace
