// `motorbench render FILE.bpt`: a valid patch file renders in both pipelines; malformed ones
// (generated from the teapot: truncated, wrong degree, text in numbers, 10^9 patches claimed)
// exit 2 with a message naming the file and the line.
#include <gtest/gtest.h>

#include <sstream>

#include "tests/support/cli_test_support.h"

namespace {

using namespace mb::cli_test;
namespace fs = std::filesystem;

std::string teapot() { return readText(std::string(MB_SOURCE_DIR) + "/pipelines/scene/data/teapot.bpt"); }

std::string replaceLine(const std::string& text, int line, const std::string& with) {
  std::istringstream in(text);
  std::string out, l;
  for (int n = 1; std::getline(in, l); ++n) out += (n == line ? with : l) + "\n";
  return out;
}

TEST(CliBpt, RendersAPatchFileWithBothPipelines) {
  fs::path dir = scratchDir("cli_bpt_ok");
  std::ofstream(dir / "pot.bpt") << teapot();
  for (const char* p : {"matrix", "motor"}) {
    std::string out;
    int rc = runCommand(motorbench() + "render " + quoted(dir / "pot.bpt") + " --pipeline " + p + " --size 96x72 -o " +
                            quoted(dir / (std::string(p) + ".png")),
                        &out);
    EXPECT_EQ(rc, 0) << out;
    EXPECT_TRUE(fs::exists(dir / (std::string(p) + ".png"))) << out;
  }
  fs::remove_all(dir);
}

TEST(CliBpt, MalformedFilesExit2NamingTheLine) {
  fs::path dir = scratchDir("cli_bpt_bad");
  const std::string good = teapot();
  struct Case {
    std::string file, text, expect;
  } cases[] = {
      {"truncated.bpt", good.substr(0, good.size() / 3), "truncated.bpt: line 1: 32 patches claimed, but the file has"},
      {"degree.bpt", replaceLine(good, 36, "4 4"), "degree.bpt: line 36: patch 3 of 32: degrees 4 4 not supported"},
      {"text.bpt", replaceLine(good, 40, "0.5 spout 1.0"), "text.bpt: line 40: patch 3 of 32, control point 4 of 16: 'spout' is not a number"},
      {"billion.bpt", replaceLine(good, 1, "1000000000"), "billion.bpt: line 1: 1000000000 patches claimed; the limit is"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.file);
    std::ofstream(dir / c.file) << c.text;
    std::string out;
    int rc = runCommand(motorbench() + "render " + quoted(dir / c.file) + " --pipeline motor -o " + quoted(dir / "x.png"), &out);
    EXPECT_EQ(rc, 2) << out;
    EXPECT_NE(out.find(c.expect), std::string::npos) << out;
    EXPECT_FALSE(fs::exists(dir / "x.png"));
  }
  fs::remove_all(dir);
}

}  // namespace
