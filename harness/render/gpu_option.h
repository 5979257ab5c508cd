// `--gpu auto|llvmpipe|N`, the option of every command that renders or times: checked before
// any work and handed to the GL context through MB_GPU (pipelines/gl/gpu_choice.h), so the
// option wins over the environment and the command's worker processes draw on the same device.
#pragma once
#include <string>

#include "harness/options/args.h"
#include "pipelines/result.h"

namespace mb {

inline constexpr const char* kGpuOptionUsage = "[--gpu auto|llvmpipe|N]";
// Its lines under "options:" in every such command's help (a macro: help texts are literals joined
// at compile time).
#define MB_GPU_OPTION_HELP \
  "  --gpu auto|llvmpipe|N  the GL device that draws (default auto: the first hardware EGL device, else\n" \
  "                     llvmpipe; N: an EGL device index); the option wins over the environment's MB_GPU\n"

// Reads --gpu (else MB_GPU): a malformed value, or a device index that eglQueryDevicesEXT does
// not list, is an error naming it (the latter lists the devices seen). Sets MB_GPU.
Status applyGpuOption(const options::Args& args);

}  // namespace mb
