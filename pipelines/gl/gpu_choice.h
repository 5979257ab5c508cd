// Which GL device a run draws on: `--gpu auto|llvmpipe|N` (and MB_GPU for scripts and for the
// worker processes a command starts, which inherit it). Parsing and the software/hardware
// rule are pure functions, so they are tested without a GPU.
#pragma once
#include <string>

#include "pipelines/result.h"

namespace mb::gl {

struct GpuChoice {
  enum class Kind { Auto, Llvmpipe, Device };
  Kind kind = Kind::Auto;
  int index = -1;  // Device: the index as eglQueryDevicesEXT lists the devices
  std::string text() const;  // "auto", "llvmpipe" or the index
};

// "auto" (also ""), "llvmpipe" or a whole number 0..255; anything else is an error naming the
// value and the accepted forms (`origin` says where it came from: "--gpu", "MB_GPU").
Result<GpuChoice> parseGpuChoice(const std::string& text, const std::string& origin);

// The choice in MB_GPU (auto when unset). `--gpu` is applied by setting MB_GPU, so the option
// wins over the environment and child processes draw on the same device.
Result<GpuChoice> gpuChoiceFromEnvironment();

// True for GL_RENDERER strings of software rasterisers (llvmpipe, softpipe, swrast, lavapipe,
// SwiftShader): their "frame time" is CPU time, and their timer queries measure no GPU.
bool isSoftwareRenderer(const std::string& renderer);

}  // namespace mb::gl
