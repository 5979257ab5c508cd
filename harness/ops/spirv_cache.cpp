#include "harness/ops/spirv_cache.h"

#include "harness/ops/spirv_compile.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace mb::spirv {

namespace fs = std::filesystem;

uint64_t keyHash(const std::string& s) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  return h;
}

std::string cacheRoot() {
  if (const char* dir = std::getenv("MB_CACHE_DIR")) return std::string(dir) == "off" ? "" : dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return (fs::path(xdg) / "motorbench").string();
  if (const char* home = std::getenv("HOME"); home && *home) return (fs::path(home) / ".cache" / "motorbench").string();
  return "";
}

namespace {

// "" when the cache is off or has no place.
fs::path cacheFolder() {
  const std::string root = cacheRoot();
  return root.empty() ? fs::path() : fs::path(root) / "spirv";
}

fs::path entryPath(const std::string& key) {
  const fs::path dir = cacheFolder();
  if (dir.empty()) return {};
  char name[32];
  std::snprintf(name, sizeof name, "%016llx.spvasm", static_cast<unsigned long long>(keyHash(key)));
  return dir / name;
}

}  // namespace

std::string cacheKey(const std::string& source, const std::string& stage, const std::string& passes) {
  return "motorbench spirv cache 2\n" + toolchainVersion() + "\nstage " + stage + "\npasses " + passes + "\n" + source;
}

std::optional<std::string> cachedDisassembly(const std::string& key) {
  const fs::path p = entryPath(key);
  if (p.empty()) return std::nullopt;
  std::ifstream in(p, std::ios::binary);
  if (!in) return std::nullopt;
  // Entry: the key's length, newline, the key, the disassembly.
  size_t length = 0;
  if (!(in >> length) || in.get() != '\n' || length != key.size()) return std::nullopt;
  std::string stored(length, '\0');
  if (!in.read(stored.data(), std::streamsize(length)) || stored != key) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void storeDisassembly(const std::string& key, const std::string& text) {
  const fs::path p = entryPath(key);
  if (p.empty()) return;
  std::error_code ec;
  fs::create_directories(p.parent_path(), ec);
  const fs::path tmp = p.string() + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!(out << key.size() << '\n' << key << text)) {
      fs::remove(tmp, ec);
      return;
    }
  }
  fs::rename(tmp, p, ec);
  if (ec) fs::remove(tmp, ec);
}

}  // namespace mb::spirv
