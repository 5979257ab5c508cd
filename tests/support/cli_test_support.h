// Helpers for tests that run the motorbench executable (test_cli_*): run a command and
// capture its output (runMb: status and output together), quote paths, a fresh scratch folder
// or file name per test process (ctest runs tests in parallel, each in its own process), write
// bytes to a file, a small glTF with cameras, and the shared real-world corpus beside the
// checkout.
#pragma once
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace mb::cli_test {

// Runs a shell command (stderr folded into stdout); its exit status, -1 when it did not exit.
inline int runCommand(const std::string& cmd, std::string* output) {
  FILE* p = popen((cmd + " 2>&1").c_str(), "r");
  if (!p) return -1;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) output->append(buf, n);
  const int status = pclose(p);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

inline std::string quoted(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

// The JSON in file `p`; discarded (is_discarded()) when the file is missing or not JSON.
inline nlohmann::json readJson(const std::filesystem::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in, nullptr, false);
}

// The bytes of file `p` as text; empty when it cannot be read.
inline std::string readText(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// "'<motorbench>' " ready for arguments.
inline std::string motorbench() { return quoted(MB_MOTORBENCH_EXE) + " "; }

// The same as motorbench(): the name the bench, time and ops tests build their commands with.
inline std::string exe() { return motorbench(); }

// An empty folder <tmp>/motorbench_<name>_<pid>.
inline std::filesystem::path scratchDir(const std::string& name) {
  namespace fs = std::filesystem;
  fs::path p = fs::temp_directory_path() / ("motorbench_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

// A file name <tmp>/motorbench_cli_<pid>_<name> for one test's output (not created).
inline std::filesystem::path scratchFile(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("motorbench_cli_" + std::to_string(::getpid()) + "_" + name);
}

// Writes `bytes` to file `p` (replacing it).
inline void writeBytes(const std::filesystem::path& p, const std::vector<uint8_t>& bytes) {
  std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// One triangle, a perspective camera 'Cam' on a node looking at it from +Z, and an
// orthographic camera 'Ortho' on no node.
inline constexpr const char* kCameraGltf = R"({
  "asset": {"version": "2.0"},
  "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "cameras": [{"name": "Cam", "type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.1, "zfar": 100}},
              {"name": "Ortho", "type": "orthographic", "orthographic": {"xmag": 1, "ymag": 1, "znear": 0.1, "zfar": 10}}],
  "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0.3, 0.3, 3]}],
  "scenes": [{"nodes": [0, 1]}],
  "scene": 0
})";

// ../shared/corpus next to the checkout; a worktree (/work/wt/<name>) finds it one level up.
// Empty when neither exists (tests that need it skip).
inline std::filesystem::path corpusDir() {
  namespace fs = std::filesystem;
  for (const char* rel : {"../shared/corpus", "../../shared/corpus"}) {
    const fs::path p = fs::path(MB_SOURCE_DIR) / rel;
    std::error_code ec;
    if (fs::is_directory(p, ec)) return fs::canonical(p);
  }
  return {};
}

struct Run {
  int rc = -1;
  std::string out;  // stdout and stderr together
};

// Runs `motorbench <args>` (args already quoted where needed).
inline Run runMb(const std::string& args) {
  Run r;
  r.rc = runCommand(motorbench() + args, &r.out);
  return r;
}

inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace mb::cli_test
