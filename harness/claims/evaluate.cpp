#include "harness/claims/evaluate.h"

#include <cmath>
#include <cstdio>

#include "harness/document/report_format.h"

namespace mb::claims {
namespace {

using nlohmann::json;

const char* const kColumns[] = {"mul", "add", "div", "sqrt", "other"};

// One kind of evidence as read: its value (a ratio when `over` is set), how it reads, whether it
// passes the rule, or why it is left out.
struct Reading {
  const Evidence* evidence = nullptr;
  double value = NAN;
  std::string text;       // "1.05x (89 ops / 85 ops)", "48 mul, 40 add"
  std::string leftOut;    // non-empty: not judged, and why
  json columns;           // the column rules: {"mul": 48, ...}
  json figures = json::array();  // what each figure is: reference, statistic, n, device
  bool passes = false;
  bool share = false;     // a count over a count of the same thing: printed as a percentage
};

// Units that count things: a ratio of two figures in the same one is a share.
bool countsThings(const std::string& unit) {
  for (const char* u : {"models", "files", "frames", "quaternions", "draws", "scenes", "joints", "vertices",
                        "primitives", "pairs", "key pairs", "meshes"})
    if (unit == u) return true;
  return false;
}

json describe(const std::string& ref, const figures::Figure& f) {
  return {{"reference", ref}, {"value", std::isfinite(f.value) ? json(f.value) : json()}, {"kind", f.kind},
          {"statistic", f.statistic},
          {"n", f.n}, {"device", f.device}, {"scope", f.scope}};
}

// The figure `ref`, or why it cannot be judged (absent, not measured, disturbed, too few samples).
std::optional<figures::Figure> read(const FigureSet& set, const std::string& ref, const Rule& rule, Reading& r) {
  auto f = lookUp(set, ref);
  const std::string source = ref.substr(0, ref.find(':'));
  if (!f) {
    const auto miss = set.missing.find(source);
    r.leftOut = "no figure " + ref + (miss != set.missing.end() ? " (" + miss->second + ")" : "");
    return std::nullopt;
  }
  r.figures.push_back(describe(ref, *f));
  if (!std::isfinite(f->value)) r.leftOut = ref + " not measured" + (f->why.empty() ? "" : ": " + f->why);
  else if (figures::isDisturbed(*f))
    r.leftOut = ref + " disturbed (" + f->disturbed.value("reason", std::string("load")) + ")";
  else if (rule.gpuTimed && f->device.find("CPU rasterizer") != std::string::npos)
    r.leftOut = ref + " was timed on a CPU rasterizer, which cannot stand for a GPU";
  else if (rule.minN > 0 && f->n < rule.minN)
    r.leftOut = ref + ": n = " + std::to_string(f->n) + " < " + std::to_string(rule.minN) + ", too few to carry a verdict";
  return f;
}

bool isColumnRule(RuleKind k) {
  return k == RuleKind::PaperColumns || k == RuleKind::PaperColumnsOrListing || k == RuleKind::PaperColumnsUndefined;
}

// The .mul/.add/... figures under the prefix `ref`; passes when every column the paper states matches.
Reading readColumns(const FigureSet& set, const Evidence& e, const ClaimRow& row) {
  Reading r{&e};
  r.columns = json::object();
  for (const char* c : kColumns) {
    Reading part;
    auto f = read(set, e.value + "." + c, row.rule, part);
    if (!f || !part.leftOut.empty()) {
      if (!row.paperValue.contains(c) && !f) continue;  // an unstated column may be absent
      r.leftOut = part.leftOut;
      return r;
    }
    r.columns[c] = f->value;
    r.figures.push_back(part.figures[0]);
  }
  std::string text = document::sig3(r.columns.value("mul", 0.0)) + " mul, " + document::sig3(r.columns.value("add", 0.0)) + " add";
  for (const char* c : {"div", "sqrt", "other"})
    if (r.columns.value(c, 0.0) != 0) text += " + " + document::sig3(r.columns[c].get<double>()) + " " + c;
  r.text = text;
  std::string diff;
  for (const char* c : kColumns) {
    if (!row.paperValue.contains(c)) continue;
    const double d = r.columns.value(c, 0.0) - row.paperValue[c].get<double>();
    if (d != 0) diff += (diff.empty() ? "" : ", ") + std::string(d > 0 ? "+" : "") + document::sig3(d) + " " + c;
  }
  r.passes = diff.empty();
  if (!r.passes) r.text += " (" + diff + ")";
  return r;
}

Reading readValue(const FigureSet& set, const Evidence& e, const Rule& rule) {
  Reading r{&e};
  auto a = read(set, e.value, rule, r);
  if (!a || !r.leftOut.empty()) return r;
  if (e.over.empty()) {
    r.value = a->value;
    r.text = figures::valueText(*a);
  } else {
    auto b = read(set, e.over, rule, r);
    if (!b || !r.leftOut.empty()) return r;
    if (b->value == 0) {
      r.leftOut = e.over + " is 0";
      return r;
    }
    r.value = a->value / b->value;
    r.share = a->unit == b->unit && countsThings(a->unit);
    r.text = (r.share ? document::sig3(100 * r.value) + " %" : document::sig3(r.value) + "x") + " (" + figures::valueText(*a) + " / " +
             figures::valueText(*b) + ")";
  }
  if (rule.kind == RuleKind::AtMost) r.passes = r.value <= rule.limit;
  if (rule.kind == RuleKind::AtLeast) r.passes = r.value >= rule.limit;
  return r;
}

std::string ruleText(const ClaimRow& row, bool shares = false) {
  const Rule& r = row.rule;
  const bool ratio = !row.evidence.empty() && !row.evidence[0].over.empty();
  const std::string what = shares ? "each share" : ratio ? "each ratio" : "each value";
  const std::string limit = shares ? document::sig3(100 * r.limit) + " %" : document::sig3(r.limit);
  switch (r.kind) {
    case RuleKind::PaperColumns: return "every column the paper states, equal";
    case RuleKind::PaperColumnsOrListing: return "ours or the paper's printed listing equal in every column the paper states";
    case RuleKind::PaperColumnsUndefined:
      return "every column the paper states, equal; a difference is inconclusive (the paper defines no expansion)";
    case RuleKind::AtMost: return what + " <= " + limit;
    case RuleKind::AtLeast: return what + " >= " + limit;
    case RuleKind::Baseline: return "a baseline: no verdict";
  }
  return "?";
}

bool allShares(const std::vector<Reading>& rs) {
  for (const Reading& r : rs)
    if (r.leftOut.empty() && !r.share) return false;
  return !rs.empty();
}

void judge(Claim& c, const ClaimRow& row, const std::vector<Reading>& rs) {
  std::vector<const Reading*> judged;
  std::string leftOut;
  for (const Reading& r : rs) {
    if (r.leftOut.empty()) judged.push_back(&r);
    else leftOut += (leftOut.empty() ? "" : "; ") + r.evidence->label + ": " + r.leftOut;
  }
  auto withLeftOut = [&](std::string s) { return leftOut.empty() ? s : s + " (left out: " + leftOut + ")"; };
  if (judged.empty()) {
    c.verdict = Verdict::NotMeasurable;
    c.verdictText = "not measurable here: " + (leftOut.empty() ? std::string("no evidence declared") : leftOut);
    return;
  }
  if (row.rule.kind == RuleKind::Baseline) {
    c.verdict = Verdict::Baseline;
    c.verdictText = withLeftOut("baseline");
    return;
  }
  if (row.rule.kind == RuleKind::PaperColumnsOrListing) {
    const bool ours = rs[0].leftOut.empty() && rs[0].passes;
    const bool listing = rs.size() > 1 && rs[1].leftOut.empty() && rs[1].passes;
    c.verdict = ours || listing ? Verdict::Reproduced : Verdict::Differs;
    const std::string oursText = rs[0].leftOut.empty() ? "; ours " + rs[0].text : "";
    c.verdictText = ours      ? "reproduced by ours"
                    : listing ? "reproduced by the paper's printed listing" + oursText
                              : "differs" + (oursText.empty() ? std::string(":") : ":" + oursText.substr(1)) +
                                    (rs.size() > 1 && rs[1].leftOut.empty() ? "; listing " + rs[1].text : "");
    c.verdictText = withLeftOut(c.verdictText);
    return;
  }
  size_t pass = 0;
  std::string passing, failing;
  for (const Reading* r : judged) {
    pass += r->passes;
    std::string& to = r->passes ? passing : failing;
    to += (to.empty() ? "" : ", ") + r->evidence->label + " " + r->text;
  }
  const std::string rule = " under the rule (" + ruleText(row, allShares(rs)) + ")";
  if (pass == judged.size()) {
    c.verdict = Verdict::Reproduced;
    c.verdictText = judged.size() == 1 && isColumnRule(row.rule.kind)
                        ? "reproduced"
                        : "reproduced: " + std::string(judged.size() == 1 ? "" : "every kind passes ") + passing + rule;
  } else if (pass == 0) {
    c.verdict = row.rule.kind == RuleKind::PaperColumnsUndefined ? Verdict::Inconclusive : Verdict::Differs;
    c.verdictText = (c.verdict == Verdict::Inconclusive ? "inconclusive: " : "differs: ") + failing +
                    (isColumnRule(row.rule.kind) ? "" : rule);
  } else {
    c.verdict = Verdict::Inconclusive;
    c.verdictText = "inconclusive: the kinds of evidence disagree" + rule + ": passes " + passing + "; fails " + failing;
  }
  c.verdictText = withLeftOut(c.verdictText);
}

}  // namespace

Claim evaluate(const ClaimRow& row, const FigureSet& set) {
  Claim c;
  c.id = row.id;
  c.section = row.section;
  c.statement = row.statement;
  c.paper = row.paper.empty() ? "-" : row.paper;
  c.paperValue = row.paperValue;
  c.origin = row.origin == "paper" ? "" : row.origin;
  c.quote = row.quote;
  c.tallyAs = row.tallyAs;
  std::vector<Reading> rs;
  for (const Evidence& e : row.evidence)
    rs.push_back(isColumnRule(row.rule.kind) ? readColumns(set, e, row) : readValue(set, e, row.rule));
  json evidence = json::array(), measuredValue = json::object();
  for (const Reading& r : rs) {
    if (r.leftOut.empty()) {
      c.measured += (c.measured.empty() ? "" : "; ") + r.evidence->label + " " + r.text;
      measuredValue[r.evidence->label] = r.columns.is_object() ? r.columns : json(r.value);
    }
    evidence.push_back({{"label", r.evidence->label}, {"value", r.evidence->value},
                        {"over", r.evidence->over.empty() ? json() : json(r.evidence->over)},
                        {"read", r.leftOut.empty() ? (r.columns.is_object() ? r.columns : json(r.value)) : json()},
                        {"passes", r.leftOut.empty() && row.rule.kind != RuleKind::Baseline ? json(r.passes) : json()},
                        {"leftOut", r.leftOut.empty() ? json() : json(r.leftOut)}, {"figures", r.figures}});
  }
  if (c.measured.empty()) c.measured = "-";
  c.measuredValue = measuredValue.empty() ? json() : measuredValue;
  judge(c, row, rs);
  c.method = "scope: " + row.scope.stage + "; baseline: " + row.scope.baseline + "; content: " + row.scope.content +
             ". Rule: " + ruleText(row, allShares(rs)) + (rs.size() > 1 && !isColumnRule(row.rule.kind) && row.rule.kind != RuleKind::Baseline
                                               ? "; every kind passes: reproduced, none: differs, some: inconclusive"
                                               : "") +
             ".";
  static const char* const kKinds[] = {"paper_columns", "paper_columns_or_listing", "paper_columns_undefined",
                                       "at_most", "at_least", "baseline"};
  c.declared = {{"scope", {{"stage", row.scope.stage}, {"baseline", row.scope.baseline}, {"content", row.scope.content}}},
                {"rule", {{"kind", kKinds[int(row.rule.kind)]}, {"limit", row.rule.limit}, {"minN", row.rule.minN}, {"gpuTimed", row.rule.gpuTimed},
                          {"text", ruleText(row, allShares(rs))}}},
                {"evidence", evidence}, {"note", row.note.empty() ? json() : json(row.note)}};
  return c;
}

std::vector<Claim> evaluateAll(const std::vector<ClaimRow>& rows, const FigureSet& set) {
  std::vector<Claim> out;
  for (const ClaimRow& row : rows) out.push_back(evaluate(row, set));
  return out;
}

}  // namespace mb::claims
