// `motorbench`, `motorbench --help` and `motorbench <command> --help`: usage goes to stdout,
// asking for it exits 0, a missing or unknown command exits 2.
#include <gtest/gtest.h>

#include <string>

#include "tests/support/cli_test_support.h"

namespace {

using mb::cli_test::motorbench;
using mb::cli_test::runCommand;

TEST(CliUsage, TopLevelHelpListsEveryCommand) {
  std::string out;
  EXPECT_EQ(runCommand(motorbench() + "--help", &out), 0) << out;
  for (const char* c : {"bench", "check", "claims", "compare", "inspect", "ops", "render", "report", "scenes", "time"})
    EXPECT_NE(out.find(std::string("  ") + c + " "), std::string::npos) << c << " missing from:\n" << out;
  std::string none;
  EXPECT_EQ(runCommand(motorbench(), &none), 2) << none;
}

// The help is the usage line, then options and an example (test_cli_help.cpp);
// nothing runs: none of the lines a run prints (time's machine line, report's progress, bench's
// "Running" line) appears.
TEST(CliUsage, CommandHelpPrintsThatCommandsUsageAndRunsNothing) {
  for (const char* c : {"time", "report", "render", "bench"}) {
    std::string out;
    EXPECT_EQ(runCommand(motorbench() + c + " --help", &out), 0) << c << ": " << out;
    EXPECT_EQ(out.rfind(std::string("usage: motorbench ") + c + " ", 0), 0u) << out;
    for (const char* ran : {"machine:", "report: ", "Running ", "GL_RENDERER"})
      EXPECT_EQ(out.find(ran), std::string::npos) << c << " ran instead of printing its help:\n" << out;
  }
  std::string out;
  EXPECT_EQ(runCommand(motorbench() + "time --frames 3 -h", &out), 0) << out;
  EXPECT_NE(out.find("usage: motorbench time"), std::string::npos) << out;
}

TEST(CliUsage, UnknownCommandIsAnError) {
  std::string out;
  EXPECT_EQ(runCommand(motorbench() + "frobnicate", &out), 2) << out;
  EXPECT_NE(out.find("unknown command 'frobnicate'"), std::string::npos) << out;
}

}  // namespace
