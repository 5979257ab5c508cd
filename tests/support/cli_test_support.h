// Helpers for tests that run the motorbench executable (test_cli_*): run a command and
// capture its output (runMb: status and output together), quote paths, a fresh scratch folder
// per test process (ctest runs tests in parallel, each in its own process), and the shared
// real-world corpus beside the checkout.
#pragma once
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

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

// An empty folder <tmp>/motorbench_<name>_<pid>.
inline std::filesystem::path scratchDir(const std::string& name) {
  namespace fs = std::filesystem;
  fs::path p = fs::temp_directory_path() / ("motorbench_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

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
