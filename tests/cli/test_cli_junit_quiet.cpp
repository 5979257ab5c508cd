// --junit and --quiet on diff, compare and report (check's: test_cli_check_files.cpp): --quiet
// prints the failures and the summary line only, and the JUnit file passes the JUnit schema
// (tests/cli/junit_schema.xsd) with the counts junitparser reads equal to the verdicts.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/support/cli_test_support.h"
#include "tests/support/junit_check.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::junitCheckSkipped;
using mb::cli_test::junitCounts;
using mb::cli_test::quoted;
using mb::cli_test::readText;
using mb::cli_test::runMb;

const fs::path kGolden = fs::path(MB_SOURCE_DIR) / "tests" / "golden";

int lineCount(const std::string& text) { return int(std::count(text.begin(), text.end(), '\n')); }

TEST(CliJunitQuiet, DiffCompareAndReportPrintTheVerdictOnlyAndWriteValidJunit) {
  const fs::path root = mb::cli_test::scratchDir("junit_quiet");
  const std::string a = quoted(kGolden / "crowd.rest.matrix.png"), b = quoted(kGolden / "crowd.rest.motor.png");
  // diff: two different goldens fail with any difference allowed by nothing.
  auto r = runMb("diff " + a + " " + b + " --quiet --junit " + quoted(root / "diff.xml"));
  EXPECT_EQ(r.rc, 1) << r.out;
  EXPECT_EQ(lineCount(r.out), 1) << r.out;
  EXPECT_TRUE(contains(r.out, "crowd.rest.motor.png -> FAIL (")) << r.out;
  const std::string diffXml = readText(root / "diff.xml");
  EXPECT_TRUE(contains(diffXml, "<testcase classname=\"diff\" name=\"")) << diffXml;
  EXPECT_TRUE(contains(diffXml, "<failure message=\"")) << diffXml;
  r = runMb("diff " + a + " " + a + " --quiet");
  EXPECT_EQ(r.rc, 0) << r.out;
  EXPECT_EQ(lineCount(r.out), 1) << r.out;
  // compare: the verdict line only (no notes on stderr, no figures).
  r = runMb("compare textured_box --size 32x32 --fail 2/255 --quiet --junit " + quoted(root / "compare.xml") + " -o " +
            quoted(root / "compare"));
  EXPECT_EQ(r.rc, 0) << r.out;
  EXPECT_EQ(lineCount(r.out), 1) << r.out;
  EXPECT_TRUE(contains(r.out, "matrix vs motor -> PASS")) << r.out;
  EXPECT_TRUE(contains(readText(root / "compare.xml"), "<testcase classname=\"textured_box\" name=\"matrix vs motor rest\""));
  // report: a file that does not load is one error case; the run's output goes to the log.
  std::ofstream(root / "empty.glb").close();
  r = runMb("report " + quoted(root / "empty.glb") + " --frames 0 --no-bench --no-isa --no-plots -o " +
            quoted(root / "report") + " --quiet --junit " + quoted(root / "report.xml"));
  EXPECT_EQ(r.rc, 1) << r.out;
  EXPECT_EQ(lineCount(r.out), 2) << r.out;
  EXPECT_TRUE(contains(r.out, "ERROR  empty scene: ")) << r.out;
  EXPECT_TRUE(contains(r.out, "empty file (0 bytes)")) << r.out;
  EXPECT_TRUE(contains(r.out, "report: 1 scenes: 0 ok, 0 partial, 1 failed; 1 frames x pipelines: 0 passed, 0 failed, "
                              "1 errors -> ")) << r.out;
  EXPECT_TRUE(contains(readText(root / "report" / "report-log.txt"), "scene(s) not measured fully (exit 1)"));

  const auto counts = junitCounts({root / "diff.xml", root / "compare.xml", root / "report.xml"});
  if (junitCheckSkipped(counts)) GTEST_SKIP() << counts[0];
  ASSERT_EQ(counts.size(), 3u) << ::testing::PrintToString(counts);
  EXPECT_EQ(counts[0], "1 1 0 1 1 0");
  EXPECT_EQ(counts[1], "1 0 0 1 0 0");
  EXPECT_EQ(counts[2], "1 0 1 1 0 1");
  fs::remove_all(root);
}

}  // namespace
