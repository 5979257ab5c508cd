// What the image fuzzer checks for one input, shared by tests/fuzz/fuzz_images.cpp (which aborts
// on a non-empty result) and the regression replay (tests/scene/test_scene_fuzz_regressions.cpp,
// regressions/images/): PNG/JPEG bytes through pipelines/scene/gltf/image_decode.h.
//   - a decoded image agrees with its header, is within the pixel limit and is w*h*4 bytes;
//   - a refused image has a non-empty, printable one-line reason (it ends up in JSON reports).
#pragma once
#include <cstdint>
#include <string>

#include "pipelines/scene/gltf/image_decode.h"

namespace mb::fuzz {

inline std::string checkImageDecode(const uint8_t* data, size_t size) {
  Result<ImageHeader> h = readImageHeader(data, size);
  Result<DecodedImage> d = decodeImage(data, size);
  if (d.ok()) {
    if (!h.ok()) return "decoded an image whose header was refused";
    if (d->width != int(h->width) || d->height != int(h->height)) return "decoded size differs from the header";
    if (uint64_t(d->width) * uint64_t(d->height) > kMaxImagePixels) return "decoded above the pixel limit";
    if (d->rgba.size() != size_t(d->width) * size_t(d->height) * 4) return "RGBA8 buffer of the wrong size";
    return "";
  }
  if (d.error().empty()) return "refused without a reason";
  for (unsigned char c : d.error())
    if (c < 0x20 || c >= 0x7F) return "reason is not printable one-line ASCII: " + d.error();
  return "";
}

}  // namespace mb::fuzz
