// libFuzzer target for the glTF loader and the scene conversion pipelines rely on: see
// tests/fuzz/fuzz_exercise.h for what each input goes through. A violation aborts, which libFuzzer
// records as a crash. Build and run: scripts/fuzz.sh [SECONDS].
#include <cstdio>
#include <cstdlib>

#include "tests/fuzz/fuzz_exercise.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string e = mb::fuzz::exercise(data, size);
  if (!e.empty()) {
    std::fprintf(stderr, "fuzz_loader: %s\n", e.c_str());
    std::abort();
  }
  return 0;
}
