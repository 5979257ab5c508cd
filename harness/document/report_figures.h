// report.json's "figures": every aggregate the report prints, computed once here
// from the scenes, op counts and kernel pairs it assembles, each with its definition
// (harness/figures/figure.h). The report text, the plots, claims and the README tables read
// them by name.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/figures/figure.h"

namespace mb::document {

// The total ops of an ops object: mul + add + div + sqrt + other (subtraction counts as addition,
// negation is free); NaN when `ops` is not an object.
double opsTotal(const nlohmann::json& ops);

// The device a frame time was measured on, from report.json's "machine" ("CPU rasterizer
// (llvmpipe ...)" or the GPU's GL_RENDERER).
std::string frameTimeDevice(const nlohmann::json& machine);

// Frame time motor / matrix of one scene's timing configuration (report_timing.h's JSON):
// the median of per-frame paired ratios with their IQR; NaN with `why` when not measured.
figures::Figure sceneFrameTimeFigure(const std::string& name, const nlohmann::json& config,
                                     const std::string& device);

// {name: figure} for the whole report: frame time (normal and vertex-bound, per scene and over
// scenes), bytes per vertex and floats per transform per pipeline, ops per vertex per pipeline
// (counted, SPIR-V of the probe, SPIR-V of the whole shader), CPU kernel time ratios.
nlohmann::json reportFigures(const nlohmann::json& machine, const nlohmann::json& settings,
                             const std::vector<nlohmann::json>& scenes, const nlohmann::json& ops,
                             const nlohmann::json& kernels);

// Adds the curved-space figures to `out`: per non-Euclidean scene curved.frame_time.<scene>.
// motor_over_matrix (and _vertex_bound) and curved.floats_per_instance.<scene>.<pipeline>; per
// space and side of `drift` (report.json's curved.drift) curved.drift.<space>.<side>.raw /
// .renormalised.
void curvedFigures(nlohmann::json& out, const std::vector<nlohmann::json>& scenes, const nlohmann::json& drift,
                   const std::string& device);

}  // namespace mb::document
