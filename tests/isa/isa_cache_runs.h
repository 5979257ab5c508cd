// The isa room's `motorbench isa` runs share one SPIR-V cache of their own (MB_CACHE_DIR in a
// scratch folder), filled once per test process: its first run finds the cache empty and compiles
// every module with glslang (~140 glslangValidator processes, ~45 s of CPU, whatever the user's
// cache holds), the second run of the same families reads every module back
// (CliIsa.TwoRunsGiveIdenticalFiles compares the two), and every later isa run of the room starts
// from the filled cache instead of compiling again. The room therefore runs as one process
// (tests/isa/CMakeLists.txt: no shards), TwoRunsGiveIdenticalFiles first (registered first).
#pragma once
#include <array>
#include <filesystem>
#include <string>

#include "tests/support/cli_test_support.h"

namespace mb::isa_test {

struct ColdThenCachedRuns {
  std::filesystem::path dir;    // a.json, a_isa/ (run a); b.json, b_isa/ (run b); cache/
  std::array<int, 2> rc{};      // exit status of run a and run b
  std::array<std::string, 2> output;
};

// Whether runs a and b have run in this process.
inline bool& coldThenCachedRunsDone() {
  static bool done = false;
  return done;
}

// Runs a (empty cache: glslang) and b (the cache a filled) on polaris10 and navi21-ngg, once.
inline const ColdThenCachedRuns& coldThenCachedRuns() {
  using namespace mb::cli_test;
  static const ColdThenCachedRuns runs = [] {
    ColdThenCachedRuns r;
    r.dir = scratchDir("isa_twice");  // new and empty, so is cache/ inside it
    const std::string cache = "MB_CACHE_DIR=" + quoted(r.dir / "cache") + " ";
    for (int i = 0; i < 2; ++i) {
      const std::string name = i == 0 ? "a" : "b";
      r.rc[i] = runCommand(cache + motorbench() + "isa --family polaris10,navi21-ngg --json " +
                               quoted(r.dir / (name + ".json")) + " --isa-text " + quoted(r.dir / (name + "_isa")),
                           &r.output[i]);
    }
    coldThenCachedRunsDone() = true;
    return r;
  }();
  return runs;
}

// "MB_CACHE_DIR='<the filled cache>' " for the room's other isa runs once runs a and b have run in
// this process; before that (a test run alone) "", the user's cache: a later run a must still
// find its cache empty.
inline std::string filledIsaCacheIfAny() {
  if (!coldThenCachedRunsDone()) return "";
  return "MB_CACHE_DIR=" + mb::cli_test::quoted(coldThenCachedRuns().dir / "cache") + " ";
}

}  // namespace mb::isa_test
