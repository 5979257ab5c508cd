// libFuzzer target for image decoding alone: PNG/JPEG bytes through exactly what the
// loader uses for an embedded or external image, pipelines/scene/gltf/image_decode.h (our header
// checks, then OpenImageIO's PNG or JPEG reader from memory). What is checked:
// tests/fuzz/fuzz_image_checks.h; a violation aborts. Seeds: tests/fuzz/seeds/images, findings
// in tests/fuzz/regressions/images. Build and run: scripts/fuzz.sh [SECONDS] (after the loader).
#include <cstdio>
#include <cstdlib>

#include "tests/fuzz/fuzz_image_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string e = mb::fuzz::checkImageDecode(data, size);
  if (!e.empty()) {
    std::fprintf(stderr, "fuzz_images: %s\n", e.c_str());
    std::abort();
  }
  return 0;
}
