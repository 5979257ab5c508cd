// The curved-space camera drift (pipelines/curved/curved_drift.h, as `motorbench drift` and the
// report's curved section measure it: harness/report/report_drift.h) as figures.
#pragma once
#include <cstdint>

#include <nlohmann/json.hpp>

namespace mb::accuracy {

inline constexpr int64_t kDriftSteps = 1000000;

// The figures drift.<s3|h3>.<matrix|motor>.{raw, renormalised, renorm_ops} of report::driftJson(steps)
// into `figures`, that JSON into `details`.
void putDriftFigures(const nlohmann::json& drift, nlohmann::json& figures, nlohmann::json& details);

}  // namespace mb::accuracy
