#include "kernels/simd/simd_targets.h"

#include "hwy/highway.h"
#include "hwy/targets.h"

namespace mb::simd {

std::vector<Target> supportedTargets() {
  std::vector<Target> out;
  for (int64_t t : hwy::SupportedAndGeneratedTargets()) out.push_back({t, hwy::TargetName(t)});
  return out;  // Highway lists the lowest bit (the best target) first
}

Target currentTarget() {
  const std::vector<Target> all = supportedTargets();
  return all.empty() ? Target{} : all.front();
}

void forceTarget(int64_t bits) {
  // SetSupportedTargetsForTest re-initialises the dispatch tables (hwy::GetChosenTarget).
  hwy::SetSupportedTargetsForTest(bits);
}

}  // namespace mb::simd
