// claims.md and the claims JSON, made from the measured Claim rows.
#pragma once
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/claims/claims_model.h"
#include "harness/document/report_model.h"

namespace mb::claims {

inline constexpr const char* kClaimsSchema = "motorbench-claims/1";

// {"schema", "machine", "sources", "scope", "counts": {verdict: n} (every row), "paperCounts" (the
// paper's claims), "ownCounts" (our own rows: baselines, vs strongest, curved, not claimed),
// "claims": [toJson(claim)...]}. `scope`: {"cpu": cpuScope(...), "frameTimeDevice": label}.
nlohmann::json claimsJson(const std::vector<Claim>& claims, const nlohmann::json& machine,
                          const nlohmann::json& sources, const nlohmann::json& scope = nullptr);

// One verdict line per claim, then a table per section (paper | measured | how | verdict).
report::Document claimsDocument(const nlohmann::json& claims);

}  // namespace mb::claims
