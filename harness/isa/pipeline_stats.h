// One graphics pipeline (vertex + fragment SPIR-V) built on a Vulkan device with
// VK_KHR_pipeline_executable_properties, and what the driver reports about each executable:
// its statistics (name -> value, in the driver's order) and its ISA text. Works on RADV's null
// device: only shader modules, layouts, a render pass and the pipeline are created.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/isa/spirv_interface.h"
#include "harness/isa/vulkan_loader.h"
#include "pipelines/result.h"

namespace mb::isa {

struct StageModule {
  std::vector<uint32_t> spirv;
  ShaderInterface interface;
};

struct ExecutableStats {
  std::string stage;  // "vertex", "fragment" (from the executable's stage bits)
  std::string name, description;
  uint32_t subgroupSize = 0;
  std::vector<std::pair<std::string, nlohmann::json>> statistics;  // driver order
  std::string isaText;  // the internal representation that is the machine code ("" if none)
};

struct DeviceInfo {
  std::string deviceName, driverName, driverInfo;  // e.g. "AMD RADV NAVI21", "radv", "Mesa 22.3.6"
  uint32_t driverId = 0, deviceType = 0;
  bool executableProperties = false;  // VK_KHR_pipeline_executable_properties offered
};

// The physical devices of an instance with their properties.
std::vector<std::pair<VkPhysicalDevice, DeviceInfo>> listDevices(const Vulkan& vk);

// A logical device with VK_KHR_pipeline_executable_properties enabled.
class StatsDevice {
public:
  static Result<std::unique_ptr<StatsDevice>> open(const Vulkan& vk, VkPhysicalDevice physical);
  ~StatsDevice();
  // Builds the pipeline (layout derived from both interfaces, vertex inputs from the vertex
  // interface) and returns every executable's statistics and ISA text. `name` labels errors.
  Result<std::vector<ExecutableStats>> compile(const StageModule& vertex, const StageModule& fragment,
                                              const std::string& name);

private:
  StatsDevice() = default;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mb::isa
