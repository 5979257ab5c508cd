// The minimum of work for a timed verdict: a scene whose timed block is shorter
// than 50 us, or that draws fewer than 1000 vertices, is listed but not counted — a 100 ns update
// of a one-node scene times the clock and the call, not the transforms.
#pragma once
#include <algorithm>
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "harness/claims/claims_model.h"
#include "harness/timing/frame_timing.h"

namespace mb::claims {

inline constexpr double kMinTimedMs = 0.05;

// The timed block of a CPU update (the rule printed is per timed block, so it is applied per
// block): R calls of `perCallMs` each, R as the timing recorded it
// ("updateCallsPerBlock"), else as the timing chooses it (enough calls for kMinUpdateBlockMs,
// at most 1000: harness/timing/frame_timing.h).
inline double updateBlockMs(double perCallMs, const nlohmann::json& pipelineTiming) {
  int r = pipelineTiming.is_object() ? pipelineTiming.value("updateCallsPerBlock", 0) : 0;
  if (r <= 0) r = perCallMs > 0 ? std::clamp(int(std::ceil(timing::kMinUpdateBlockMs / perCallMs)), 1, 1000) : 1;
  return perCallMs * r;
}
inline constexpr int kMinDrawnVertices = 1000;

// "" when a scene with these statistics (toJson(FileStats), or null: unknown) and this timed
// block (ms) may be counted; else why not, e.g. "0.0001 ms per update < 0.05 ms".
inline std::string belowMinimum(const nlohmann::json& stats, double timedMs, const char* block) {
  std::string why;
  if (timedMs < kMinTimedMs) why = fmt("%.4g ms per timed ", timedMs) + block + " block < " + fmt("%.2g ms", kMinTimedMs);
  const nlohmann::json geometry = stats.is_object() ? stats.value("geometry", nlohmann::json()) : nlohmann::json();
  if (geometry.is_object() && geometry.value("drawnVertices", nlohmann::json()).is_number()) {
    const int drawn = geometry["drawnVertices"].get<int>();
    if (drawn < kMinDrawnVertices)
      why += (why.empty() ? "" : ", ") + std::to_string(drawn) + " drawn vertices < " + std::to_string(kMinDrawnVertices);
  }
  return why;
}

inline std::string minimumRule() {
  return "scenes with less than " + fmt("%.0f us", kMinTimedMs * 1000) + " per timed block or fewer than " +
         std::to_string(kMinDrawnVertices) + " drawn vertices are listed but not counted";
}

}  // namespace mb::claims
