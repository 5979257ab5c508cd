// report.json: the document every other output (report.md, report.html, the plots, claims) is
// made from. Its schema is documented in README.md, section "Report".
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace mb::document {

inline constexpr const char* kReportSchema = "motorbench-report/1";

// Puts the parts together and adds "summary" (per pipeline: bytes/floats per vertex, floats
// per transform and joint, conversion time; per compared pipeline: PSNR spread and largest
// fraction of changed pixels, "images" over every frame, each judged against its own reference
// (judgedFrame: skinned frames of another skinning method against their own method's; with the
// count per reference and the frames not judged, with their reasons), and
// "skinningMethodImages" over skinned scenes where one blends with LBS and the other with
// motors, against the baseline (the methods' expected difference, measured); frame-time ratio of the Euclidean scenes and kernel
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

// How frame `frame` of `scene` judges pipeline `p` against `baseline` (the worker's
// skinJudgement, skin_judgement.h): a skinned frame of another skinning method than the
// baseline's against its own method's reference ("referenceMetrics.<p>"), every other frame
// against the baseline ("metrics.<p>"). Not judged (metrics null, `why`): its own reference
// could not be made, or the report was made before skinned frames were judged by their method.
struct JudgedFrame {
  bool compared = false;                    // the frame has metrics.<p> (both pipelines drew it)
  const nlohmann::json* metrics = nullptr;  // the metrics that judge it; null: not judged
  std::string reference;                    // what it was judged against: the baseline, "matrix" or
                                            // "motor-blend reference"
  bool skinnedOwnMethod = false;            // a skinned frame judged by its own skinning method
  std::string why;                          // not judged: why
};
JudgedFrame judgedFrame(const nlohmann::json& scene, const nlohmann::json& frame, const std::string& p,
                        const std::string& baseline);

}  // namespace mb::document
