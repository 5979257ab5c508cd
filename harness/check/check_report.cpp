#include "harness/check/check_report.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "harness/render/render_frame.h"
#include "harness/document/report_format.h"

namespace mb::check {
namespace {

using document::html;

std::string metricsText(const ImageMetrics& m, const FlipResult& flip) {
  if (m.rmse == 0.0) return "identical";
  char buf[200];
  std::snprintf(buf, sizeof buf, "PSNR %.2f dB, max %.0f/255 at (%d,%d), >1/255 %.3f%%, >4/255 %.3f%%",
                m.psnr, std::round(m.maxError * 255.0), m.maxX, m.maxY, 100 * m.fractionOver1,
                100 * m.fractionOver4);
  return std::string(buf) + "; " + flipText(flip);
}

std::string image(const std::string& file, const char* caption) {
  if (file.empty()) return "<td>(none)</td>";
  return "<td><a href=\"" + html(file) + "\"><img src=\"" + html(file) + "\" alt=\"" + caption +
         "\"></a><br>" + caption + "</td>";
}

}  // namespace

const char* outcomeName(CheckItem::Outcome o) {
  switch (o) {
    case CheckItem::Outcome::Pass: return "PASS";
    case CheckItem::Outcome::Warn: return "WARN";
    case CheckItem::Outcome::Fail: return "FAIL";
    case CheckItem::Outcome::Error: return "ERROR";
    case CheckItem::Outcome::Changed: return "CHANGED";
  }
  return "?";
}

std::string changedLine(const ChangedSource& c) {
  return "CHANGED  " + c.path + ": changed since its goldens were recorded (sha256 " + c.recorded.substr(0, 12) +
         "..., now " + c.now.substr(0, 12) + "...): its " + std::to_string(c.images) +
         " images not judged; look at the change, then run check --update to record its goldens again";
}

namespace {

std::array<int, CheckItem::kOutcomes> outcomeCounts(const CheckRun& run) {
  std::array<int, CheckItem::kOutcomes> n{};
  for (const CheckItem& it : run.items) ++n[size_t(it.outcome)];
  return n;
}

}  // namespace

std::string summaryLine(const CheckRun& run) {
  const auto n = outcomeCounts(run);
  char b[256];
  std::snprintf(b, sizeof b, "check: %zu images: %d passed, %d warned, %d failed, %d errors", run.items.size(), n[0],
                n[1], n[2], n[3]);
  std::string line = b;
  if (!run.changed.empty())
    line += "; " + std::to_string(run.changed.size()) +
            (run.changed.size() == 1 ? " file changed since its goldens were" : " files changed since their goldens were") +
            " recorded (" + std::to_string(n[4]) + " images not judged)";
  return line;
}

int exitCode(const CheckRun& run) {
  const auto n = outcomeCounts(run);
  if (n[size_t(CheckItem::Outcome::Error)] > 0) return 2;
  return n[size_t(CheckItem::Outcome::Fail)] > 0 || !run.changed.empty() ? 1 : 0;
}

std::vector<JunitCase> junitCases(const CheckRun& run) {
  using Kind = JunitCase::Kind;
  std::vector<JunitCase> cases;
  for (const CheckItem& it : run.items) {
    JunitCase c;
    c.classname = it.source.empty() ? it.scene : it.source;
    c.name = it.pose + "." + it.pipeline;
    c.seconds = it.seconds;
    c.kind = it.outcome == CheckItem::Outcome::Fail || it.outcome == CheckItem::Outcome::Changed ? Kind::Fail
             : it.outcome == CheckItem::Outcome::Error                                           ? Kind::Error
                                                                                                 : Kind::Pass;
    if (c.kind == Kind::Pass) {
      cases.push_back(std::move(c));
      continue;
    }
    c.message = it.reason;
    c.detail = "golden " + it.file;
    if (it.compared) c.detail += "\n[" + it.level + "] " + metricsText(it.metrics, it.flip);
    for (const std::string* f : {&it.expected, &it.actual, &it.diff, &it.flipMap})
      if (!f->empty()) c.detail += "\n" + *f;
    cases.push_back(std::move(c));
  }
  return cases;
}

std::string consoleLine(const CheckItem& it) {
  std::string s = std::string(outcomeName(it.outcome)) + "  " + it.file;
  if (it.compared) s += "  [" + it.level + "] " + metricsText(it.metrics, it.flip);
  if (!it.reason.empty()) s += "  -- " + it.reason;
  return s;
}

Status writeCheckReport(const std::string& dir, const CheckRun& run) {
  namespace fs = std::filesystem;
  const auto counts = outcomeCounts(run);

  std::string h =
      "<!doctype html><html><head><meta charset=\"utf-8\"><title>motorbench check</title><style>"
      "body{font-family:sans-serif;margin:1em}table{border-collapse:collapse}"
      "td,th{border:1px solid #ccc;padding:4px;vertical-align:top;text-align:center}"
      "img{width:320px;image-rendering:pixelated}.FAIL,.ERROR{color:#b00}.WARN{color:#a60}"
      ".PASS{color:#070}td.l{text-align:left}</style></head><body><h1>motorbench check</h1>\n";
  char counts_text[160];
  std::snprintf(counts_text, sizeof counts_text, "%d passed, %d warned, %d failed, %d errors, %d not judged (file changed)",
                counts[0], counts[1], counts[2], counts[3], counts[4]);
  h += "<p><b>" + std::string(counts_text) + "</b></p><p>goldens: " + html(run.goldenDir) +
       "<br>shaders: " + html(run.shaderDir) + "<br>GL_RENDERER: " + html(run.glRenderer) +
       "<br>GL_VERSION: " + html(run.glVersion) + "</p>\n";
  for (const std::string& n : run.notes) h += "<p class=\"WARN\">warning: " + html(n) + "</p>\n";

  if (!run.changed.empty()) {
    h += "<h2 class=\"FAIL\">Files changed since their goldens were recorded (not judged)</h2>\n<ul>\n";
    for (const ChangedSource& c : run.changed) h += "<li>" + html(changedLine(c).substr(9)) + "</li>\n";
    h += "</ul>\n";
  }
  h += "<h2>Failures, errors and warnings</h2>\n";
  bool any = false;
  for (const CheckItem& it : run.items) {
    if (it.outcome == CheckItem::Outcome::Pass || it.outcome == CheckItem::Outcome::Changed) continue;
    any = true;
    const char* name = outcomeName(it.outcome);
    h += "<h3 class=\"" + std::string(name) + "\">" + name + " " + html(it.file) + "</h3><p>" +
         html(it.reason) + (it.compared ? "<br>[" + html(it.level) + "] " + html(metricsText(it.metrics, it.flip)) : "") +
         "</p>\n<table><tr>" + image(it.expected, "expected (golden)") +
         image(it.actual, "actual") + image(it.diff, "diff (blue 1 step .. white 64+)") +
         image(it.flipMap, "LDR-FLIP (magma: black 0 .. yellow 1)") +
         "</tr></table>\n";
  }
  if (!any) h += "<p>none</p>\n";

  h += "<h2>All images</h2>\n<table><tr><th>result</th><th>image</th><th>thresholds</th>"
       "<th>metrics</th></tr>\n";
  for (const CheckItem& it : run.items) {
    const char* name = outcomeName(it.outcome);
    h += "<tr><td class=\"" + std::string(name) + "\">" + name + "</td><td class=\"l\">" +
         html(it.file) + "</td><td>" + html(it.level) + "</td><td class=\"l\">" +
         (it.compared ? html(metricsText(it.metrics, it.flip)) : html(it.reason)) + "</td></tr>\n";
  }
  h += "</table></body></html>\n";

  const std::string htmlPath = (fs::path(dir) / "summary.html").string();
  std::ofstream out(htmlPath);
  out << h;
  if (!out.good()) return Status::fail(htmlPath + ": write failed");

  nlohmann::json j = {{"golden", run.goldenDir}, {"shaders", run.shaderDir},
                      {"gl", {{"renderer", run.glRenderer}, {"version", run.glVersion}}},
                      {"notes", run.notes},
                      {"counts", {{"pass", counts[0]}, {"warn", counts[1]}, {"fail", counts[2]},
                                  {"error", counts[3]}, {"changed", counts[4]}}},
                      {"images", nlohmann::json::array()}, {"shard", run.shard},
                      {"changedFiles", nlohmann::json::array()}};
  for (const ChangedSource& c : run.changed)
    j["changedFiles"].push_back({{"scene", c.scene}, {"path", c.path}, {"recordedSha256", c.recorded},
                                 {"sha256", c.now}, {"images", c.images}});
  for (const CheckItem& it : run.items) {
    nlohmann::json e = {{"file", it.file}, {"scene", it.scene}, {"source", it.source}, {"pipeline", it.pipeline},
                        {"pose", it.pose}, {"outcome", outcomeName(it.outcome)},
                        {"level", it.level}, {"reason", it.reason}, {"expected", it.expected},
                        {"actual", it.actual}, {"diff", it.diff}, {"flipMap", it.flipMap}};
    if (it.compared) e["metrics"] = toJson(it.metrics, it.flip);
    j["images"].push_back(e);
  }
  const std::string jsonPath = (fs::path(dir) / "check.json").string();
  std::ofstream js(jsonPath);
  js << j.dump(2) << "\n";
  if (!js.good()) return Status::fail(jsonPath + ": write failed");
  return {};
}

}  // namespace mb::check
