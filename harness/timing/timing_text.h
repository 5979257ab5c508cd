// The text `motorbench time` prints: one block per scene and configuration,
// one row per pipeline (every pipeline of the scene's space), each ratio to the space's matrix
// pipeline with its spread [q1-q3] over the per-frame ratios and "noise" where that spread
// reaches both sides of 1. Scene names head their block, so long paths never shift columns.
#pragma once
#include <string>

#include "harness/timing/frame_timing.h"

namespace mb::timing {

// Fewer paired frames than this give no spread to judge a ratio by: from 5 on, the median and
// the two quartiles are three different frames (with 1 frame all three are that frame).
inline constexpr int kMinRatioFrames = 5;

// A ratio's spread over paired per-frame ratios.
struct RatioText {
  Spread spread;  // n == 0: not measured
  // Both quartiles on different sides of 1 (or on it): the frames do not decide which is faster.
  bool noise() const { return spread.n > 0 && spread.q1 <= 1.0 && spread.q3 >= 1.0; }
  bool tooFewFrames() const { return spread.n > 0 && spread.n < kMinRatioFrames; }
  // "0.874 [0.801-0.950] noise", "1.020 [1.020-1.020] too few frames (1 < 5)", "-" when not measured
  std::string text() const;
};
RatioText pairedRatio(const std::vector<double>& baseline, const std::vector<double>& other);

// The line printed once above the blocks: what a ratio is, "< 1: motor faster", what "noise" is.
std::string timingLegend();
// One configuration's block: header "scene (config WxH)", a row per pipeline (frame ms, CPU
// update us, frame/matrix, update/matrix, each with its spread), the paired and of-medians
// motor/matrix frame ratio and the CPU-time ratio, then the update phases per pipeline and
// the vertices drawn (instances counted) per microsecond of median frame time.
std::string timingBlock(const ConfigTiming& c);

}  // namespace mb::timing
