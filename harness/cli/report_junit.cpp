#include "harness/cli/report_junit.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>

namespace mb {
namespace {

using json = nlohmann::json;
using check::JunitCase;
using check::JunitCounts;
using check::junitCounts;
using Kind = JunitCase::Kind;

std::string text(const json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : "";
}

// The case of pipeline `p` in frame `k` of scene `s`.
JunitCase frameCase(const json& s, const json& frame, size_t k, const std::string& p) {
  JunitCase c{text(s, "id"), "t" + std::to_string(k) + " " + p, 0, Kind::Pass, "", ""};
  if (frame.contains("time") && frame["time"].is_number()) {
    char b[48];
    std::snprintf(b, sizeof b, " (t=%.3f)", frame["time"].get<double>());
    c.name = "t" + std::to_string(k) + b + " " + p;
  }
  const json& pipeline = s.contains("pipelines") && s["pipelines"].contains(p) ? s["pipelines"][p] : json::object();
  const json& errors = frame.value("errors", json::object());
  const json& check = frame.contains("drawnCheck") && frame["drawnCheck"].contains(p) ? frame["drawnCheck"][p] : json();
  if (const std::string e = text(pipeline, "error"); !e.empty()) {
    c.kind = Kind::Error, c.message = p + ": " + e;
  } else if (errors.contains(p)) {
    c.kind = Kind::Error, c.message = errors[p].is_string() ? errors[p].get<std::string>() : errors[p].dump();
  } else if (!frame.value("images", json::object()).contains(p)) {
    c.kind = Kind::Error, c.message = p + ": no image in report.json";
  } else if (check.is_object() && check.value("failed", false)) {
    c.kind = Kind::Fail, c.message = "drawn-pixel check against " + text(check, "against") + ": " + text(check, "reason");
  }
  return c;
}

}  // namespace

std::vector<JunitCase> reportJunitCases(const json& report) {
  std::vector<JunitCase> cases;
  for (const json& s : report.value("scenes", json::array())) {
    const json& frames = s.value("frames", json::array());
    if (frames.empty()) {
      const std::string status = text(s, "status");
      cases.push_back({text(s, "id"), "scene", 0, status == "ok" ? Kind::Pass : Kind::Error,
                       status == "ok" ? "" : text(s, "error").empty() ? "not measured (" + status + ")" : text(s, "error"),
                       ""});
      continue;
    }
    std::vector<std::string> order = s.value("pipelineOrder", std::vector<std::string>{});
    for (size_t k = 0; k < frames.size(); ++k)
      for (const std::string& p : order) cases.push_back(frameCase(s, frames[k], k, p));
  }
  return cases;
}

std::string reportSummaryLine(const json& report, const std::vector<JunitCase>& cases) {
  const json& sum = report.value("summary", json::object());
  const JunitCounts n = junitCounts(cases);
  char b[256];
  std::snprintf(b, sizeof b, "report: %d scenes: %d ok, %d partial, %d failed; %d frames x pipelines: %d passed, %d failed, %d errors",
                sum.value("scenes", 0), sum.value("ok", 0), sum.value("partial", 0), sum.value("failed", 0), n.tests,
                n.tests - n.failures - n.errors - n.skipped, n.failures, n.errors);
  return b;
}

OutputToFile::OutputToFile(const std::string& path) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return;
  std::fflush(stdout);
  std::fflush(stderr);
  saved_[0] = ::fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 0);  // not inherited by the workers
  saved_[1] = ::fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 0);
  ::dup2(fd, STDOUT_FILENO);
  ::dup2(fd, STDERR_FILENO);
  ::close(fd);
}

void OutputToFile::restore() {
  if (saved_[0] < 0) return;
  std::fflush(stdout);
  std::fflush(stderr);
  for (int i = 0; i < 2; ++i) {
    ::dup2(saved_[i], i == 0 ? STDOUT_FILENO : STDERR_FILENO);
    ::close(saved_[i]);
    saved_[i] = -1;
  }
}

OutputToFile::~OutputToFile() { restore(); }

}  // namespace mb
