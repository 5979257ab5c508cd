// Helpers shared by the CLI tests (options, messages, visibility, readme):
// the shared real-world corpus, byte comparison of image files, and a run that keeps the exit
// status and the output together.
#pragma once
#include <filesystem>
#include <string>

#include "tests/support/cli_test_support.h"

namespace mb::cli_test {

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
