// Headless Chromium for the browser tests (tests/cli/test_cli_browser.cpp, test_cli_answer_browser.cpp):
// the executable when installed, and one run on a file:// page with its own profile folder.
#pragma once
#include <cstdlib>
#include <filesystem>
#include <string>

#include "tests/support/cli_test_support.h"

namespace mb::cli_test {

// "chromium" or "chromium-browser" when on PATH, else "" (the tests skip).
inline std::string chromiumExe() {
  for (const char* name : {"chromium", "chromium-browser"})
    if (std::system((std::string("command -v ") + name + " >/dev/null 2>&1").c_str()) == 0) return name;
  return "";
}

// Headless Chromium on file://page at `window` ("1200,900"); `extra` adds --dump-dom or
// --screenshot=... . A time limit keeps a stuck browser from hanging the suite. Returns stdout.
inline std::string runChromium(const std::string& exe, const std::filesystem::path& profile,
                               const std::filesystem::path& page, const std::string& extra, int* status,
                               const std::string& window = "1200,900") {
  std::string out;
  *status = runCommand("timeout 120 " + exe + " --headless --no-sandbox --disable-gpu --no-first-run "
                       "--user-data-dir=" + quoted(profile) + " --virtual-time-budget=10000 --window-size=" + window +
                       " " + extra + " " + quoted(std::filesystem::path("file://" + std::filesystem::absolute(page).string())) +
                       " 2>/dev/null", &out);
  return out;
}

}  // namespace mb::cli_test
