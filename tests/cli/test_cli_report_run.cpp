// `motorbench report` as a run a user stops, repeats and reads: Ctrl-C (SIGINT) leaves a folder
// that says it is partial (exit 130); a second run into the folder leaves nothing of the first and
// refuses a folder of the user's; a report of files runs no kernel benchmark unless asked, takes
// its ISA evidence from the cache (or says why there is none), and prints its answer on stdout.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "harness/report/report_isa_run.h"
#include "tests/support/cli_test_support.h"

namespace mb::cli_test {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

const char* const kTiny = " --frames 0 --no-plots --size 32x32 --pipelines matrix,motor";

// The first line of report.md after its title.
std::string firstLineAfterTitle(const fs::path& md) {
  std::ifstream in(md);
  std::string line;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') return line;
  return "";
}

TEST(CliReportRun, InterruptedAfterItsFirstSceneTheFolderSaysPartialAndExits130) {
  const auto dir = scratchDir("report_interrupt");
  const fs::path out = dir / "r", err = dir / "err.txt";
  // Started in the background; SIGINT once the first scene's progress line is out.
  const std::string script =
      motorbench() + "report textured_box normal_torus skinned_tube scaled_hierarchy teapot" + kTiny +
      " --no-bench --no-isa -o " + quoted(out) + " 2> " + quoted(err) + " & pid=$!; "
      "for i in $(seq 1 3000); do grep -q 'report: \\[1/5\\] measured' " + quoted(err) + " 2>/dev/null && break; sleep 0.01; done; "
      "kill -INT $pid; wait $pid; echo rc=$?";
  std::ofstream(dir / "run.sh") << script << "\n";
  std::string shell;
  runCommand("bash " + cli_test::quoted(dir / "run.sh"), &shell);
  const std::string log = readText(err);
  ASSERT_NE(shell.find("rc=130"), std::string::npos) << shell << log;
  EXPECT_NE(log.find("INTERRUPTED (SIGINT): "), std::string::npos) << log;
  EXPECT_NE(log.find("exit 130"), std::string::npos) << log;
  // The marker stays and says how far it got; the documents open with the same.
  ASSERT_TRUE(fs::exists(out / "PARTIAL"));
  EXPECT_NE(readText(out / "PARTIAL").find("INTERRUPTED"), std::string::npos);
  EXPECT_EQ(firstLineAfterTitle(out / "report.md").rfind("INTERRUPTED: ", 0), 0u) << readText(out / "report.md");
  EXPECT_NE(readText(out / "report.html").find("INTERRUPTED: "), std::string::npos);
  const json r = readJson(out / "report.json");
  ASSERT_TRUE(r.contains("interrupted")) << r.dump().substr(0, 400);
  EXPECT_EQ(r["interrupted"]["scenes"], 5);
  EXPECT_GE(r["interrupted"]["measured"].get<int>(), 1);
  EXPECT_LT(r["interrupted"]["measured"].get<int>(), 5);
  fs::remove_all(dir);
}

TEST(CliReportRun, ASecondRunRemovesTheFirstRunsFilesAndKeepsTheUsers) {
  const auto dir = scratchDir("report_rerun");
  const fs::path out = dir / "r";
  std::string log;
  ASSERT_EQ(runCommand(motorbench() + "report textured_box" + kTiny + " --no-bench --no-isa -o " + quoted(out), &log), 0) << log;
  ASSERT_TRUE(fs::exists(out / "images" / "textured_box"));
  EXPECT_FALSE(fs::exists(out / "PARTIAL"));  // complete: the marker went
  std::ofstream(out / "notes.txt") << "mine\n";
  log.clear();
  ASSERT_EQ(runCommand(motorbench() + "report normal_torus" + kTiny + " --no-bench --no-isa -o " + quoted(out), &log), 0) << log;
  EXPECT_FALSE(fs::exists(out / "images" / "textured_box")) << "a stale image folder of the first run";
  EXPECT_TRUE(fs::exists(out / "images" / "normal_torus"));
  EXPECT_EQ(readText(out / "notes.txt"), "mine\n");
  const json r = readJson(out / "report.json");
  ASSERT_EQ(r["scenes"].size(), 1u);
  EXPECT_EQ(r["scenes"][0]["id"], "normal_torus");
  // A folder of the user's that no report wrote: refused, its files named and left as they were.
  const fs::path own = dir / "own";
  fs::create_directories(own / "images");
  std::ofstream(own / "holiday.png") << "x";
  log.clear();
  EXPECT_EQ(runCommand(motorbench() + "report textured_box" + kTiny + " --no-bench --no-isa -o " + quoted(own), &log), 2) << log;
  EXPECT_NE(log.find("holds files that are not a report's: holiday.png"), std::string::npos) << log;
  EXPECT_TRUE(fs::exists(own / "images"));
  EXPECT_TRUE(fs::exists(own / "holiday.png"));
  fs::remove_all(dir);
}

// A hand-made ISA document (one family, the rigid shader of each side), cached under the key this
// build of motorbench computes: the report reads it instead of compiling.
json handIsa() {
  auto shader = [](const char* pipeline, int instructions) {
    return json{{"pipeline", pipeline}, {"program", "rigid"}, {"variant", "rigid"}, {"labels", {"rigid"}},
                {"family", "tahiti"}, {"familyId", "tahiti"}, {"stage", "vertex"}, {"instructions", instructions},
                {"vgprs", 20}, {"sgprs", 30}, {"wavesPerSimd", 10}};
  };
  return {{"schema", "motorbench-isa/1"}, {"driver", "hand-made"},
          {"families", {{{"id", "tahiti"}, {"family", "tahiti"}, {"generation", "GCN 1"}}}},
          {"shaders", {shader("matrix", 100), shader("motor", 90)}}};
}

TEST(CliReportRun, AFileReportRunsNoBenchTakesItsIsaFromTheCacheAndPrintsTheAnswer) {
  const auto dir = scratchDir("report_file_defaults");
  std::string log;
  ASSERT_EQ(runCommand(motorbench() + "scenes -o " + quoted(dir / "in") + " textured_box", &log), 0) << log;
  // The entry goes under a driver manifest of the test's own (a key no real run has), in the
  // cache the SPIR-V counts already use, and is removed after.
  const fs::path icd = dir / "test_icd.json";
  std::ofstream(icd) << "{}\n";
  setenv("VK_DRIVER_FILES", icd.c_str(), 1);
  const std::string key = report::isaCacheKey(MB_MOTORBENCH_EXE);
  const fs::path entry = report::isaCacheFile(key);
  unsetenv("VK_DRIVER_FILES");
  ASSERT_FALSE(entry.empty()) << "no cache folder (MB_CACHE_DIR=off?)";
  fs::create_directories(entry.parent_path());
  std::ofstream(entry) << json{{"key", key}, {"isa", handIsa()}}.dump();
  const fs::path out = dir / "r";
  std::string stdoutText;
  const int rc = runCommand("(VK_DRIVER_FILES=" + quoted(icd) + " " + motorbench() + "report " +
                           quoted(dir / "in" / "textured_box.glb") + kTiny + " -o " + quoted(out) + " 2> " +
                           quoted(dir / "err.txt") + ")",
                       &stdoutText);
  fs::remove(entry);
  ASSERT_EQ(rc, 0) << readText(dir / "err.txt");
  EXPECT_NE(readText(dir / "err.txt").find("AMD ISA: read from the cache"), std::string::npos) << readText(dir / "err.txt");
  const json r = readJson(out / "report.json");
  EXPECT_EQ(r["kernels"]["source"], "skipped");
  EXPECT_NE(r["kernels"]["error"].get<std::string>().find("--bench"), std::string::npos) << r["kernels"];
  EXPECT_FALSE(fs::exists(out / "bench.json"));
  EXPECT_EQ(r["isa"], handIsa());
  EXPECT_EQ(r["isaSource"]["source"], "cache");
  // stdout: the answer block's lines, then where the report is.
  EXPECT_EQ(stdoutText.rfind("The answer: ", 0), 0u) << stdoutText;
  // The hand-made ISA's one family: motor 90 / matrix 100 instructions = 0.9, within the 1.1 rule.
  EXPECT_NE(stdoutText.find("1 families (RADV null device, compiled, not timed): instructions 0.9x as cheap"),
            std::string::npos) << stdoutText;
  EXPECT_NE(stdoutText.find("\n  time: not measured (--frames 0: no frame was timed)"), std::string::npos) << stdoutText;
  EXPECT_NE(stdoutText.find("report: " + (out / "report.html").string()), std::string::npos) << stdoutText;
  EXPECT_NE(readText(out / "report.md").find("not measured (--frames 0: no frame was timed)"), std::string::npos);
  fs::remove_all(dir);
}

TEST(CliReportRun, WithoutRadvTheReportIsWrittenAndSaysWhyTheIsaIsMissing) {
  const auto dir = scratchDir("report_no_radv");
  std::string log;
  ASSERT_EQ(runCommand("VK_DRIVER_FILES=" + quoted(dir / "none.json") + " " + motorbench() +
                           "report textured_box" + kTiny + " --no-bench -o " + quoted(dir / "r"), &log),
            0)
      << log;
  const json r = readJson(dir / "r" / "report.json");
  ASSERT_TRUE(r["isa"].contains("error")) << r["isa"].dump().substr(0, 300);
  EXPECT_EQ(r["isa"]["error"].get<std::string>().rfind("not measured: motorbench isa exit status 2", 0), 0u) << r["isa"];
  EXPECT_NE(log.find("  AMD ISA per family: not measured: motorbench isa exit status 2"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir / "r" / "isa.json"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mb::cli_test
