// tinygltf's implementation, compiled here instead of linking Debian's libtinygltf.so, which
// decodes images with stb_image. Built with TINYGLTF_NO_STB_IMAGE (set on mb_scene for every
// file that includes tiny_gltf.h): no image byte of a loaded file reaches stb_image; the loader
// installs its own image callback (gltf_loader.cpp -> image_decode.h, OpenImageIO).
// stb_image_write stays, privately (static functions): tinygltf's writer encodes the built-in
// scenes' procedural textures as PNG with it; it only ever sees pixels we generated.
// The fuzz build compiles this same file with coverage and sanitizers (tests/fuzz). Third-party
// code: compiled without warnings (-w, CMakeLists.txt).
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
