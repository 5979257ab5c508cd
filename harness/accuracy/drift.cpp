#include "harness/accuracy/drift.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "harness/accuracy/accuracy_figure.h"

namespace mb::accuracy {
namespace {

using json = nlohmann::json;

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

double totalOps(const json& ops) {
  double t = 0;
  for (const char* k : {"mul", "add", "div", "sqrt", "other"}) t += ops.value(k, 0.0);
  return t;
}

}  // namespace

void putDriftFigures(const json& drift, json& figures, json& details) {
  details["drift"] = drift;
  const std::string steps = std::to_string(drift.value("steps", int64_t(0)));
  const std::string step = drift.value("step", std::string());
  for (const json& sp : drift.value("spaces", json::array())) {
    const std::string space = sp.value("space", std::string("?"));
    const std::string scope = space + " camera accumulated over " + steps + " float steps (" + step + ")";
    const std::string distance = space == "S3" ? "matrix: max|M^T eta M - eta|; motor (quaternion pair): max(||L|^2 - 1|, ||R|^2 - 1|)"
                                               : "matrix: max|M^T eta M - eta|; motor: max(|M~M - 1|)";
    for (const char* side : {"matrix", "motor"}) {
      const json& d = sp.value(side, json::object());
      const std::string prefix = "drift." + lower(space) + "." + side + ".";
      const std::string method = d.value("renormalisation", std::string());
      const FigureText raw{"", "measured: distance from the group after the last step, one deterministic run", scope,
                           std::string(side) + " camera never renormalised; distance " + distance,
                           "CPU, float32 camera"};
      FigureText renorm = raw;
      renorm.definition = std::string(side) + " camera renormalised after every step (" + method + "); distance " + distance;
      putFigure(figures, prefix + "raw", d.value("raw", 0.0), 1, raw);
      putFigure(figures, prefix + "renormalised", d.value("renormalised", 0.0), 1, renorm);
      putFigure(figures, prefix + "renorm_ops", totalOps(d.value("renormOps", json::object())), 1,
                {"ops", "counted once by execution on the op-counting scalar", scope,
                 "arithmetic ops (mul + add + div + sqrt + other) of one renormalisation (" + method + ")",
                 "op-counting scalar"});
    }
  }
}

}  // namespace mb::accuracy
