// The fuzz build's own copy of the tinygltf and stb_image implementations, compiled with
// coverage and sanitizer instrumentation. The Debian libtinygltf.so is built without either, so
// linking it would leave the fuzzer blind inside the JSON/GLB/image parsing it most needs to
// explore, and ASan unable to see out-of-bounds accesses there. Used only by tests/fuzz.
#if defined(__clang__)
#pragma clang diagnostic ignored "-Weverything"
#endif
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
