// report.json: the document every other output (report.md, report.html, the plots, claims) is
// made from. Its schema is documented in README.md, section "Report".
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace mb::report {

inline constexpr const char* kReportSchema = "motorbench-report/1";

// Puts the parts together and adds "summary" (per pipeline: bytes/floats per vertex, floats
// per transform and joint, conversion time; per compared pipeline: PSNR spread and largest
// fraction of changed pixels, "images" over the frames where both pipelines should agree and
// "skinningMethodImages" over skinned scenes where one blends with LBS and the other with
// motors (the methods' expected difference); frame-time ratio of the Euclidean scenes and kernel
// ratios; scene counts by status and by origin ("built-in" / "file"); "curved": one row per
// curved-space scene (space, pipelines, floats per instance, ops, PSNR, frame-time ratios)).
// Scenes with a "space" other than "Euclidean" are left out of the Euclidean figures.
nlohmann::json assembleReport(nlohmann::json machine, nlohmann::json settings,
                              std::vector<nlohmann::json> scenes, nlohmann::json opsPerVertex,
                              nlohmann::json kernels);

// False for a curved-space scene (its "space" is not "Euclidean").
bool isEuclidean(const nlohmann::json& scene);

// True when `scene` is skinned and pipelines `p` and `baseline` blend joints differently
// (their "skinBlend": linear blend skinning vs motor blending).
bool skinningMethodsDiffer(const nlohmann::json& scene, const std::string& p, const std::string& baseline);

// min / median / max of `values` ({"n": 0} when empty).
nlohmann::json spread(std::vector<double> values);

}  // namespace mb::report
