#include "pipelines/gl/gpu_choice.h"

#include <cstdlib>

namespace mb::gl {

std::string GpuChoice::text() const {
  return kind == Kind::Device ? std::to_string(index) : kind == Kind::Llvmpipe ? "llvmpipe" : "auto";
}

Result<GpuChoice> parseGpuChoice(const std::string& text, const std::string& origin) {
  if (text.empty() || text == "auto") return GpuChoice{};
  if (text == "llvmpipe") return GpuChoice{.kind = GpuChoice::Kind::Llvmpipe};
  const bool digits = text.size() <= 3 && text.find_first_not_of("0123456789") == std::string::npos;
  if (!digits || std::stoi(text) > 255)
    return Result<GpuChoice>::fail(origin + " " + text +
                                   ": expected auto, llvmpipe or an EGL device index 0..255");
  return GpuChoice{.kind = GpuChoice::Kind::Device, .index = std::stoi(text)};
}

Result<GpuChoice> gpuChoiceFromEnvironment() {
  const char* env = std::getenv("MB_GPU");
  return parseGpuChoice(env ? env : "", "MB_GPU");
}

bool isSoftwareRenderer(const std::string& renderer) {
  for (const char* sw : {"llvmpipe", "softpipe", "swrast", "lavapipe", "SwiftShader", "Software"})
    if (renderer.find(sw) != std::string::npos) return true;
  return false;
}

}  // namespace mb::gl
