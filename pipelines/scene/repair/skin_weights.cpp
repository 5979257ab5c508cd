#include "pipelines/scene/repair/skin_weights.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace mb {

void reduceInfluences(const uint32_t* joints, const float* weights, int n, uint32_t jointCount,
                      glm::u16vec4* outJoints, glm::vec4* outWeights, InfluenceReport* report) {
  *report = InfluenceReport{};
  struct Inf { uint32_t joint; float weight; };
  std::vector<Inf> infs;
  infs.reserve(size_t(n));
  int nonZero = 0;
  for (int i = 0; i < n; ++i) {
    float w = weights[i];
    if (!(w > 0.0f) || !std::isfinite(w)) continue;  // NaN, negative, zero
    if (joints[i] >= jointCount || joints[i] > 0xFFFFu) {
      ++report->jointsOutOfRange;
      continue;
    }
    ++nonZero;
    infs.push_back({joints[i], w});
  }
  report->truncated = nonZero > 4;
  std::stable_sort(infs.begin(), infs.end(),
                   [](const Inf& a, const Inf& b) { return a.weight > b.weight; });
  if (infs.size() > 4) infs.resize(4);
  double sum = 0.0;
  for (const auto& f : infs) sum += f.weight;
  *outJoints = glm::u16vec4(0);
  *outWeights = glm::vec4(0.0f);
  if (!(sum > 0.0)) {
    report->zeroSum = true;
    outWeights->x = 1.0f;
    return;
  }
  double authored = 0.0;
  for (int i = 0; i < n; ++i) authored += std::isfinite(weights[i]) ? weights[i] : 0.0f;
  report->renormalised = std::fabs(authored - 1.0) > 1e-3 || std::fabs(sum - 1.0) > 1e-3;
  for (size_t k = 0; k < infs.size(); ++k) {
    (*outJoints)[int(k)] = uint16_t(infs[k].joint);
    (*outWeights)[int(k)] = float(infs[k].weight / sum);
  }
}

}  // namespace mb
