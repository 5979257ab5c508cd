// JUnit files of the motorbench commands checked as CI would read them: validated against
// tests/cli/junit_schema.xsd (the Jenkins/Ant JUnit format) with python3-xmlschema and read by
// python3-junitparser, both from the system python (scripts/setup.sh installs them).
#pragma once
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/cli_test_support.h"

namespace mb::cli_test {

inline std::string systemPython() { return std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3"; }

// The schema check and the reader, one python process for `files`: per file "tests failures
// errors suite-tests suite-failures suite-errors" as junitparser counts them, or "ERROR <why>" when
// the schema refuses it; one "SKIP <why>" line without the modules (setup.sh installs them).
inline std::vector<std::string> junitCounts(const std::vector<std::filesystem::path>& files) {
  const std::string script =
      "import sys\n"
      "try:\n"
      "    import xmlschema, junitparser\n"
      "except ImportError as e:\n"
      "    print('SKIP', e); sys.exit(0)\n"
      "schema = xmlschema.XMLSchema(sys.argv[1])\n"
      "for f in sys.argv[2:]:\n"
      "    try:\n"
      "        schema.validate(f)\n"
      "    except Exception as e:\n"
      "        print('ERROR', str(e).splitlines()[0]); continue\n"
      "    x = junitparser.JUnitXml.fromfile(f)\n"
      "    cases = [c for s in x for c in s]\n"
      "    kinds = [type(r).__name__ for c in cases for r in c.result]\n"
      "    print(len(cases), kinds.count('Failure'), kinds.count('Error'), x.tests, x.failures, x.errors)\n";
  const std::filesystem::path py = files.front().parent_path() / "junit_counts.py";
  std::ofstream(py) << script;
  std::string command = systemPython() + " " + quoted(py) + " " +
                        quoted(std::filesystem::path(MB_SOURCE_DIR) / "tests" / "cli" / "junit_schema.xsd");
  for (const std::filesystem::path& f : files) command += " " + quoted(f);
  std::string out;
  const int rc = runCommand(command, &out);
  std::vector<std::string> lines;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  if (rc != 0) lines.insert(lines.begin(), "ERROR (rc " + std::to_string(rc) + ") " + out);
  return lines;
}

inline bool junitCheckSkipped(const std::vector<std::string>& counts) {
  return !counts.empty() && counts[0].rfind("SKIP", 0) == 0;
}

}  // namespace mb::cli_test
