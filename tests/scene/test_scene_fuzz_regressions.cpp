// Replays every input in tests/fuzz/regressions/ (crashes and violations the fuzzer found, see
// the README there) through exactly what the fuzzer does with it (tests/fuzz/fuzz_exercise.h),
// in the normal build -- and under ASan/UBSan in `scripts/test.sh --sanitize`.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "tests/fuzz/fuzz_exercise.h"
#include "tests/fuzz/fuzz_image_checks.h"

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> regressionInputs(const char* sub = "") {
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(fs::path(MB_SOURCE_DIR) / "tests" / "fuzz" / "regressions" / sub, ec))
    if (e.is_regular_file() && e.path().filename() != "README.md") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(FuzzRegressions, EveryFindingStaysFixed) {
  const auto files = regressionInputs();
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(mb::fuzz::exercise(bytes.data(), bytes.size()), "") << f.filename().string();
  }
  std::printf("[ replay   ] %zu regression inputs\n", files.size());
}

// Findings of the image fuzzer (tests/fuzz/fuzz_images.cpp): raw PNG/JPEG bytes through the
// same checks (leaks show under LeakSanitizer in `scripts/test.sh --sanitize`).
TEST(FuzzRegressions, EveryImageFindingStaysFixed) {
  const auto files = regressionInputs("images");
  EXPECT_GE(files.size(), 1u);
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(mb::fuzz::checkImageDecode(bytes.data(), bytes.size()), "") << f.filename().string();
  }
  std::printf("[ replay   ] %zu image regression inputs\n", files.size());
}

}  // namespace
