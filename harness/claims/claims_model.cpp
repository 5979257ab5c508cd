#include "harness/claims/claims_model.h"

#include <cstdio>

namespace mb::claims {

std::string verdictName(Verdict v) {
  switch (v) {
    case Verdict::Reproduced: return "reproduced";
    case Verdict::Differs: return "differs";
    case Verdict::NotMeasurable: return "not measurable here";
    case Verdict::Baseline: return "baseline";
    case Verdict::Inconclusive: return "inconclusive";
  }
  return "?";
}

nlohmann::json opsJson(const OpCounts& c) {
  nlohmann::json calls = nlohmann::json::object();
  for (size_t i = 0; i < c.fn.size(); ++i)
    if (c.fn[i]) calls[kOpFnNames[i]] = c.fn[i];
  return {{"mul", c.mul}, {"add", c.add}, {"div", c.div}, {"sqrt", c.sqrt}, {"other", c.other}, {"calls", calls}};
}

std::string opsText(const OpCounts& c) {
  std::string s = std::to_string(c.mul) + " mul, " + std::to_string(c.add) + " add";
  if (c.div) s += " + " + std::to_string(c.div) + " div";
  if (c.sqrt) s += " + " + std::to_string(c.sqrt) + " sqrt";
  if (c.other) s += " + " + c.otherCalls();
  return s;
}

nlohmann::json paperOpsJson(const PaperOps& p) {
  nlohmann::json j = {{"mul", p.mul}, {"add", p.add}};
  if (p.div >= 0) j["div"] = p.div;
  if (p.sqrt >= 0) j["sqrt"] = p.sqrt;
  if (p.other >= 0) j["other"] = p.other;
  return j;
}

std::string paperOpsText(const PaperOps& p) {
  std::string s = std::to_string(p.mul) + " mul, " + std::to_string(p.add) + " add";
  if (p.div > 0) s += " + " + std::to_string(p.div) + " div";
  if (p.sqrt > 0) s += " + " + std::to_string(p.sqrt) + " sqrt";
  if (!p.otherText.empty()) s += " + " + p.otherText;
  return s;
}

void judgeOps(Claim& c, const PaperOps& paper, const OpCounts& m) {
  c.paper = paperOpsText(paper);
  c.paperValue = paperOpsJson(paper);
  c.measured = opsText(m);
  c.measuredValue = opsJson(m);
  std::string diff, unstated;
  auto column = [&](const char* name, long stated, uint64_t measured) {
    if (stated < 0) {
      if (measured) unstated += (unstated.empty() ? "" : ", ") + std::to_string(measured) + " " + name;
      return;
    }
    const long d = long(measured) - stated;
    if (d) diff += (diff.empty() ? "" : ", ") + std::string(d > 0 ? "+" : "") + std::to_string(d) + " " + name;
  };
  column("mul", paper.mul, m.mul);
  column("add", paper.add, m.add);
  column("div", paper.div, m.div);
  column("sqrt", paper.sqrt, m.sqrt);
  column("other", paper.other, m.other);
  if (diff.empty()) {
    c.verdict = Verdict::Reproduced;
    c.verdictText = "reproduced";
  } else {
    c.verdict = Verdict::Differs;
    const double total = paper.mul + paper.add, got = double(m.mul + m.add);
    char pct[48] = "";
    if (total > 0) std::snprintf(pct, sizeof pct, " (mul+add %+.0f %%)", 100.0 * (got - total) / total);
    c.verdictText = "differs: " + diff + pct;
  }
  if (!unstated.empty()) c.verdictText += "; not stated by the paper: " + unstated;
}

void judgeOpsThree(Claim& c, const PaperOps& paper, const OpCounts& listing,
                   const OpCounts& measured, const std::string& oursWhy) {
  Claim vsListing = c, vsOurs = c;
  judgeOps(vsListing, paper, listing);
  judgeOps(vsOurs, paper, measured);
  c.paper = vsOurs.paper + " (table)";
  c.paperValue = vsOurs.paperValue;
  c.measured = "ours " + opsText(measured) + "; the paper's printed listing, counted: " + opsText(listing);
  c.measuredValue = {{"ours", opsJson(measured)}, {"listing", opsJson(listing)}};
  const std::string tableVsListing = "table vs printed listing: " +
      (vsListing.verdict == Verdict::Reproduced ? std::string("the listing counts what the table says")
                                                : "the listing " + vsListing.verdictText.substr(9, vsListing.verdictText.find(';') - 9) +
                                                      " (the printed code does not reach its table)");
  const std::string tableVsOurs =
      "table vs ours: " + (vsOurs.verdictText.rfind("differs: ", 0) == 0 ? vsOurs.verdictText.substr(9) : vsOurs.verdictText);
  std::string oursVsListing = "ours vs listing: ";
  {
    const long dm = long(measured.mul) - long(listing.mul), da = long(measured.add) - long(listing.add);
    oursVsListing += (dm == 0 && da == 0) ? "same mul/add"
                     : std::string(dm > 0 ? "+" : "") + std::to_string(dm) + " mul, " + (da > 0 ? "+" : "") +
                           std::to_string(da) + " add";
    auto calls = [](const OpCounts& o) {
      std::string t;
      if (o.div) t += std::to_string(o.div) + " div";
      if (o.sqrt) t += (t.empty() ? "" : ", ") + std::to_string(o.sqrt) + " sqrt";
      if (o.other) t += (t.empty() ? "" : ", ") + o.otherCalls();
      return t.empty() ? std::string("none") : t;
    };
    if (calls(measured) != calls(listing))
      oursVsListing += " (other calls: ours " + calls(measured) + ", listing " + calls(listing) + ")";
  }
  if (vsOurs.verdict == Verdict::Reproduced) {
    c.verdict = Verdict::Reproduced;
    c.verdictText = "reproduced by ours; " + tableVsListing;
  } else if (vsListing.verdict == Verdict::Reproduced) {
    c.verdict = Verdict::Reproduced;
    c.verdictText = "reproduced by the paper's printed listing; ours differs (" + oursVsListing + "): " + oursWhy;
  } else {
    c.verdict = Verdict::Differs;
    c.verdictText = "differs: " + tableVsOurs + "; " + tableVsListing + "; " + oursVsListing +
                    (oursWhy.empty() ? "" : " (" + oursWhy + ")");
  }
}

std::string originOf(const Claim& c) {
  if (!c.origin.empty()) return "own: " + c.origin;
  if (c.verdict == Verdict::Baseline) return "own: baseline";
  if (c.paper.rfind("(not claimed", 0) == 0) return "own: not claimed by the paper";
  return "paper";
}

nlohmann::json toJson(const Claim& c) {
  nlohmann::json j = {{"id", c.id}, {"origin", originOf(c)}, {"section", c.section}, {"statement", c.statement}, {"paper", c.paper},
          {"paperValue", c.paperValue}, {"measured", c.measured}, {"measuredValue", c.measuredValue},
          {"method", c.method}, {"verdict", verdictName(c.verdict)}, {"verdictText", c.verdictText},
          {"quote", c.quote.empty() ? nlohmann::json() : nlohmann::json(c.quote)}, {"tallyAs", c.tallyAs.empty() ? c.id : c.tallyAs}};
  if (c.declared.is_object()) j.update(c.declared);
  return j;
}

std::string fmt(const char* f, double v) {
  char b[48];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

}  // namespace mb::claims
