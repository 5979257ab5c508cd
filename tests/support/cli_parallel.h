// Runs many command lines at once from one shell (each motorbench or idiff process costs ~0.2 s
// to start, mostly its shared libraries): the exit status and output of each, in order.
#pragma once
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/support/cli_test_support.h"

namespace mb::cli_test {

struct Ran {
  int rc = -1;          // -1: it did not finish
  std::string out;      // stdout and stderr together
};

// Each of `commands` in the background in `dir` (its working folder; its files run<i>.out/.rc
// go there), then waits for all.
inline std::vector<Ran> runAll(const std::filesystem::path& dir, const std::vector<std::string>& commands) {
  std::string script = "cd " + quoted(dir) + "\n";
  for (size_t i = 0; i < commands.size(); ++i) {
    const std::string n = std::to_string(i);
    script += "( " + commands[i] + " > run" + n + ".out 2>&1; echo $? > run" + n + ".rc ) &\n";
  }
  script += "wait\n";
  std::ofstream(dir / "run.sh") << script;
  std::string ignored;
  runCommand("bash " + quoted(dir / "run.sh"), &ignored);
  std::vector<Ran> ran(commands.size());
  for (size_t i = 0; i < commands.size(); ++i) {
    const std::string n = std::to_string(i);
    const std::string rc = readText(dir / ("run" + n + ".rc"));
    ran[i].rc = rc.empty() ? -1 : std::stoi(rc);
    ran[i].out = readText(dir / ("run" + n + ".out"));
  }
  return ran;
}

}  // namespace mb::cli_test
