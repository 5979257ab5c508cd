// One kernel pair of report_bench.h's kernelPairs() reduced to the fastest implementation on
// each side, whatever sides the bench registers: bench::sideKind says which side a name is
// ("motor", "simd_motor": motor; "matrix", "glm", "simd_matrix", "simd_affine": matrix). Fair in
// both directions: a faster motor implementation counts as much as a faster matrix one. The
// bench summary (fastest_matrix / fastest_motor) and the claims read the pair through this.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace mb::bench {

struct FastestSides {
  double motor = 0, matrix = 0;      // items/s of the fastest side of each kind (0: none)
  std::string motorSide, matrixSide;  // their names
  std::string all;                    // "matrix 1.2e+08, glm 3.4e+08, motor 1.1e+08" (items/s)
  // {side: reason} of every side whose figure was disturbed (report_bench's "disturbance").
  nlohmann::json disturbed = nlohmann::json::object();
  // motor time / fastest matrix time per item (< 1: motor faster); -1 when a side is missing or
  // any side was disturbed (not a verdict input).
  double costRatio() const { return motor > 0 && matrix > 0 && disturbed.empty() ? matrix / motor : -1.0; }
};

// Entries of `pair` that are not a side (kernel, size, ratios) or have no positive items/s
// are skipped.
FastestSides fastestSides(const nlohmann::json& pair);

}  // namespace mb::bench
