#include "harness/claims/claims_device.h"

#include <cmath>

#include "harness/claims/claims_model.h"

namespace mb::claims {

std::string TimingDevice::label() const {
  if (!known) return "unknown device (no machine.gl in the timing's source)";
  return std::string(cpuRasterizer ? "CPU rasterizer (" : "GPU (") + renderer + ")";
}

TimingDevice timingDevice(const nlohmann::json& machine) {
  TimingDevice d;
  const nlohmann::json gl = machine.is_object() ? machine.value("gl", nlohmann::json()) : nlohmann::json();
  if (!gl.is_object() || !gl.value("renderer", nlohmann::json()).is_string()) return d;
  d.known = true;
  d.renderer = gl["renderer"].get<std::string>();
  if (gl.value("kind", nlohmann::json()).is_string()) {
    d.cpuRasterizer = gl["kind"].get<std::string>() != "gpu";
  } else if (gl.value("realGpu", nlohmann::json()).is_boolean()) {
    d.cpuRasterizer = !gl["realGpu"].get<bool>();
  } else {
    d.cpuRasterizer = false;
    for (const char* sw : {"llvmpipe", "softpipe", "lavapipe", "swrast", "SwiftShader"})
      d.cpuRasterizer |= d.renderer.find(sw) != std::string::npos;
  }
  return d;
}

std::optional<AlikePair> timedAlike(const std::map<std::string, double>& times,
                                    const std::map<std::string, double>& ops) {
  std::optional<AlikePair> worst;
  for (const auto& [p, tp] : times)
    for (const auto& [q, tq] : times) {
      if (!ops.count(p) || !ops.count(q) || ops.at(p) <= ops.at(q)) continue;
      const double r = ops.at(p) / ops.at(q);
      if (r > kDiscriminateOps && std::fabs(tp / tq - 1.0) <= kTimeTolerance && (!worst || r > worst->opsRatio))
        worst = AlikePair{p, q, r, tp / tq};
    }
  return worst;
}

std::string cpuScope(const nlohmann::json& machine) {
  if (!machine.is_object() || !machine.value("cpu", nlohmann::json()).is_string()) return "an unrecorded CPU";
  std::string s = machine["cpu"].get<std::string>();
  if (machine.value("logicalCores", nlohmann::json()).is_number())
    s += " (" + std::to_string(machine["logicalCores"].get<int>()) + " logical cores";
  else
    s += " (cores not recorded";
  for (const char* key : {"highwayTarget", "simdTarget"})
    if (machine.value(key, nlohmann::json()).is_string()) s += ", SIMD target " + machine[key].get<std::string>();
  return s + ")";
}

}  // namespace mb::claims
