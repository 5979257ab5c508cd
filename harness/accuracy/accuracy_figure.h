// How this room writes one figure: every figure states its value, unit, the statistic that
// produced it, what it aggregates (n), its scope and a one-sentence definition.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "harness/figures/figure.h"

namespace mb::accuracy {

struct FigureText {
  std::string unit, statistic, scope, definition;
  std::string device = "CPU, double precision";
  std::string why;  // when the value is NaN: why nothing was measured
};

// Adds the figure `name` = `value` over `n` samples to the {name: figure} object `figures`.
void putFigure(nlohmann::json& figures, const std::string& name, double value, int n, const FigureText& text);

}  // namespace mb::accuracy
