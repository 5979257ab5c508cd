#include "harness/bench/cpu_machine.h"

#include <fstream>
#include <thread>

#include "kernels/simd/simd_targets.h"

namespace mb::bench {

CpuMachine cpuMachine() {
  CpuMachine m{"unknown", std::thread::hardware_concurrency(), simd::currentTarget().name};
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
      const size_t value = line.find_first_not_of(' ', line.find(':') + 1);
      if (value != std::string::npos) m.cpu = line.substr(value);
      break;
    }
  if (m.simdTarget.empty()) m.simdTarget = "none";
  return m;
}

std::string cpuMachineLine(const CpuMachine& m) {
  return "CPU: " + m.cpu + ", " + (m.logicalCores ? std::to_string(m.logicalCores) : std::string("unknown")) +
         " logical cores; SIMD kernels: Highway " + m.simdTarget;
}

nlohmann::json toJson(const CpuMachine& m) {
  return {{"cpu", m.cpu}, {"logicalCores", m.logicalCores}, {"simdTarget", m.simdTarget}};
}

std::string forceSimdTarget(const std::string& name) {
  std::string names;
  for (const simd::Target& t : simd::supportedTargets()) {
    if (t.name == name) {
      simd::forceTarget(t.bits);
      return "";
    }
    names += (names.empty() ? "" : ", ") + t.name;
  }
  return "--simd-target '" + name + "' is not a target this CPU supports (" + names + ")";
}

}  // namespace mb::bench
