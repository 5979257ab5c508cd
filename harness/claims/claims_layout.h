// claims.md and the claims JSON, made from the measured Claim rows.
#pragma once
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/claims/claims_model.h"
#include "harness/document/report_model.h"

namespace mb::claims {

inline constexpr const char* kClaimsSchema = "motorbench-claims/1";

// {"schema", "machine", "sources", "counts": {verdict: n} (every row), "paperCounts" (the
// paper's claims), "ownCounts" (our own rows: baselines, vs strongest, curved, not claimed),
// "claims": [toJson(claim)...]}.
nlohmann::json claimsJson(const std::vector<Claim>& claims, const nlohmann::json& machine,
                          const nlohmann::json& sources);

// The tally, one verdict line per claim, then a table per section (claim | scope | paper |
// measured | rule | verdict | note). The answer block with the scope ladder goes before it
// (report_answer.h).
document::Document claimsDocument(const nlohmann::json& claims);

}  // namespace mb::claims
