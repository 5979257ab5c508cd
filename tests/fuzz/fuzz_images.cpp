// libFuzzer target for image decoding alone (issue 20): PNG/JPEG bytes through exactly what the
// loader uses for an embedded or external image, pipelines/scene/image_decode.h (our header
// checks, then OpenImageIO's PNG or JPEG reader from memory). A violation aborts:
//   - a decoded image agrees with its header, is within the pixel limit and is w*h*4 bytes;
//   - a refused image has a non-empty, printable one-line reason (it ends up in JSON reports).
// Seeds: tests/fuzz/seeds/images. Build and run: scripts/fuzz.sh [SECONDS] (after the loader).
#include <cstdio>
#include <cstdlib>

#include "pipelines/scene/image_decode.h"

namespace {
[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "fuzz_images: %s\n", what);
  std::abort();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  mb::Result<mb::ImageHeader> h = mb::readImageHeader(data, size);
  mb::Result<mb::DecodedImage> d = mb::decodeImage(data, size);
  if (d.ok()) {
    if (!h.ok()) fail("decoded an image whose header was refused");
    if (d->width != int(h->width) || d->height != int(h->height)) fail("decoded size differs from the header");
    if (uint64_t(d->width) * uint64_t(d->height) > mb::kMaxImagePixels) fail("decoded above the pixel limit");
    if (d->rgba.size() != size_t(d->width) * size_t(d->height) * 4) fail("RGBA8 buffer of the wrong size");
  } else {
    if (d.error().empty()) fail("refused without a reason");
    for (unsigned char c : d.error())
      if (c < 0x20 || c >= 0x7F) fail("reason is not printable one-line ASCII");
  }
  return 0;
}
