#include "harness/report/report_isa_run.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "harness/ops/spirv_cache.h"
#include "harness/process/report_workers.h"
#include "pipelines/gl/shader_source.h"

namespace mb::report {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;


std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// "path size mtime" of a file ("path missing" when it is not there).
std::string fileStamp(const fs::path& p) {
  struct stat st {};
  if (::stat(p.c_str(), &st) != 0) return p.string() + " missing\n";
  return p.string() + " " + std::to_string(st.st_size) + " " + std::to_string(st.st_mtim.tv_sec) + "." +
         std::to_string(st.st_mtim.tv_nsec) + "\n";
}

// The RADV manifests the isa children would load (as isa_run.cpp's radvManifest looks for them),
// with the driver library each names.
std::string driverStamp() {
  std::string out;
  for (const char* var : {"VK_DRIVER_FILES", "VK_ICD_FILENAMES", "XDG_DATA_DIRS"})
    if (const char* v = std::getenv(var)) out += std::string(var) + "=" + v + "\n";
  std::vector<fs::path> manifests;
  for (const char* d : {"/usr/local/share/vulkan/icd.d", "/usr/share/vulkan/icd.d", "/etc/vulkan/icd.d"}) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(d, ec))
      if (e.path().filename().string().rfind("radeon_icd.", 0) == 0) manifests.push_back(e.path());
  }
  std::sort(manifests.begin(), manifests.end());
  for (const fs::path& m : manifests) {
    const std::string text = readText(m);
    out += m.string() + "\n" + text;
    const json j = json::parse(text, nullptr, false);
    const std::string lib = j.is_object() && j.contains("ICD") ? j["ICD"].value("library_path", "") : "";
    if (!lib.empty()) out += fileStamp(lib);
  }
  return out;
}

}  // namespace

std::string isaCacheKey(const std::string& executable) {
  std::string key = "motorbench isa cache 1\n" + fileStamp(executable) + driverStamp();
  std::vector<fs::path> shaders;
  std::error_code ec;
  for (const auto& e : fs::recursive_directory_iterator(gl::shaderDir(), ec))
    if (e.is_regular_file(ec)) shaders.push_back(e.path());
  std::sort(shaders.begin(), shaders.end());
  for (const fs::path& p : shaders) key += p.string() + " " + std::to_string(spirv::keyHash(readText(p))) + "\n";
  return key;
}

std::string isaCacheFile(const std::string& key) {
  const std::string root = spirv::cacheRoot();
  if (root.empty()) return {};
  char name[32];
  std::snprintf(name, sizeof name, "%016llx.json", static_cast<unsigned long long>(spirv::keyHash(key)));
  return (fs::path(root) / "isa" / name).string();
}

namespace {

// The cached document when its stored key is exactly `key`.
json cached(const fs::path& file, const std::string& key) {
  if (file.empty()) return json();
  std::ifstream in(file);
  json j = json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object() || j.value("key", "") != key || !j.contains("isa")) return json();
  return j["isa"];
}

void store(const fs::path& file, const std::string& key, const json& isa) {
  if (file.empty()) return;
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  const fs::path tmp = file.string() + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(tmp);
    out << json{{"key", key}, {"isa", isa}}.dump() << "\n";
    if (!out.flush()) return;
  }
  fs::rename(tmp, file, ec);  // whole entries only: a concurrent run never reads half of one
  if (ec) fs::remove(tmp, ec);
}

bool isIsaDocument(const json& j) { return j.is_object() && j.value("schema", "") == "motorbench-isa/1"; }

}  // namespace

IsaEvidence measureIsa(const std::string& outDir, double timeoutS) {
  const auto start = std::chrono::steady_clock::now();
  auto secondsSince = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  const std::string key = isaCacheKey(process::selfExecutable());
  const fs::path file = isaCacheFile(key);
  const fs::path out = fs::path(outDir) / "isa.json";
  IsaEvidence e;
  if (json j = cached(file, key); isIsaDocument(j)) {
    std::ofstream(out) << j.dump(1) << "\n";
    e.isa = std::move(j), e.source = "cache", e.seconds = secondsSince();
    return e;
  }
  const fs::path log = fs::path(outDir) / "isa.txt";
  const std::string how = process::runSelf({"isa", "--json", out.string()}, log.string(), timeoutS);
  e.source = "run";
  std::ifstream in(out);
  json j = json::parse(in, nullptr, false);
  if (!how.empty() || !isIsaDocument(j)) {
    // `motorbench isa` says why on its stderr (e.g. no RADV): shown in the report.
    e.isa = {{"error", "not measured: motorbench isa " + (how.empty() ? "wrote no ISA JSON" : how) +
                           " (its message is on the run's stderr)"}};
    std::error_code ec;
    fs::remove(out, ec);
  } else {
    store(file, key, j);
    e.isa = std::move(j);
  }
  e.seconds = secondsSince();
  return e;
}

}  // namespace mb::report
