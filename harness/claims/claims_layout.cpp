#include "harness/claims/claims_layout.h"

#include <map>
#include <set>

#include "harness/document/report_format.h"

namespace mb::claims {
namespace {

using json = nlohmann::json;

std::string s(const json& v) { return v.is_string() ? v.get<std::string>() : v.is_null() ? "-" : document::dumpJson(v); }

}  // namespace

json claimsJson(const std::vector<Claim>& claims, const json& machine, const json& sources) {
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
  return {{"schema", kClaimsSchema}, {"tool", "motorbench claims"}, {"machine", machine},
          {"sources", sources}, {"counts", counts}, {"paperCounts", paper}, {"ownCounts", own}, {"claims", list}};
}

std::string scopeText(const json& cl) {
  const json& sc = cl.value("scope", json());
  if (!sc.is_object()) return "-";
  return s(sc["stage"]) + "; baseline: " + s(sc["baseline"]) + "; content: " + s(sc["content"]);
}

document::Document claimsDocument(const json& j) {
  document::Document d;
  d.title = "Claims of \"Look, Ma, No Matrices!\" judged by motorbench";
  json m = j.contains("machine") && j["machine"].is_object() ? j["machine"] : json::object();
  d.paragraph("Each row below is declared once (harness/claims/claim_table.h): what it states, its scope (stage, "
              "baseline, content), the figures it reads by name and its rule. `motorbench claims` measures nothing: "
              "it applies the rules to the figures of a run (" + s(m["cpu"]) + ", " + s(m["logicalCores"]) +
              " logical cores, " + s(m["date"]) + "). claims.json gives every figure with what it is: counted (the "
              "op-counting scalar), compiled (SPIR-V; RADV's null-device statistics, not timed), measured (uploads, "
              "images, Google Benchmark and frame times) or modelled (meshoptimizer's vertex-fetch model), with its n "
              "and statistic. Several kinds of evidence combine one way: every kind passes, reproduced; none, differs; "
              "some, inconclusive; a kind without its figure, disturbed or on too few samples is left out and named.");
  auto tally = [](const json& c) {
    return s(c["reproduced"]) + " reproduced, " + s(c["differs"]) + " differ, " + s(c.value("inconclusive", json(0))) +
           " inconclusive, " + s(c["not measurable here"]) + " not measurable here";
  };
  d.paragraph("The paper's claims (each quotes its sentence or table row; a table row printed as a pair, such as "
              "gp_rt / gp_tr, counts once): " + tally(j["paperCounts"]) + ". Our own rows (marked with their kind): " +
              tally(j["ownCounts"]) + ", " + s(j["ownCounts"]["baseline"]) + " baselines.");
  d.heading(2, "Verdicts", "verdicts");
  std::vector<std::string> lines;
  for (const json& cl : j["claims"])
    lines.push_back("`" + s(cl["id"]) + "`" + (cl.value("origin", "paper") == "paper" ? "" : " (" + s(cl["origin"]) + ")") +
                    " " + s(cl["statement"]) + " [" + scopeText(cl) + "]" +
                    (cl.value("quote", json()).is_string() ? " — paper: " + s(cl["quote"]) : std::string()) + ": " +
                    s(cl["verdictText"]));
  d.bullets(lines);
  std::vector<std::string> order;  // sections in first-seen order
  std::map<std::string, std::vector<const json*>> bySection;
  for (const json& cl : j["claims"]) {
    const std::string sec = s(cl["section"]);
    if (!bySection.count(sec)) order.push_back(sec);
    bySection[sec].push_back(&cl);
  }
  for (const std::string& sec : order) {
    d.heading(2, sec);
    std::vector<std::vector<document::Cell>> rows;
    for (const json* cl : bySection[sec]) {
      const json& rule = cl->value("rule", json());
      rows.push_back({{s((*cl)["id"])}, {s(cl->value("origin", json("paper")))}, {s((*cl)["statement"])}, {scopeText(*cl)},
                      {s((*cl)["paper"])}, {s((*cl)["measured"])}, {rule.is_object() ? s(rule["text"]) : "-"},
                      {s((*cl)["verdictText"])}, {s(cl->value("note", json()))}});
    }
    d.table({"id", "origin", "claim", "scope", "paper", "measured", "rule", "verdict", "note"}, rows);
  }
  std::vector<std::string> src;
  for (const auto& [k, v] : j["sources"].items()) src.push_back(k + ": " + s(v));
  d.heading(2, "Sources of this run");
  d.bullets(src);
  return d;
}

}  // namespace mb::claims
