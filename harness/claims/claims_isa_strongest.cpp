// The ISA kind of op evidence against the strongest matrix form: per vertex shader (rigid to clip,
// skinned) and family, the fewest instructions and the highest occupancy (waves per SIMD) of each
// side; the worst family decides. VGPRs are quoted beside the occupancy: more registers cost
// nothing while the waves per SIMD stay equal.
#include <algorithm>

#include "harness/claims/claims_ranking.h"
#include "harness/claims/claims_sources.h"

namespace mb::claims {
namespace {

using json = nlohmann::json;

bool motorSide(const std::string& p) { return p.rfind("motor", 0) == 0; }

struct Worst {
  double ratio = -1;
  std::string detail;
};

// Per family: the best motor side against the best matrix side of `cost` (lower is better).
template <class Cost>
Worst worstFamily(const IsaTable& table, Cost cost, const char* what) {
  Worst w;
  std::vector<double> all;
  for (const auto& [family, byPipeline] : table) {
    std::string bm, bx;
    for (const auto& [p, s] : byPipeline) {
      std::string& best = motorSide(p) ? bm : bx;
      if (cost(s) > 0 && (best.empty() || cost(s) < cost(byPipeline.at(best)))) best = p;
    }
    if (bm.empty() || bx.empty()) continue;
    const double r = cost(byPipeline.at(bm)) / cost(byPipeline.at(bx));
    all.push_back(r);
    w.detail += (w.detail.empty() ? "" : "; ") + family + " " + fmt("%.2fx", r) + " " + bm + " / " + bx;
  }
  if (all.empty()) return w;
  w.ratio = *std::max_element(all.begin(), all.end());
  w.detail = std::string(what) + " worst of " + std::to_string(all.size()) + " families " + fmt("%.2fx", w.ratio) + " (" +
             w.detail + ")";
  return w;
}

}  // namespace

std::vector<Claim> isaStrongestClaims(const json& isa, const std::string& isaSource) {
  std::vector<Claim> out;
  for (const char* program : {"rigid", "skinned"}) {
    Claim c{std::string("ops_") + (std::string(program) == "rigid" ? "clip" : "skinned") + "_vs_strongest_isa",
            "Against the strongest baseline",
            std::string("AMD ISA of the ") + program + " vertex shader (instructions and occupancy, RADV's compiler "
            "on its null device): the cheapest motor side vs the cheapest matrix side"};
    c.paper = "(not claimed; the paper counts ops per vertex)";
    c.method = "motorbench isa (" + (isaSource.empty() ? std::string("the report's \"isa\"") : isaSource) +
               "): each pipeline's " + program + " vertex shader as the GL pipeline loads it (normal-mapped form), "
               "per family and NGG mode the fewest instructions and the most waves per SIMD of each side; the worst "
               "family decides; holds when the motor side needs no more instructions and reaches the same occupancy "
               "(cost ratio <= 1 for both); VGPRs quoted, judged only through the occupancy they allow";
    const IsaTable table = isaVertexTable(isa, program);
    const Worst instr = worstFamily(table, [](const IsaStats& s) { return s.instructions; }, "instructions");
    // Occupancy as a cost: 1 / waves (fewer waves per SIMD cost more).
    const Worst occ = worstFamily(table, [](const IsaStats& s) { return s.waves > 0 ? 1.0 / s.waves : 0.0; },
                                  "occupancy cost (1 / waves per SIMD)");
    const Worst vgprs = worstFamily(table, [](const IsaStats& s) { return s.vgprs; }, "VGPRs");
    if (instr.ratio < 0) {
      c.measured = "-";
      c.measuredValue = nullptr;
      c.verdict = Verdict::NotMeasurable;
      c.verdictText = "not measurable here: no " + std::string(program) + " vertex shader of both sides in the ISA statistics";
      out.push_back(c);
      continue;
    }
    c.measured = instr.detail + "; " + occ.detail + "; " + vgprs.detail;
    c.measuredValue = {{"instructions", instr.ratio}, {"occupancyCost", occ.ratio >= 0 ? json(occ.ratio) : json()},
                       {"vgprs", vgprs.ratio >= 0 ? json(vgprs.ratio) : json()}};
    const bool holds = instr.ratio <= 1.0 && (occ.ratio < 0 || occ.ratio <= 1.0);
    c.verdict = holds ? Verdict::Reproduced : Verdict::Differs;
    c.verdictText = std::string(holds ? "holds" : "does not hold") +
                    " against the strongest baseline on every family: motor side / matrix side instructions " +
                    fmt("%.2fx", instr.ratio) + ", occupancy cost " + fmt("%.2fx", occ.ratio) + " on the worst family (VGPRs " +
                    fmt("%.2fx", vgprs.ratio) + ")";
    out.push_back(c);
  }
  return out;
}

}  // namespace mb::claims
