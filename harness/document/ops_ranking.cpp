#include "harness/document/ops_ranking.h"

#include <cmath>
#include <map>
#include <set>
#include <vector>

#include "harness/document/report_figures.h"
#include "harness/document/report_format.h"
#include "harness/document/report_isa.h"
#include "harness/document/report_layout_common.h"
#include "harness/figures/figure.h"

namespace mb::document {
namespace {

using json = nlohmann::json;
using layout::str;

struct Scope {
  const char* label;  // the ops room's and the isa room's variant label
  const char* name;   // as printed
};
const Scope kScopes[] = {{"rigid", "rigid vertex to clip"}, {"skinned", "skinned vertex (4 joints) to clip"}};

std::string isaDevice(const json& isa) {
  std::string families;
  for (const json& f : at(isa, {"families"}).is_array() ? isa["families"] : json::array())
    families += (families.empty() ? "" : ", ") + f.value("id", "?") + " (" + f.value("generation", "?") + ")";
  return "RADV null device (" + str(at(isa, {"driver"}), "Mesa") + "), not timed: " + families;
}

// The three measures of one scope: {key: {pipeline: value}} (values > 0 only: 0 means not joined).
std::map<std::string, std::map<std::string, double>> measure(const json& variants, const json& isa, const std::string& label,
                                                             std::vector<std::string>& pipelines) {
  std::map<std::string, std::map<std::string, double>> v;
  for (const json& row : variants.is_array() ? variants : json::array()) {
    if (row.value("variant", "") != label) continue;
    const std::string p = row.value("pipeline", "");
    pipelines.push_back(p);
    if (const double c = opsTotal(row.value("counted", json())); c > 0) v["counted"][p] = c;
    if (const double s = opsTotal(row.value("spirv_kernel_probes", json())); s > 0) v["spirv_probe"][p] = s;
    std::vector<double> perFamily;
    for (const json& f : at(isa, {"families"}).is_array() ? isa["families"] : json::array())
      if (const json* r = isaRow(isa, p, label, f.value("id", "")))
        if (const double n = figures::numberOrNaN(r->value("instructions", json())); n > 0) perFamily.push_back(n);
    if (!perFamily.empty()) v["isa"][p] = figures::quartilesOf(perFamily).median;
  }
  return v;
}

json measures(const json& isa) {
  const size_t families = at(isa, {"families"}).is_array() ? isa["families"].size() : 0;
  return json::array(
      {{{"key", "counted"}, {"name", "counted ops"}, {"short", "counted"},
        {"definition", "mul + add + div + sqrt + other of the functions the vertex shader calls, executed once on the "
                       "op-counting scalar through the GLSL shim (subtraction counts as addition, negation is free)"},
        {"device", "op-counting scalar (mb::Counted)"}},
       {{"key", "spirv_probe"}, {"name", "SPIR-V probe ops"}, {"short", "SPIR-V probe"},
        {"definition", "the same total counted in the SPIR-V of those functions compiled alone (glslangValidator, "
                       "spirv-opt -O, vector and matrix instructions expanded to scalar operations)"},
        {"device", "SPIR-V probe: the transform functions compiled alone"}},
       {{"key", "isa"}, {"name", "AMD ISA instructions (median over " + std::to_string(families) + " families)"},
        {"short", "ISA"},
        {"definition", "instructions of the whole compiled vertex shader (main() included), the median over the GPU "
                       "families of motorbench isa"},
        {"device", isaDevice(isa)}}});
}

// Dense ranks, 1 = cheapest; equal values share a rank.
std::map<std::string, int> ranksOf(const std::map<std::string, double>& values) {
  std::set<double> distinct;
  for (const auto& [p, x] : values) distinct.insert(x);
  std::map<std::string, int> out;
  for (const auto& [p, x] : values) out[p] = int(std::distance(distinct.begin(), distinct.find(x))) + 1;
  return out;
}

std::string joinedAnd(const std::vector<std::string>& items) {
  std::string out;
  for (size_t i = 0; i < items.size(); ++i)
    out += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
  return out;
}

json rankScope(const json& variants, const json& isa, const Scope& s) {
  std::vector<std::string> pipelines;
  const auto values = measure(variants, isa, s.label, pipelines);
  const json defs = measures(isa);
  json out = {{"scope", s.name}, {"measures", defs}, {"pipelines", pipelines}, {"table", json::object()},
              {"ranks", json::object()}, {"reversed", json::array()}};
  std::vector<std::string> present;
  for (const json& m : defs) {
    const std::string key = m["key"];
    const auto it = values.find(key);
    if (it == values.end()) continue;
    present.push_back(m["name"]);
    for (const auto& [p, rank] : ranksOf(it->second)) out["ranks"][key][p] = rank;
  }
  for (const std::string& p : pipelines)
    for (const json& m : defs) {
      const std::string key = m["key"];
      const auto it = values.find(key);
      out["table"][p][key] = it != values.end() && it->second.count(p) ? json(it->second.at(p)) : json();
    }
  int pairs = 0;
  std::string listed;
  for (size_t i = 0; i < pipelines.size(); ++i)
    for (size_t j = i + 1; j < pipelines.size(); ++j) {
      const std::string &a = pipelines[i], &b = pipelines[j];
      std::vector<std::string> aFirst, bFirst;
      int measured = 0;
      json cheaper = json::object();
      for (const json& m : defs) {
        const auto it = values.find(m["key"].get<std::string>());
        if (it == values.end() || !it->second.count(a) || !it->second.count(b)) continue;
        ++measured;
        const double d = it->second.at(a) - it->second.at(b);
        if (d == 0) continue;
        cheaper[m["key"].get<std::string>()] = d < 0 ? a : b;
        (d < 0 ? aFirst : bFirst).push_back(m["short"]);
      }
      if (measured >= 2) ++pairs;
      if (aFirst.empty() || bFirst.empty()) continue;
      out["reversed"].push_back({{"a", a}, {"b", b}, {"cheaper", cheaper}});
      listed += (listed.empty() ? "" : "; ") + a + " vs " + b + ": " + a + " cheaper by " + joinedAnd(aFirst) + ", " + b +
                " cheaper by " + joinedAnd(bFirst);
    }
  out["pairs"] = pairs;
  const std::string measuresText = joinedAnd(present);
  if (present.size() < 2)
    out["line"] = "op ranking of the " + std::string(s.name) + ": not ranked: " + (present.empty() ? "nothing" : "only " + measuresText) +
                  " measured" + (values.count("isa") ? "" : " (no ISA statistics: motorbench isa --json FILE, then report --isa-json FILE)");
  else if (out["reversed"].empty())
    out["line"] = "op ranking of the " + std::string(s.name) + ": " + measuresText + " order all " + std::to_string(pairs) +
                  " pipeline pairs alike (ties aside)";
  else
    out["line"] = "op ranking of the " + std::string(s.name) + ": " + measuresText + " disagree on the order of " +
                  std::to_string(out["reversed"].size()) + " of " + std::to_string(pairs) + " pipeline pairs: " + listed;
  return out;
}

}  // namespace

json opsRanking(const json& opsVariants, const json& isa) {
  json out = json::object();
  for (const Scope& s : kScopes) out[s.label] = rankScope(opsVariants, isa, s);
  return out;
}

void addOpsRanking(json& r) {
  r["opsRanking"] = opsRanking(at(r, {"opsPerVertex", "detail", "variants"}), at(r, {"isa"}));
  if (!r.contains("figures") || !r["figures"].is_object()) r["figures"] = json::object();
  for (const Scope& s : kScopes) {
    const json& entry = r["opsRanking"][s.label];
    figures::Figure f;
    f.kind = "compiled";
    f.name = std::string("ops_ranking.") + s.label + ".pairs_reversed";
    f.unit = "pairs";
    f.statistic = "count";
    f.scope = s.name;
    f.n = entry["pairs"].get<int>();
    f.value = f.n > 0 ? double(entry["reversed"].size()) : std::nan("");
    f.device = "counted ops, SPIR-V probe ops, AMD ISA instructions (report.json opsRanking)";
    f.definition = "pipeline pairs one measure orders one way and another the other way (ties order nothing), "
                   "of n pairs at least two measures order";
    if (!std::isfinite(f.value)) f.why = entry.value("line", "");
    figures::put(r["figures"], f);
  }
}

std::string opsRankingTableText(const json& scope) {
  std::string text;
  for (const json& p : scope.value("pipelines", json::array())) {
    std::string cell;
    for (const json& m : scope.value("measures", json::array()))
      cell += (cell.empty() ? "" : " / ") + fmt(at(scope, {"table", p.get<std::string>().c_str(), m.value("key", "").c_str()}), 4);
    text += (text.empty() ? "" : ", ") + p.get<std::string>() + " " + cell;
  }
  std::string names;
  for (const json& m : scope.value("measures", json::array())) names += (names.empty() ? "" : " / ") + m.value("name", "");
  return text + " (" + names + ")";
}

void opsRankingSection(Document& d, const json& r) {
  const json& ranking = at(r, {"opsRanking"});
  if (!ranking.is_object() || !at(ranking, {kScopes[0].label, "measures"}).is_array()) return;
  std::string defs;
  for (const json& m : ranking[kScopes[0].label]["measures"])
    defs += (defs.empty() ? "" : " ") + m.value("name", "") + ": " + m.value("definition", "") + "; " + m.value("device", "") + ".";
  d.paragraph("Ranking of the pipelines by the three op measures (rank 1 = cheapest, equal values share a rank); a "
              "pair is named where one measure puts it one way and another the other way. " + defs);
  for (const Scope& s : kScopes) {
    const json& e = at(ranking, {s.label});
    if (!e.is_object()) continue;
    d.paragraph(e.value("line", ""));
    std::vector<std::string> header = {"pipeline"};
    for (const json& m : e["measures"]) header.push_back(m.value("name", "") + " (rank)");
    std::vector<std::vector<Cell>> rows;
    for (const json& p : e["pipelines"]) {
      const std::string name = p.get<std::string>();
      std::vector<Cell> row = {{name}};
      for (const json& m : e["measures"]) {
        const std::string key = m.value("key", "");
        const json& rank = at(e, {"ranks", key.c_str(), name.c_str()});
        row.push_back({fmt(at(e, {"table", name.c_str(), key.c_str()}), 4) +
                       (rank.is_number() ? " (" + std::to_string(rank.get<int>()) + ")" : "")});
      }
      rows.push_back(row);
    }
    d.table(header, rows);
  }
}

}  // namespace mb::document
