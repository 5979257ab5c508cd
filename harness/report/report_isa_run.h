// The AMD ISA evidence of a report that was given no --isa-json: `motorbench isa --json` run once
// as a child process (every shader variant compiled once on RADV's null device), its JSON kept in
// the report folder as isa.json and in a cache, so the next report on the same build, shaders and
// driver reads it instead of compiling again.
// Cache: $MB_CACHE_DIR, else $XDG_CACHE_HOME/motorbench, else $HOME/.cache/motorbench (an "isa"
// folder inside); MB_CACHE_DIR=off turns it off. The key: this executable (path, size, time), every
// file of the shader folder (contents) and the RADV driver manifest with the library it names
// (contents, size, time): a rebuilt binary, an edited shader or another Mesa measures again.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace mb::report {

struct IsaEvidence {
  nlohmann::json isa;     // the motorbench-isa/1 document, or {"error": why not}
  std::string source;     // "run", "cache"
  double seconds = 0;     // spent getting it
};

// Writes `outDir`/isa.json (when measured) and returns the evidence; never fails the report: a
// machine without RADV gets {"error": "..."} and the answer says "not measured: ...".
IsaEvidence measureIsa(const std::string& outDir, double timeoutS);

// The cache key of a run by `executable`, and its entry's path ("" when the cache is off). An
// entry is {"key": the whole key, "isa": the document}; one whose key differs is not read.
std::string isaCacheKey(const std::string& executable);
std::string isaCacheFile(const std::string& key);

}  // namespace mb::report
