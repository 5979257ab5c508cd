// The families of claims `motorbench claims` checks, each measured where it is implemented:
//   claims_ops.cpp       arithmetic of the PGA kernels and the matrix operators (counted)
//   claims_memory.cpp    floats per vertex / transform / joint (PipelineStats of real uploads)
//   claims_speed.cpp     "as fast as matrices" (bench kernel ratios + frame timing)
//   claims_corpus.cpp    animated / non-uniform scale over the built-in scenes + a corpus
//   claims_skinning.cpp  volume kept by motor skinning vs LBS (candy wrapper)
//   claims_baselines.cpp affine matrix path, full world-to-clip, skinning per vertex
//   claims_curved.cpp    curved space (issue 15): S3 / H3 matrix vs motor
//   claims_strongest.cpp the paper's verdicts against the strongest matrix variant measured
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/claims/claims_model.h"

namespace mb::claims {

std::vector<Claim> opClaims();

// Renders built-in scenes with each pipeline (needs GL); a failure makes the claims
// "not measurable here" with the reason.
std::vector<Claim> memoryClaims();

struct SpeedInputs {
  nlohmann::json kernelPairs;  // report_bench.h kernelPairs()["pairs"], or null
  std::string kernelSource;    // where they came from (file or "short run")
  // [{"scene", "ratio", "vertexBound"}...] or null: motor / matrix frame time, the median of the
  // per-frame ratios (both pipelines render each frame back to back; report.json's
  // paired_ratio_motor_matrix), the ratio of the medians where no paired ratio was recorded.
  nlohmann::json frameTimes;
  std::string frameSource;
  std::string missing;         // why some input is absent
  // {scene id: timing JSON of report_timing.h (every timed pipeline)}, or null.
  nlohmann::json timings;
};
std::vector<Claim> speedClaims(const SpeedInputs& in);

// `corpusDir`: "" or a folder of .gltf/.glb files (recursively), measured with the built-in
// scenes.
std::vector<Claim> corpusClaims(const std::string& corpusDir);

// Skinning: ring radius of skinned_tube's candy_wrapper, LBS vs motor (claims_skinning.cpp).
std::vector<Claim> skinningClaims();

// Reviewer baselines (Verdict::Baseline): counted and SPIR-V.
std::vector<Claim> baselineClaims();

// Curved space (section "Curved space"): floats per instance, ops per vertex, frame time
// (when `runTiming`, `frames` per pipeline), drift over 10^6 steps. Needs GL.
std::vector<Claim> curvedClaims(bool runTiming, int frames);

// Every pipeline's bytes per vertex, floats per transform and joint (renders of built-in
// scenes), ops per vertex (counted and SPIR-V) and time ratios (`timings`: {scene: timing JSON},
// or null), the motor pipeline judged against the best matrix-side pipeline (issue 16); and the
// CPU kernels vertex_frame / skinned_vertex, the fastest motor implementation against the
// fastest matrix implementation measured (`kernelPairs`: report_bench's pairs, or null; issue 13).
std::vector<Claim> strongestBaselineClaims(const nlohmann::json& timings, const std::string& timingSource,
                                           const nlohmann::json& kernelPairs = nullptr,
                                           const std::string& kernelSource = "");

}  // namespace mb::claims
