// The statistics every figure uses, defined once (one statistic per kind of figure).
// Times: the median of per-frame paired ratios with their interquartile range; aggregates over
// scenes: the median with the interquartile range over the scenes' own figures.
//
// Two medians, equal in exact arithmetic but not always in the last bit of a double:
// quantileSorted(sorted, 0.5) (a + 0.5 * (b - a) for an even count) is the median of every
// Figure (withQuartiles: frame times, the figures over scenes) and of frame_timing's samples;
// midpointMedian (0.5 * (a + b)) is the median of report.json's spreads (summary min / median /
// max over scenes) and of each pipeline's conversionMs in a scene's report.
#pragma once
#include <vector>

#include <nlohmann/json.hpp>

namespace mb::figures {

struct Quartiles {
  double q1 = 0, median = 0, q3 = 0, min = 0, max = 0;
  int n = 0;  // 0: no samples (every other field meaningless)
};

// The p-quantile (0..1) of `sorted` by linear interpolation between closest ranks
// (position p * (n - 1)); the median of an even count is the mean of the middle two.
double quantileSorted(const std::vector<double>& sorted, double p);
// Quartiles of `samples` (NaN samples dropped).
Quartiles quartilesOf(std::vector<double> samples);
// Per-frame ratios b[i] / a[i] of two series of the same frames (pairs where a[i] > 0 and
// both are finite), in frame order.
std::vector<double> pairedRatios(const std::vector<double>& a, const std::vector<double>& b);
// The median of `v`: the middle sample of an odd count, 0.5 * (a + b) of the middle two of an
// even count; 0 when empty.
double midpointMedian(std::vector<double> v);
// min / midpointMedian / max of `values`: {"n", "min", "median", "max"} ({"n": 0} when empty).
nlohmann::json spread(std::vector<double> values);

}  // namespace mb::figures
