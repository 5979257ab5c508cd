// Pixels a test counts itself from a PNG the command wrote, apart from the harness's drawnPixels.
#pragma once
#include <cstdint>
#include <filesystem>

#include "harness/render/image_metrics.h"

namespace mb::cli_test {

// Pixels whose RGB is not the clear colour (0.2, 0.2, 0.22) as 8-bit: 51, 51, 56; -1 when the
// file cannot be read.
inline int64_t nonBackground(const std::filesystem::path& png) {
  auto img = mb::readImage(png.string());
  if (!img) return -1;
  int64_t n = 0;
  for (size_t i = 0; i < img->rgba.size(); i += 4)
    n += !(img->rgba[i] == 51 && img->rgba[i + 1] == 51 && img->rgba[i + 2] == 56);
  return n;
}

}  // namespace mb::cli_test
