// fuzz_seeds DIR: writes the fuzzer's seed corpus -- every built-in scene as .glb (through
// builtinSceneGlb, the bytes `motorbench scenes -o` writes), the hostile catalogue
// (tests/hostile/hostile_cases.h, both good and bad files) and the rich test document in its
// three forms (.glb, .gltf with data: URI). Deterministic: same files every run.
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "pipelines/scene/builtin_scenes.h"
#include "tests/hostile/hostile_cases.h"

namespace {
bool write(const std::filesystem::path& p, const std::vector<uint8_t>& b) {
  std::ofstream f(p, std::ios::binary);
  f.write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
  return f.good();
}
}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: fuzz_seeds DIR\n");
    return 2;
  }
  namespace fs = std::filesystem;
  using namespace mb::hostile;
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
