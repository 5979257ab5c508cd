#include "harness/claims/claims_ranking.h"

#include <cmath>
#include <vector>

#include "harness/claims/claims_vertex_ops.h"
#include "harness/figures/figure_statistics.h"
#include "pipelines/pipeline.h"

namespace mb::claims {
namespace {

using json = nlohmann::json;

struct Column {
  const char* name;
  std::map<std::string, double> values;
};

std::vector<Column> columns(const json& isa, const std::string& label) {
  std::string zero;
  Column counted{"counted", opsPerPipeline(label, false, zero)};
  Column spirv{"SPIR-V (probe)", opsPerPipeline(label, true, zero)};
  Column instr{"ISA instructions (median over families)", {}};
  std::map<std::string, std::vector<double>> perPipeline;
  for (const auto& [family, byPipeline] : isaVertexTable(isa, label))
    for (const auto& [p, s] : byPipeline) perPipeline[p].push_back(s.instructions);
  for (const auto& [p, v] : perPipeline) instr.values[p] = figures::quartilesOf(v).median;
  return {counted, spirv, instr};
}

}  // namespace

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

std::string rankingLine(const json& isa, const std::string& label) {
  const std::vector<Column> cols = columns(isa, label);
  std::string out;
  const std::vector<std::string> names = pipelineNames();
  for (size_t i = 0; i < names.size(); ++i)
    for (size_t j = i + 1; j < names.size(); ++j) {
      const std::string &a = names[i], &b = names[j];
      std::string orders;
      int signs = 0;  // bit 0: some column puts a first, bit 1: some column puts b first
      for (const Column& c : cols) {
        if (!c.values.count(a) || !c.values.count(b)) continue;
        const double d = c.values.at(a) - c.values.at(b);
        if (d == 0) continue;
        signs |= d < 0 ? 1 : 2;
        orders += std::string(orders.empty() ? "" : ", ") + (d < 0 ? a + " < " + b : b + " < " + a) + " " + c.name;
      }
      if (signs == 3) out += (out.empty() ? "" : "; ") + orders;
    }
  return out.empty() ? "" : "counted ops, SPIR-V and ISA rank the " + label + " pipelines differently: " + out;
}

Claim rankingClaim(const json& isa, const std::string& label) {
  Claim c{"ops_ranking_" + label, "Speed",
          "the kinds of op evidence order the " + label + " vertex shaders alike (counted, SPIR-V, ISA)"};
  c.paper = "(not claimed)";
  c.origin = "ops evidence";
  c.method = "per pipeline: ops per vertex of the " + label + " shader to clip counted on mb::Counted and in the SPIR-V "
             "probes of its functions, and AMD ISA instructions of the whole vertex shader, the median over families "
             "(motorbench isa); every two pipelines whose order one kind reverses are named";
  const std::vector<Column> cols = columns(isa, label);
  json table = json::object();
  std::string text;
  for (const std::string& p : pipelineNames()) {
    std::string cell;
    for (const Column& col : cols) {
      const bool has = col.values.count(p);
      table[p][col.name] = has ? json(col.values.at(p)) : json();
      cell += (cell.empty() ? "" : " / ") + (has ? fmt("%.0f", col.values.at(p)) : std::string("-"));
    }
    text += (text.empty() ? "" : ", ") + p + " " + cell;
  }
  c.measured = text + " (counted / SPIR-V / ISA)";
  c.measuredValue = {{"table", table}};
  const std::string line = rankingLine(isa, label);
  c.verdict = Verdict::Baseline;
  c.verdictText = line.empty() ? "the three kinds order every two pipelines alike" : line;
  return c;
}

}  // namespace mb::claims
