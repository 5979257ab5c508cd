// fuzz_seeds DIR: writes the run-time part of the fuzzer's seeds -- every built-in scene as .glb
// (through builtinSceneGlb, the bytes `motorbench scenes -o` writes), the hostile catalogue
// (tests/hostile/hostile_cases.h, both good and bad files) and the rich test document in its
// three forms (.glb, .gltf with data: URI). Deterministic: same files every run.
// fuzz_seeds --repo DIR: writes the committed seed corpus (tests/fuzz/seed_corpus_scenes.cpp) to
// DIR/loader and DIR/images; run as `fuzz_seeds --repo tests/fuzz/seeds` after changing it.
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "pipelines/scene/builtin_scenes.h"
#include "tests/support/compressed_gltf.h"
#include "tests/fuzz/seed_files.h"
#include "tests/hostile/hostile_cases.h"

namespace {
bool write(const std::filesystem::path& p, const std::vector<uint8_t>& b) {
  std::ofstream f(p, std::ios::binary);
  f.write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
  return f.good();
}
}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  using namespace mb::hostile;
  if (argc == 3 && std::string(argv[1]) == "--repo") {
    size_t bytes = 0;
    int n = 0;
    for (const auto& [sub, files] : {std::pair{"loader", mb::fuzz::loaderSeeds()}, std::pair{"images", mb::fuzz::imageSeeds()}}) {
      const fs::path dir = fs::path(argv[2]) / sub;
      fs::remove_all(dir);
      fs::create_directories(dir);
      for (const auto& f : files) {
        if (f.bytes.empty()) {
          std::fprintf(stderr, "fuzz_seeds: %s came out empty\n", f.name.c_str());
          return 2;
        }
        n += write(dir / f.name, f.bytes);
        bytes += f.bytes.size();
      }
    }
    std::printf("fuzz_seeds: %d files, %zu bytes in %s\n", n, bytes, argv[2]);
    return 0;
  }
  if (argc != 2) {
    std::fprintf(stderr, "usage: fuzz_seeds DIR | fuzz_seeds --repo DIR\n");
    return 2;
  }
  const fs::path dir = argv[1];
  fs::create_directories(dir);
  int n = 0;
  for (const auto& name : mb::builtinSceneNames()) {
    auto glb = mb::builtinSceneGlb(name);
    if (!glb) {
      std::fprintf(stderr, "fuzz_seeds: %s\n", glb.error().c_str());
      return 2;
    }
    n += write(dir / ("builtin_" + name + ".glb"), *glb);
    // The small scenes again through the codecs' own encoders, so the fuzzer starts inside valid
    // Draco and meshopt streams (a mutation of them reaches the decoders' checks).
    if (name == "textured_box" || name == "skinned_tube") {
      n += write(dir / ("draco_" + name + ".glb"), mb::compressed::dracoCompressed(*glb));
      n += write(dir / ("meshopt_" + name + ".glb"), mb::compressed::meshoptCompressed(*glb));
    }
  }
  // Seeds should be small: libFuzzer mutates whole inputs, and its default max_len follows
  // the largest seed. Cases above 256 kB (deep hierarchies, JSON nesting) are left out.
  for (const Case& c : allCases())
    if (c.bytes.size() <= (size_t(256) << 10)) n += write(dir / ("hostile_" + c.file), c.bytes);
  Doc rich = richDoc();
  n += write(dir / "rich.glb", toGlb(rich));
  n += write(dir / "rich_embedded.gltf", toGltfEmbedded(rich));
  std::printf("fuzz_seeds: %d files in %s\n", n, dir.c_str());
  return 0;
}
