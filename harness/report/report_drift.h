// The camera drift of the curved spaces (pipelines/curved/curved_drift.h) as JSON, shared by
// `motorbench drift --json` and the report's curved-space section.
#pragma once
#include <cstdint>

#include <nlohmann/json.hpp>

namespace mb::report {

// {"steps", "step" (what one step does), "spaces": [{"space": "S3"|"H3", "kappa", "matrix",
// "motor"}]} where each side is {"raw", "renormalised", "stepOps", "renormOps" (mul, add, div,
// sqrt, other, other_calls), "renormalisation" (the method)}.
nlohmann::json driftJson(int64_t steps);

}  // namespace mb::report
