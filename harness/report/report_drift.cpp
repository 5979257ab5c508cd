#include "harness/report/report_drift.h"

#include "pipelines/curved/curved_drift.h"

namespace mb::report {
namespace {

nlohmann::json opsJson(const OpCounts& c) {
  return {{"mul", c.mul}, {"add", c.add}, {"div", c.div}, {"sqrt", c.sqrt}, {"other", c.other},
          {"other_calls", c.otherCalls()}};
}

nlohmann::json sideJson(const curved::DriftSide& d, const char* renormalisation) {
  return {{"raw", d.raw}, {"renormalised", d.renormalised}, {"stepOps", opsJson(d.stepOps)},
          {"renormOps", opsJson(d.renormOps)}, {"renormalisation", renormalisation}};
}

}  // namespace

nlohmann::json driftJson(int64_t steps) {
  nlohmann::json spaces = nlohmann::json::array();
  for (int k : {1, -1}) {
    const curved::DriftResult r = curved::measureDrift(k, steps);
    spaces.push_back({{"space", k > 0 ? "S3" : "H3"},
                      {"kappa", k},
                      {"matrix", sideJson(r.matrix, "Gram-Schmidt of the columns in the space's form")},
                      {"motor", sideJson(r.motor, k > 0 ? "normalize_pair" : "normalize_m_k")}});
  }
  return {{"steps", steps},
          {"step", "turn 2e-3 rad (x-z plane) then move 1e-3 forward, composed in double, rounded to float once"},
          {"spaces", spaces}};
}

}  // namespace mb::report
