// `motorbench isa`'s measurement: every program (programs.h) compiled on RADV's null device for
// each family, one child process per family (RADV reads RADV_FORCE_FAMILY and RADV_DEBUG when
// the instance is created, so a family cannot change inside one process), and optionally on
// every Vulkan device for real hardware that offers VK_KHR_pipeline_executable_properties.
#pragma once
#include <string>
#include <vector>

#include "harness/isa/families.h"
#include "harness/isa/pipeline_stats.h"
#include "harness/isa/programs.h"
#include "pipelines/result.h"

namespace mb::isa {

struct ShaderStats {
  size_t program = 0;  // index into IsaRun::programs
  size_t family = 0;   // index into IsaRun::families (or IsaRun::devices for device rows)
  ExecutableStats exe;
  int interpolants = 0;  // fragment: inputs of the fragment shader (the occupancy rule's LDS term)
  // The statistic `name` as a whole number; -1 when the driver did not give it.
  long long stat(const std::string& name) const;
  int wavesPerSimd(const Family& f) const;  // our rule (families.h)
};

struct FamilyRun {
  Family family;
  std::string device;  // "Null hardware (RADV NAVI21)"
};

struct DeviceRun {
  std::string device, driver;
  std::vector<ShaderStats> shaders;
};

struct IsaRun {
  std::string driver;  // "Mesa 22.3.6"
  std::vector<Program> programs;
  std::vector<FamilyRun> families;
  std::vector<ShaderStats> shaders;  // sorted: program, stage (vertex first), family
  // --device: what was seen and the devices measured.
  bool deviceAsked = false;
  std::string deviceNote;
  std::vector<DeviceRun> devices;
};

struct IsaOptions {
  std::vector<Family> families = allFamilies();
  bool keepIsaText = false;
  bool device = false;
  int jobs = 0;  // child processes at once; 0: the number of cores
};

// Errors name what is missing: the Vulkan loader, RADV's driver manifest (or a
// VK_ICD_FILENAMES / VK_DRIVER_FILES entry that does not exist), a family RADV did not create.
Result<IsaRun> runIsa(const IsaOptions& options);

// The RADV driver manifest the children load: VK_DRIVER_FILES / VK_ICD_FILENAMES as given (each
// entry must exist), else radeon_icd.<arch>.json from the loader's search folders.
Result<std::string> radvManifest();

}  // namespace mb::isa
