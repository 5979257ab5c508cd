#include "harness/render/gpu_option.h"

#include <cstdlib>

#include "pipelines/gl/egl_devices.h"
#include "pipelines/gl/gpu_choice.h"

namespace mb {

Status applyGpuOption(const options::Args& args) {
  auto choice = args.has("gpu") ? gl::parseGpuChoice(args.get("gpu", ""), "--gpu") : gl::gpuChoiceFromEnvironment();
  if (!choice) return Status::fail(choice.error());
  if (choice->kind == gl::GpuChoice::Kind::Device)
    if (auto device = gl::findEglDevice(*choice); !device) return Status::fail(device.error());
  setenv("MB_GPU", choice->text().c_str(), 1);
  return Status();
}

}  // namespace mb
