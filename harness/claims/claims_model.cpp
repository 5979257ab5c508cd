#include "harness/claims/claims_model.h"

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

std::string originOf(const Claim& c) { return c.origin.empty() ? "paper" : "own: " + c.origin; }

nlohmann::json toJson(const Claim& c) {
  nlohmann::json j = {{"id", c.id}, {"origin", originOf(c)}, {"section", c.section}, {"statement", c.statement},
                      {"paper", c.paper}, {"paperValue", c.paperValue}, {"measured", c.measured},
                      {"measuredValue", c.measuredValue}, {"method", c.method}, {"verdict", verdictName(c.verdict)},
                      {"verdictText", c.verdictText},
                      {"quote", c.quote.empty() ? nlohmann::json() : nlohmann::json(c.quote)},
                      {"tallyAs", c.tallyAs.empty() ? c.id : c.tallyAs}};
  if (c.declared.is_object()) j.update(c.declared);
  return j;
}

}  // namespace mb::claims
