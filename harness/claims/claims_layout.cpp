#include "harness/claims/claims_layout.h"

#include <map>
#include <set>

#include "harness/document/report_format.h"

namespace mb::claims {
namespace {

using json = nlohmann::json;

std::string s(const json& v) { return v.is_string() ? v.get<std::string>() : v.is_null() ? "-" : report::dumpJson(v); }

}  // namespace

json claimsJson(const std::vector<Claim>& claims, const json& machine, const json& sources, const json& scope) {
  json list = json::array();
  const json zero = {{"reproduced", 0}, {"differs", 0}, {"inconclusive", 0}, {"not measurable here", 0}, {"baseline", 0}};
  json counts = zero, paper = zero, own = zero;
  std::set<std::string> tallied;  // a table row printed as a pair (gp_rt / gp_tr) counts once
  for (const Claim& c : claims) {
    list.push_back(toJson(c));
    if (!tallied.insert(c.tallyAs.empty() ? c.id : c.tallyAs).second) continue;
    const std::string v = verdictName(c.verdict);
    counts[v] = counts[v].get<int>() + 1;
    json& side = originOf(c) == "paper" ? paper : own;
    side[v] = side[v].get<int>() + 1;
  }
  return {{"schema", kClaimsSchema}, {"tool", "motorbench claims"}, {"machine", machine}, {"scope", scope},
          {"sources", sources}, {"counts", counts}, {"paperCounts", paper}, {"ownCounts", own}, {"claims", list}};
}

report::Document claimsDocument(const json& j) {
  report::Document d;
  d.title = "Claims of \"Look, Ma, No Matrices!\" measured by motorbench";
  // The machine block is the report's (claims measures nothing given a report); a report without
  // one (a hand-made input) leaves every field "-" instead of failing.
  json m = j.contains("machine") && j["machine"].is_object() ? j["machine"] : json::object();
  d.paragraph("Every measured value below comes from a run of `motorbench claims` on " + s(m["cpu"]) + " (" +
              s(m["logicalCores"]) + " logical cores), " + s(m["os"]) + ", " + s(m["date"]) +
              ": op counts by executing the kernels on an op-counting scalar, bytes from the buffers the "
              "pipelines uploaded, times from Google Benchmark and frame timing. Paper values are the "
              "paper's text; verdicts compare the two.");
  auto tally = [](const json& c) {
    return s(c["reproduced"]) + " reproduced, " + s(c["differs"]) + " differ, " + s(c.value("inconclusive", json(0))) +
           " inconclusive, " + s(c["not measurable here"]) + " not measurable here";
  };
  if (j.contains("paperCounts")) {
    d.paragraph("The paper's claims (each row quotes the sentence or table row it tests; a table row printed as a "
                "pair, such as gp_rt / gp_tr, counts once): " + tally(j["paperCounts"]) + ". Our own rows (no sentence "
                "of the paper: reviewer baselines, the motor against the strongest matrix variant, curved space, "
                "skinning volume, blending; marked \"own\" below): " + tally(j["ownCounts"]) + ", " +
                s(j["ownCounts"]["baseline"]) + " baselines.");
  } else {
    d.paragraph(tally(j["counts"]) + "; " + s(j["counts"]["baseline"]) + " reviewer baselines.");
  }
  const json& scope = j.value("scope", json());
  if (scope.is_object())
    d.paragraph("CPU verdicts (kernel times, update times, composition timing) hold for the CPU they were measured on: " +
                s(scope["cpu"]) + "; another CPU can rank the implementations differently. Frame times were measured on " +
                s(scope["frameTimeDevice"]) + ".");
  d.heading(2, "Verdicts", "verdicts");
  std::vector<std::string> lines;
  for (const json& cl : j["claims"])
    lines.push_back("`" + s(cl["id"]) + "`" + (cl.value("origin", "paper") == "paper" ? "" : " (" + s(cl["origin"]) + ")") +
                    " " + s(cl["statement"]) + (cl.value("quote", json()).is_string() ? " — paper: " + s(cl["quote"]) : std::string()) +
                    ": " + s(cl["verdictText"]) + " (paper: " +
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
      rows.push_back({{s((*cl)["id"])}, {s(cl->value("origin", json("paper")))}, {s((*cl)["statement"])}, {s((*cl)["paper"])}, {s((*cl)["measured"])},
                      {s((*cl)["method"])}, {s((*cl)["verdictText"])}});
    d.table({"id", "origin", "claim", "paper", "measured", "how it was measured", "verdict"}, rows);
  }
  std::vector<std::string> src;
  for (const auto& [k, v] : j["sources"].items()) src.push_back(k + ": " + s(v));
  d.heading(2, "Sources of this run");
  d.bullets(src);
  return d;
}

}  // namespace mb::claims
