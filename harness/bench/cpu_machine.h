// The machine a CPU figure was measured on: CPU model, logical cores and the Highway target the
// SIMD kernels dispatch to. CPU kernel ratios change with the CPU (a 16-core Xeon
// measured vertex_frame shim motor/matrix 0.32 where a 2-core EPYC measured 1.03), so every
// CPU table (bench summary, report kernel and update tables) prints this line above it.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace mb::bench {

struct CpuMachine {
  std::string cpu;         // /proc/cpuinfo "model name", "unknown" without it
  unsigned logicalCores = 0;
  std::string simdTarget;  // the Highway target in use ("AVX2", "AVX3" = AVX-512, ...)
};

CpuMachine cpuMachine();

// "CPU: <model>, <n> logical cores; SIMD kernels: Highway <target>".
std::string cpuMachineLine(const CpuMachine& m);

nlohmann::json toJson(const CpuMachine& m);

// `motorbench bench --simd-target NAME`: the SIMD kernels dispatch to the Highway target NAME
// ("AVX3", "AVX2", "SSE4", ...) for the rest of the process, so each pair can be measured per
// target. Returns "" when done, else why not (not a target this CPU supports, with the list).
std::string forceSimdTarget(const std::string& name);

}  // namespace mb::bench
