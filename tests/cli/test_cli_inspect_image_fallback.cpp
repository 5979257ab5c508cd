// `motorbench inspect` on a fuzzer finding (tests/fuzz/regressions/
// f12_jpeg_huffman_counts_over_256.glb): a JPEG whose Huffman counts sum past 256 is a counted
// fallback, not a crash: exit 0, `imagesNotDecoded 1`, the decoder's reason listed; the JSON
// report says the same.
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using namespace mb::cli_test;

TEST(CliInspectImageFallback, JpegHuffmanFindingExitsNormallyWithOneUndecodedImage) {
  const fs::path file = fs::path(MB_SOURCE_DIR) / "tests" / "fuzz" / "regressions" / "f12_jpeg_huffman_counts_over_256.glb";
  const fs::path dir = scratchDir("inspect_image_fallback");
  std::string out;
  int rc = runCommand(motorbench() + "inspect " + quoted(file) + " --json " + quoted(dir / "inspect.json"), &out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("imagesNotDecoded 1"), std::string::npos) << out;
  EXPECT_NE(out.find("Bogus Huffman table definition"), std::string::npos) << out;
  nlohmann::json j = readJson(dir / "inspect.json");
  ASSERT_FALSE(j.is_discarded()) << out;
  EXPECT_NE(j.dump().find("\"imagesNotDecoded\":1"), std::string::npos) << j.dump(1).substr(0, 2000);
  fs::remove_all(dir);
}

}  // namespace
