// Output paths are checked (missing folders created, as render does) before the
// work, in every command that writes; a file-like name for a folder output, a folder for a file
// output and a missing merge input are refused clearly.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::quoted;
using mb::cli_test::runMb;

// "`time ... --json t4/time.json` measures everything, then 'cannot write t4/time.json'."
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

// "`claims ... --json t10/x/claims.json` fails the same way after 3 minutes."
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

// "`compare -o out.png` makes a folder named out.png."
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

// "`merge -o dir/` says only 'cannot write'; merging a missing path says 'every input must be a
// report folder' instead of 'not found'."
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

}  // namespace
