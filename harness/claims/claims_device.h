// Which device a frame time was measured on, from report.json's machine.gl ("kind"
// "gpu" | "cpu-rasterizer" and "renderer"; older reports: "realGpu" and the renderer string), so
// that every timing verdict names its device and one from a CPU rasterizer says so.
#pragma once
#include <map>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace mb::claims {

struct TimingDevice {
  bool known = false;          // machine.gl says what it is
  bool cpuRasterizer = false;  // llvmpipe, softpipe, lavapipe, swrast: times follow the CPU, not a GPU
  std::string renderer;        // GL_RENDERER as recorded
  // "CPU rasterizer (llvmpipe (LLVM 15.0.6, 256 bits))", "GPU (NVIDIA H100 80GB HBM3/PCIe/SSE2)",
  // "unknown device (no machine.gl in the timing's source)".
  std::string label() const;
};

TimingDevice timingDevice(const nlohmann::json& machine);

// Two timed pipelines whose counted ops differ by more than kDiscriminateOps but whose times agree
// within kTimeTolerance: a device that times unequal arithmetic alike cannot discriminate it.
// The pair with the largest ops ratio, `dearer` the one with more ops.
inline constexpr double kDiscriminateOps = 1.25;
struct AlikePair {
  std::string dearer, cheaper;
  double opsRatio = 0, timeRatio = 0;  // dearer / cheaper
};
// `times` and `ops` per pipeline; pipelines missing from either are skipped. nullopt: none.
std::optional<AlikePair> timedAlike(const std::map<std::string, double>& times,
                                    const std::map<std::string, double>& ops);

// "CPU verdicts hold for <cpu> (<n> logical cores[, Highway target T])": CPU results depend on
// the CPU.
std::string cpuScope(const nlohmann::json& machine);

}  // namespace mb::claims
