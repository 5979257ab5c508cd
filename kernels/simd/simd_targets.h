// The Highway targets the SIMD kernels were compiled for and the CPU supports, and a way to
// force one (tests run every kernel on each; `motorbench bench` names the one in use).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace mb::simd {

struct Target {
  int64_t bits = 0;  // HWY_* target bit
  std::string name;  // "AVX2", "AVX3" (AVX-512), "SSE4", ...
};

// Compiled and supported here, best first.
std::vector<Target> supportedTargets();

// The target the dispatch picks now.
Target currentTarget();

// Restricts dispatch to `t` (0: the CPU's full set again). For tests and comparisons only.
void forceTarget(int64_t bits);

}  // namespace mb::simd
