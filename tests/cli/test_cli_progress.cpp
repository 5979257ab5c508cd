// Long runs show progress with an estimate of the time left: in a log
// (stderr not a terminal, as here) one plain line per finished item.
#include <gtest/gtest.h>

#include <regex>

#include "harness/process/progress.h"
#include "tests/support/cli_test_support.h"

namespace mb::cli_test {
namespace {

TEST(Progress, DurationTextReadsAsAPersonWouldSayIt) {
  EXPECT_EQ(process::durationText(0.4), "0 s");
  EXPECT_EQ(process::durationText(45), "45 s");
  EXPECT_EQ(process::durationText(185), "3 min 05 s");
  EXPECT_EQ(process::durationText(3720), "1 h 02 min");
}

TEST(Progress, CheckAndReportPrintOneLinePerItemWithTimeLeft) {
  const auto dir = scratchDir("progress");
  std::string out;
  runCommand(motorbench() + "check --golden " + quoted(std::filesystem::path(MB_SOURCE_DIR) / "tests" / "golden") +
                 " --scenes textured_box,normal_torus --out " + quoted(dir / "check"), &out);
  EXPECT_TRUE(std::regex_search(out, std::regex("check: 1/2 scenes checked \\((normal_torus|textured_box)\\), [0-9]+ s elapsed, about [0-9]+ s left\n")))
      << out;
  EXPECT_TRUE(std::regex_search(out, std::regex("check: 2/2 scenes checked \\([a-z_]+\\), [0-9]+ s elapsed\n"))) << out;
  EXPECT_EQ(out.find('\r'), std::string::npos);  // not a terminal: no in-place rewriting
  out.clear();
  ASSERT_EQ(runCommand(motorbench() + "report textured_box normal_torus --frames 0 --no-bench --no-isa --no-plots --size 32x24 -o " +
                           quoted(dir / "report"), &out), 0) << out;
  EXPECT_TRUE(std::regex_search(out, std::regex("report: \\[1/2\\] measured textured_box: ok [0-9]+\\.[0-9] s, [0-9]+ s elapsed, about [0-9]+ s left\n")))
      << out;
  EXPECT_NE(out.find("report: [2/2] measured normal_torus: ok "), std::string::npos) << out;
  std::filesystem::remove_all(dir);
}

// bench counts the benchmarks its filter selects (Google Benchmark's list mode) before running
// them: compose has seven sides (matrix, motor, glm, lanes_motor, simd_matrix, simd_affine,
// simd_motor).
TEST(Progress, BenchPrintsOneLinePerBenchmarkWithTimeLeft) {
  std::string out;
  ASSERT_EQ(runCommand(motorbench() + "bench --benchmark_filter=^compose/ --benchmark_min_time=0.001", &out), 0) << out;
  EXPECT_TRUE(std::regex_search(out, std::regex("bench: 1/7 benchmarks run \\(compose/matrix\\), [0-9]+ s elapsed, about [0-9]+ s left\n")))
      << out;
  EXPECT_TRUE(std::regex_search(out, std::regex("bench: 7/7 benchmarks run \\(compose/[a-z_]+\\), [0-9]+ s elapsed\n"))) << out;
  // List mode runs nothing and so shows no progress.
  out.clear();
  ASSERT_EQ(runCommand(motorbench() + "bench --benchmark_filter=^compose/ --benchmark_list_tests", &out), 0) << out;
  EXPECT_EQ(out.find("benchmarks run"), std::string::npos) << out;
}

}  // namespace
}  // namespace mb::cli_test
