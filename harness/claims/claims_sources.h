// The families of claims `motorbench claims` checks, each measured where it is implemented:
//   claims_ops.cpp       arithmetic of the PGA kernels and the matrix operators (counted)
//   claims_memory.cpp    floats per vertex / transform / joint (PipelineStats of real uploads)
//   claims_speed.cpp     "as fast as matrices": the rigid vertex (the paper's sentence), the skinned one
//   claims_ranking.cpp   where counted ops, SPIR-V and ISA order the pipelines differently
//   claims_isa_strongest.cpp  AMD ISA instructions and occupancy against the strongest matrix form
//   claims_quotes.cpp    the paper's sentence each paper row tests (rows without one are ours)
//   claims_corpus.cpp    animated / non-uniform scale (1e-4 rule) over a corpus of real files
//   claims_skinning.cpp  volume kept by motor skinning vs LBS (candy wrapper)
//   claims_baselines.cpp affine matrix path, full world-to-clip, skinning per vertex
//   claims_curved.cpp    curved space: S3 / H3 matrix vs motor
//   claims_strongest.cpp the paper's verdicts against the strongest matrix variant measured
//   claims_composition.cpp  gp_mm vs mat4 vs affine composition; the scene-graph update
//   claims_conversion.cpp   quaternion -> rotor for free; the uniform-scale overhead
//   claims_handedness.cpp   the paper's tangent-frame handedness rule on the built-in scenes
//   claims_blending.cpp     motor blending vs slerp over the built-in animations
//   claims_compact.cpp      the smallest motor vertex vs the smallest matrix vertex
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/claims/claims_model.h"
#include "pipelines/result.h"
#include "harness/claims/claims_uploads.h"

namespace mb::claims {

std::vector<Claim> opClaims();

// Uploads of the built-in scenes per pipeline (claims_uploads.h: the report's, else rendered);
// a missing one makes the claims "not measurable here" with the reason.
std::vector<Claim> memoryClaims(const Uploads& uploads);

struct SpeedInputs {
  nlohmann::json kernelPairs;  // report_bench.h kernelPairs()["pairs"], or null
  std::string kernelSource;    // where they came from (file or "short run")
  nlohmann::json kernelMachine;  // report.json "machine" of the kernels' run (CPU model, cores), or null
  // [{"scene", "ratio", "vertexBound"}...] or null: motor / matrix frame time, the median of the
  // per-frame ratios (both pipelines render each frame back to back; report.json's
  // paired_ratio_motor_matrix), the ratio of the medians where no paired ratio was recorded.
  nlohmann::json frameTimes;
  std::string frameSource;
  std::string missing;         // why some input is absent
  // {scene id: timing JSON of report_timing.h (every timed pipeline)}, or null.
  nlohmann::json timings;
  nlohmann::json timingMachine;  // "machine" of the timing run (its "gl" names the device), or null
  // {scene id: toJson(FileStats)} of the timed scenes (drawn vertices for the minimum of work).
  nlohmann::json sceneStats;
  nlohmann::json isa;          // `motorbench isa` JSON (schema motorbench-isa/1), or null
  std::string isaSource;
  // report.json's "opsRanking" (harness/document/ops_ranking.h), or null: then ranked by the same
  // function from this process's op counts and `isa` (no report, or one written before it).
  nlohmann::json opsRanking;
  std::string opsRankingSource;
  bool spirv = true;           // SPIR-V ops as evidence (compiles every shader variant: seconds)
};
std::vector<Claim> speedClaims(const SpeedInputs& in);

// The ISA kind of op evidence as rows of their own, beside the counted and
// SPIR-V ops rows: per vertex shader (rigid to clip, skinned) the instructions and VGPRs of the
// cheapest motor-side pipeline against the cheapest matrix-side one on every family of `isa`
// (SpeedInputs::isa); the worst family decides ("holds" when the motor side needs no more).
std::vector<Claim> isaStrongestClaims(const nlohmann::json& isa, const std::string& isaSource);

// The files the two scene-statistics rows are judged on (claims_corpus.cpp).
struct CorpusInputs {
  nlohmann::json sceneGraphs;    // per-file inspect JSON of a scene-graph corpus (corpus_stats.h), or null
  std::string sceneGraphSource;  // where it came from
  nlohmann::json reportScenes;   // report.json's "scenes" (each with "stats", "spec"), or null: built-in scenes
  std::string reportSource;
  std::string corpusDir;         // "" or a folder of .gltf/.glb files measured with them
};
std::vector<Claim> corpusClaims(const CorpusInputs& in);

// Skinning: ring radius of skinned_tube's candy_wrapper, LBS vs motor (claims_skinning.cpp).
std::vector<Claim> skinningClaims();

// motor_c vs matrix_c: bytes from uploads, worst PSNR against matrix (from `report`'s
// summary, the same figure the report shows; renders at rest only without a report), counted
// ops, ISA from `isa` (a `motorbench isa` JSON, or null: that row not measurable); and motor_cf
// against motor_c (the paper's fragment-rotor suggestion). Needs GL only without a report.
std::vector<Claim> compactClaims(const nlohmann::json& isa, const std::string& isaSource,
                                 const nlohmann::json& report = nullptr, const std::string& reportSource = "");

// Reviewer baselines (Verdict::Baseline): counted and SPIR-V.
std::vector<Claim> baselineClaims();

// Curved space (section "Curved space"): floats per instance (`uploads`), ops per vertex, frame
// time, drift over 10^6 steps. `reportScenes` (report.json's "scenes", or null): their curved
// scenes' timing is the frame-time figure when present; else timed here when `runTiming`
// (`frames` per pipeline; needs GL).
std::vector<Claim> curvedClaims(bool runTiming, int frames, const nlohmann::json& reportScenes, const Uploads& uploads);

// Every pipeline's bytes per vertex, floats per transform and joint (`uploads` of built-in
// scenes), ops per vertex (counted and SPIR-V) and time ratios (`timings`: {scene: timing JSON},
// or null), the motor pipeline judged against the best matrix-side pipeline; and the
// CPU kernels vertex_frame / skinned_vertex, the fastest motor implementation against the
// fastest matrix implementation measured (`kernelPairs`: report_bench's pairs, or null).
// Timed rows count only scenes with the minimum of work (claims_work.h; `sceneStats` as in
// SpeedInputs, or null: drawn vertices unknown).
std::vector<Claim> strongestBaselineClaims(const nlohmann::json& timings, const std::string& timingSource,
                                           const nlohmann::json& kernelPairs = nullptr,
                                           const std::string& kernelSource = "",
                                           const nlohmann::json& sceneStats = nullptr,
                                           const nlohmann::json& timingMachine = nullptr,
                                           const Uploads& uploads = Uploads());

// Composition, counted (gp_mm, mat4 * mat4, affine mat4x3), and timed by the bench's compose
// pair when `kernelPairs` has an undisturbed one (every side, SIMD included); nothing timed here.
std::vector<Claim> compositionClaims(const nlohmann::json& kernelPairs = nullptr);

// Scene-graph update: the hierarchy bench pair (`kernelPairs`, report_bench.h's pairs, or null)
// and Pipeline::update per scene (`timings`: {scene: timing JSON}, or null), motor against the
// fastest matrix-side code.
std::vector<Claim> sceneGraphClaims(const nlohmann::json& kernelPairs, const nlohmann::json& timings,
                                    const std::string& timingSource, const nlohmann::json& sceneStats = nullptr);

// Quaternion -> rotor conversion cost and the uniform-scale overhead per vertex (normal_torus's
// motor uploads for the floats per transform).
std::vector<Claim> conversionClaims(const Uploads& uploads = Uploads());

// The paper's handedness load rule on every frame of the built-in scenes.
std::vector<Claim> handednessClaims();

// Motor blend vs slerp over every rotation channel of the built-in animations.
std::vector<Claim> blendingClaims();

// Volume kept by motor skinning vs LBS on the skinned files directly in `corpusDir`: JSON
// kSkinVolumesSchema {"schema", "folder", "files": [every .gltf/.glb name read], "meshes":
// [{"id" (file/mesh[#primitive]), "file", "closed", "measure", "lbs": {"min", "max"}, "motor":
// {"min", "max"}}]} (posed / rest volume over every time), or why not (no such folder). Written
// by `claims --skin-volumes-out` so that a run without the corpus reads it (--skin-volumes).
inline constexpr const char* kSkinVolumesSchema = "motorbench-skin-volumes/1";
Result<nlohmann::json> measureSkinnedFileVolumes(const std::string& corpusDir);

// The row judged on such a measurement; `keptIn`: the file its figures are kept in ("" when
// measured only for this row), named in the method.
std::vector<Claim> skinnedFileVolumeClaimsFrom(const nlohmann::json& volumes, const std::string& keptIn = "");

// Measured over `corpusDir` and judged ("not measurable here" when the folder is absent or has
// no animated skinned mesh).
std::vector<Claim> skinnedFileVolumeClaims(const std::string& corpusDir);

}  // namespace mb::claims
