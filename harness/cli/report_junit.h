// `motorbench report --junit FILE` and `--quiet`, read from the finished report.json: one JUnit
// case per scene x frame x pipeline (classname the scene, name "t<k> <pipeline>"): an error
// where the pipeline or the frame could not be measured (report.json pipelines[].error,
// frames[].errors), a failure where compare's drawn-pixel check failed (frames[].drawnCheck: one
// image empty or the drawn pixels more than 1 % apart), a scene that failed before any frame one
// error case of its own. The report has no image thresholds: the pixel figures are its findings.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/check/junit.h"

namespace mb {

std::vector<check::JunitCase> reportJunitCases(const nlohmann::json& report);

// "report: 3 scenes: 2 ok, 1 partial, 0 failed; 81 frames x pipelines: 80 passed, 0 failed, 1 errors".
std::string reportSummaryLine(const nlohmann::json& report, const std::vector<check::JunitCase>& cases);

// stdout and stderr (this process's and its workers') into a file while it lives: --quiet.
class OutputToFile {
public:
  explicit OutputToFile(const std::string& path);  // ok() false when the file cannot be made
  ~OutputToFile();  // restores stdout and stderr
  bool ok() const { return saved_[0] >= 0; }
  void restore();

private:
  int saved_[2] = {-1, -1};
};

}  // namespace mb
