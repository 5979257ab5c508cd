// report.json: the document every other output (report.md, report.html, the plots, claims) is
// made from. Its schema is documented in README.md, section "Report".
#pragma once
#include <nlohmann/json.hpp>

namespace mb::report {

inline constexpr const char* kReportSchema = "motorbench-report/1";

// Puts the parts together and adds "summary" (per pipeline: bytes/floats per vertex, floats
// per transform and joint, conversion time; per compared pipeline: worst PSNR and largest
// fraction of changed pixels; frame-time and kernel ratios; scene counts by status).
nlohmann::json assembleReport(nlohmann::json machine, nlohmann::json settings,
                              std::vector<nlohmann::json> scenes, nlohmann::json opsPerVertex,
                              nlohmann::json kernels);

// min / median / max of `values` ({"n": 0} when empty).
nlohmann::json spread(std::vector<double> values);

}  // namespace mb::report
