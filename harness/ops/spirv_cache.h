// On-disk memo of compileToDisassembly (spirv_count.h): the disassembly of an optimised module is
// a pure function of the GLSL text, the stage, the spirv-opt passes and the versions of glslang
// and SPIRV-Tools (spirv_compile.h), so it is kept under a key made of exactly those and read
// back instead of compiling again. The whole key is stored in the
// entry and compared on reading (no hash collision can return another shader's text).
// Where: $MB_CACHE_DIR, else $XDG_CACHE_HOME/motorbench, else $HOME/.cache/motorbench (a
// "spirv" folder inside). MB_CACHE_DIR=off turns it off; an unwritable folder just means no cache.
// compileToBinary keeps its SPIR-V modules here too, under keys of their own (the entry is the
// module's bytes instead of text).
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace mb::spirv {

// The cache's root folder ($MB_CACHE_DIR, else $XDG_CACHE_HOME/motorbench, else
// $HOME/.cache/motorbench); "" when MB_CACHE_DIR=off or no place is known. Other memos (the
// report's ISA document) keep a folder of their own inside it.
std::string cacheRoot();
// A 64-bit FNV-1a hash of `s`, for entry file names (the whole key is kept inside the entry).
uint64_t keyHash(const std::string& s);

// The key of one compilation: every input that decides its output.
std::string cacheKey(const std::string& source, const std::string& stage, const std::string& passes);

// The stored disassembly for `key`, if any.
std::optional<std::string> cachedDisassembly(const std::string& key);

// Stores `text` for `key` (written to a temporary file, then renamed: concurrent runs never
// read half an entry). Failures are ignored: the cache only saves time.
void storeDisassembly(const std::string& key, const std::string& text);

}  // namespace mb::spirv
