#include "harness/figures/figure_statistics.h"

#include <algorithm>
#include <cmath>

namespace mb::figures {

double quantileSorted(const std::vector<double>& sorted, double p) {
  if (sorted.empty()) return std::nan("");
  const double pos = p * double(sorted.size() - 1);
  const size_t lo = size_t(std::floor(pos));
  const size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (pos - double(lo)) * (sorted[hi] - sorted[lo]);
}

Quartiles quartilesOf(std::vector<double> samples) {
  samples.erase(std::remove_if(samples.begin(), samples.end(), [](double x) { return !std::isfinite(x); }),
                samples.end());
  Quartiles q;
  if (samples.empty()) return q;
  std::sort(samples.begin(), samples.end());
  q.n = int(samples.size());
  q.min = samples.front(), q.max = samples.back();
  q.q1 = quantileSorted(samples, 0.25);
  q.median = quantileSorted(samples, 0.5);
  q.q3 = quantileSorted(samples, 0.75);
  return q;
}

std::vector<double> pairedRatios(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> r;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    if (a[i] > 0 && std::isfinite(a[i]) && std::isfinite(b[i])) r.push_back(b[i] / a[i]);
  return r;
}

double midpointMedian(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

nlohmann::json spread(std::vector<double> v) {
  if (v.empty()) return {{"n", 0}};
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return {{"n", n}, {"min", v.front()}, {"median", midpointMedian(v)}, {"max", v.back()}};
}

}  // namespace mb::figures
