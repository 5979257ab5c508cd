#include "harness/bench/fastest_sides.h"

#include <cstdio>

#include "harness/bench/bench_common.h"

namespace mb::bench {

FastestSides fastestSides(const nlohmann::json& pair) {
  FastestSides f;
  if (!pair.is_object()) return f;
  for (const auto& [side, fig] : pair.items()) {
    const std::string kind = sideKind(side);
    if (kind.empty() || !fig.is_object() || !fig.contains("items_per_second") ||
        !fig["items_per_second"].is_number())
      continue;
    const nlohmann::json dist = fig.value("disturbance", nlohmann::json());
    if (dist.is_object() && dist.value("disturbed", false)) f.disturbed[side] = dist.value("reason", "");
    const double ips = fig["items_per_second"].get<double>();
    if (!(ips > 0)) continue;
    char b[64];
    std::snprintf(b, sizeof b, "%.3g", ips);
    f.all += (f.all.empty() ? "" : ", ") + side + " " + b;
    if (kind == "motor") {
      if (ips > f.motor) f.motor = ips, f.motorSide = side;
    } else if (ips > f.matrix) {
      f.matrix = ips, f.matrixSide = side;
    }
  }
  return f;
}

}  // namespace mb::bench
