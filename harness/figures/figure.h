// One figure the tool prints, with its definition beside its value (DESIGN.md core idea 7).
// A run's JSON holds its figures as {"figures": {name: toJson(figure)}}; readers look them up
// by name (figureNamed) and print figureText, never recompute them.
#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "harness/figures/figure_statistics.h"

namespace mb::figures {

struct Figure {
  std::string name;        // stable key, e.g. "frame_time.motor_over_matrix"
  double value = 0;        // NaN: not measured (then `why` says so)
  std::string unit;        // "x" (a ratio), "bytes", "ops", "dB", "ms", "files", ...
  // What kind of figure it is: "measured" (run and observed: uploads, images, times, counts a
  // run made), "counted" (ops executed on the op-counting scalar), "compiled" (read from a
  // compiler's output: SPIR-V, RADV's null-device statistics; not timed) or "modelled"
  // (meshoptimizer's vertex-fetch model).
  std::string kind;
  std::string statistic;   // e.g. "median over scenes of each scene's median of per-frame paired ratios"
  std::optional<double> q1, q3;  // spread: the interquartile range of what `statistic` aggregates
  std::string scope;       // what was measured, e.g. "whole frame, Euclidean scenes, 512x512"
  std::string device;      // where: "CPU rasterizer (llvmpipe ...)", "AMD EPYC ...", "op-counting scalar"
  int n = 0;               // samples the statistic aggregates (scenes, frames, files)
  std::string tolerance;   // the tolerance that decides ties or counts, "" when none applies
  std::string definition;  // one sentence: how the value is computed, and which side is which
  std::string why;         // non-empty only when value is NaN: why it is missing
  // Disturbance mark of a timed figure (CPU vs real time, load); null: not assessed.
  nlohmann::json disturbed;
};

// The figure with `q`'s median as its value and its quartiles as its spread.
Figure withQuartiles(Figure f, const Quartiles& q);

// Whether a timed figure's disturbance mark says it was disturbed (null: not assessed, so no).
bool isDisturbed(const Figure& f);

// A JSON number as a double; NaN for anything else (null, missing, text).
double numberOrNaN(const nlohmann::json& v);

nlohmann::json toJson(const Figure& f);
Figure figureFromJson(const std::string& name, const nlohmann::json& j);

// Adds `f` to a {name: figure} object (replacing one of the same name).
void put(nlohmann::json& figures, const Figure& f);
// The figure `name` of a run JSON's "figures" object (or of the object itself), or nullopt.
std::optional<Figure> figureNamed(const nlohmann::json& runOrFigures, const std::string& name);

// The value as printed everywhere: "%.3g" plus the unit ("0.971x", "36 bytes"); "-" for NaN.
std::string valueText(const Figure& f);
// Value, spread and definition in one line: "0.971x [0.95..0.99] (median of ..., n = 8,
// scope ..., device ...)".
std::string figureText(const Figure& f);

}  // namespace mb::figures
