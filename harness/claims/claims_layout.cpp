#include "harness/claims/claims_layout.h"

#include <map>

#include "harness/document/report_format.h"

namespace mb::claims {
namespace {

using json = nlohmann::json;

std::string s(const json& v) { return v.is_string() ? v.get<std::string>() : v.is_null() ? "-" : report::dumpJson(v); }

}  // namespace

json claimsJson(const std::vector<Claim>& claims, const json& machine, const json& sources) {
  json list = json::array();
  json counts = {{"reproduced", 0}, {"differs", 0}, {"inconclusive", 0}, {"not measurable here", 0}, {"baseline", 0}};
  for (const Claim& c : claims) {
    list.push_back(toJson(c));
    counts[verdictName(c.verdict)] = counts[verdictName(c.verdict)].get<int>() + 1;
  }
  return {{"schema", kClaimsSchema}, {"tool", "motorbench claims"}, {"machine", machine},
          {"sources", sources}, {"counts", counts}, {"claims", list}};
}

report::Document claimsDocument(const json& j) {
  report::Document d;
  d.title = "Claims of \"Look, Ma, No Matrices!\" measured by motorbench";
  const json& m = j["machine"];
  d.paragraph("Every measured value below comes from a run of `motorbench claims` on " + s(m["cpu"]) + " (" +
              s(m["logicalCores"]) + " logical cores), " + s(m["os"]) + ", " + s(m["date"]) +
              ": op counts by executing the kernels on an op-counting scalar, bytes from the buffers the "
              "pipelines uploaded, times from Google Benchmark and frame timing. Paper values are the "
              "paper's text; verdicts compare the two.");
  const json& c = j["counts"];
  d.paragraph(s(c["reproduced"]) + " reproduced, " + s(c["differs"]) + " differ, " + s(c.value("inconclusive", json(0))) +
              " inconclusive, " + s(c["not measurable here"]) +
              " not measurable here; " + s(c["baseline"]) + " reviewer baselines.");
  d.heading(2, "Verdicts", "verdicts");
  std::vector<std::string> lines;
  for (const json& cl : j["claims"])
    lines.push_back("`" + s(cl["id"]) + "` " + s(cl["statement"]) + ": " + s(cl["verdictText"]) + " (paper: " +
                    s(cl["paper"]) + "; measured: " + s(cl["measured"]) + ")");
  d.bullets(lines);
  // Sections in first-seen order.
  std::vector<std::string> order;
  std::map<std::string, std::vector<const json*>> bySection;
  for (const json& cl : j["claims"]) {
    const std::string sec = s(cl["section"]);
    if (!bySection.count(sec)) order.push_back(sec);
    bySection[sec].push_back(&cl);
  }
  for (const std::string& sec : order) {
    d.heading(2, sec);
    std::vector<std::vector<report::Cell>> rows;
    for (const json* cl : bySection[sec])
      rows.push_back({{s((*cl)["id"])}, {s((*cl)["statement"])}, {s((*cl)["paper"])}, {s((*cl)["measured"])},
                      {s((*cl)["method"])}, {s((*cl)["verdictText"])}});
    d.table({"id", "claim", "paper", "measured", "how it was measured", "verdict"}, rows);
  }
  std::vector<std::string> src;
  for (const auto& [k, v] : j["sources"].items()) src.push_back(k + ": " + s(v));
  d.heading(2, "Sources of this run");
  d.bullets(src);
  return d;
}

}  // namespace mb::claims
