#include "harness/claims/claims_ranking.h"

#include "harness/document/ops_ranking.h"

namespace mb::claims {

using json = nlohmann::json;

IsaTable isaVertexTable(const json& isa, const std::string& program) {
  IsaTable plain, normalMapped;
  if (!isa.is_object() || !isa.value("shaders", json()).is_array()) return {};
  for (const json& s : isa["shaders"]) {
    if (s.value("stage", "") != "vertex" || !s.value("instructions", json()).is_number()) continue;
    const std::string prog = s.value("program", "");
    if (prog != program && prog != program + "_normalmap") continue;
    const std::string family = s.value("family", "?") + (s.value("ngg", false) ? " (NGG)" : "");
    IsaStats st{s["instructions"].get<double>(), s.value("vgprs", 0.0), s.value("wavesPerSimd", 0.0)};
    (prog == program ? plain : normalMapped)[family][s.value("pipeline", "")] = st;
  }
  for (auto& [family, byPipeline] : normalMapped)
    for (auto& [p, st] : byPipeline) plain[family][p] = st;  // the normal-mapped form where there is one
  return plain;
}

std::string disagreementLine(const json& scope) {
  return scope.is_object() && !scope.value("reversed", json::array()).empty() ? scope.value("line", "") : "";
}

Claim rankingClaim(const json& scope, const std::string& label, const std::string& source) {
  Claim c{"ops_ranking_" + label, "Speed",
          "counted ops, SPIR-V (probe) ops and AMD ISA instructions order the " + label + " vertex shaders alike"};
  c.paper = "(not claimed)";
  c.origin = "ops evidence";
  if (!scope.is_object() || !scope.value("line", json()).is_string()) {
    c.verdict = Verdict::NotMeasurable;
    c.verdictText = "not measurable here: no opsRanking." + label + " in " + source;
    return c;
  }
  std::string defs;
  for (const json& m : scope.value("measures", json::array()))
    defs += "; " + m.value("name", "") + ": " + m.value("definition", "") + " (" + m.value("device", "") + ")";
  c.method = "the ranking of " + source + ", scope " + scope.value("scope", label) + defs +
             "; a pair is named where one measure orders it one way and another the other way (ties order nothing)";
  c.measured = report::opsRankingTableText(scope);
  c.measuredValue = {{"table", scope.value("table", json())}, {"ranks", scope.value("ranks", json())},
                     {"reversed", scope.value("reversed", json())}, {"pairs", scope.value("pairs", json())}};
  c.verdict = Verdict::Baseline;
  c.verdictText = scope["line"].get<std::string>();
  return c;
}

}  // namespace mb::claims
