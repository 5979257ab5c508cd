// Small images tests build by hand: one colour everywhere, and a pixel's channel to set.
#pragma once
#include <cstdint>

#include "harness/render/image_metrics.h"

namespace mb::test_images {

// A w x h image of one opaque colour.
inline RgbaImage solid(int w, int h, uint8_t r, uint8_t g, uint8_t b) {
  RgbaImage img{w, h, {}};
  for (int i = 0; i < w * h; ++i) img.rgba.insert(img.rgba.end(), {r, g, b, 255});
  return img;
}

// Channel c (0..3: R, G, B, A) of pixel (x right, y down).
inline uint8_t& at(RgbaImage& img, int x, int y, int c) {
  return img.rgba[(size_t(y) * size_t(img.width) + size_t(x)) * 4 + size_t(c)];
}

}  // namespace mb::test_images
