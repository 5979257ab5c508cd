#include "harness/accuracy/accuracy_figure.h"

#include <cmath>

namespace mb::accuracy {

void putFigure(nlohmann::json& figures, const std::string& name, double value, int n, const FigureText& text) {
  figures::Figure f;
  f.kind = "measured";
  f.name = name;
  f.value = value;
  f.n = n;
  f.unit = text.unit;
  f.statistic = text.statistic;
  f.scope = text.scope;
  f.definition = text.definition;
  f.device = text.device;
  f.why = std::isfinite(value) ? "" : text.why.empty() ? "nothing to measure" : text.why;
  figures::put(figures, f);
}

}  // namespace mb::accuracy
