// `motorbench diff A B` against OpenImageIO's idiff on small image pairs written here: the same
// verdict on the same thresholds every time (idiff 0 PASS / 1 WARNING / 2 FAILURE / 4 file error;
// diff 0 pass or warning / 1 fail / 2 error), each pair's verdict also derived by hand; FLIP
// thresholds, the maps and metrics.json. Every process of a test runs at once (cli_parallel.h).
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "harness/render/image_metrics.h"
#include "tests/support/cli_test_support.h"
#include "tests/support/cli_parallel.h"

namespace {

namespace fs = std::filesystem;
using mb::RgbaImage;
using mb::cli_test::contains;
using mb::cli_test::quoted;
using mb::cli_test::Ran;
using mb::cli_test::runAll;

constexpr int kDiffSide = 16;  // 256 pixels: one pixel is 0.390625 %

// A smooth RGBA gradient, alpha 255; every channel value in 40..200, so +-10 stays in range.
RgbaImage diffBaseImage(int w = kDiffSide, int h = kDiffSide) {
  RgbaImage img{w, h, std::vector<uint8_t>(size_t(w) * size_t(h) * 4)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      uint8_t* p = &img.rgba[(size_t(y) * size_t(w) + size_t(x)) * 4];
      p[0] = uint8_t(40 + 10 * x), p[1] = uint8_t(40 + 10 * y), p[2] = uint8_t(120 + 3 * (x - y)), p[3] = 255;
    }
  return img;
}

// `img` with channel `c` of pixel (x, y) raised by `steps` byte steps.
RgbaImage withChannelRaised(RgbaImage img, int x, int y, int c, int steps) {
  img.rgba[(size_t(y) * size_t(img.width) + size_t(x)) * 4 + size_t(c)] += uint8_t(steps);
  return img;
}

// `img` with the green channel of every `every`-th pixel raised by `steps`.
RgbaImage withEveryNthRaised(RgbaImage img, int every, int steps) {
  for (size_t p = 0; p < img.rgba.size() / 4; p += size_t(every)) img.rgba[p * 4 + 1] += uint8_t(steps);
  return img;
}

// The RGB of `img` as a 3-channel PNG (writeImage writes RGBA).
void writeRgbPng(const fs::path& path, const RgbaImage& img) {
  std::vector<uint8_t> rgb;
  for (size_t p = 0; p < img.rgba.size(); p += 4) rgb.insert(rgb.end(), img.rgba.begin() + long(p), img.rgba.begin() + long(p) + 3);
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(path.string(), OIIO::ImageSpec(img.width, img.height, 3, OIIO::TypeDesc::UINT8)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, rgb.data()));
  ASSERT_TRUE(out->close());
}

// A threshold as each tool is given it: motorbench in byte steps ("2/255"), idiff as its decimal.
struct DiffLimit {
  std::string option;  // "fail", "failpercent", ...
  std::string text;    // as given to motorbench
  double value;        // as given to idiff (%.9g)
};
DiffLimit stepLimit(const std::string& option, int n) { return {option, std::to_string(n) + "/255", n / 255.0}; }
DiffLimit percentLimit(const std::string& option, double p) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", p);
  return {option, b, p};
}

enum class DiffExpect { Pass, Warning, Fail, Error };

struct DiffCase {
  std::string name, a, b;  // file names in the scratch folder
  std::vector<DiffLimit> limits;
  DiffExpect diff;        // motorbench's verdict, derived by hand
  bool idiffPasses;   // idiff rc 0 or 1
};

bool idiffInstalled() {
  std::string out;
  return mb::cli_test::runCommand("command -v idiff", &out) == 0 && !out.empty();
}

std::string diffCommand(const DiffCase& c) {
  std::string cmd = mb::cli_test::motorbench() + "diff " + c.a + " " + c.b;
  for (const DiffLimit& l : c.limits) cmd += " --" + l.option + " " + l.text;
  return cmd;
}

std::string idiffCommand(const DiffCase& c) {
  std::string cmd = "idiff";
  for (const DiffLimit& l : c.limits) {
    char v[32];
    std::snprintf(v, sizeof v, "%.9g", l.value);
    cmd += " -" + l.option + " " + v;
  }
  return cmd + " " + c.a + " " + c.b;
}

TEST(CliDiff, SameVerdictAsIdiffOnTheSameThresholds) {
  if (!idiffInstalled()) GTEST_SKIP() << "idiff (openimageio-tools) is not installed; scripts/setup.sh installs it";
  const fs::path dir = mb::cli_test::scratchDir("diff_idiff");
  const RgbaImage a = diffBaseImage();
  const std::vector<std::pair<std::string, RgbaImage>> images = {
      {"a.png", a},
      {"copy.png", a},
      {"one1.png", withChannelRaised(a, 3, 5, 0, 1)},    // one pixel, red 1 step up (70 -> 71)
      {"one10.png", withChannelRaised(a, 7, 2, 2, 10)},  // one pixel, blue 10 steps up
      {"alpha5.png", withChannelRaised(a, 0, 0, 3, -5)}, // one pixel's alpha 5 steps down
      {"quarter3.png", withEveryNthRaised(a, 4, 3)}, // 64 pixels (25 %), green 3 steps up
      {"small.png", diffBaseImage(kDiffSide, kDiffSide / 2)},  // another size
  };
  for (const auto& [name, img] : images) ASSERT_TRUE(mb::writeImage((dir / name).string(), img)) << name;
  writeRgbPng(dir / "rgb.png", a);  // the same colours without alpha
  const std::vector<DiffCase> cases = {
      {"identical, defaults", "a.png", "copy.png", {}, DiffExpect::Pass, true},
      {"1 step, --fail 1/255 (not more than 1 step)", "a.png", "one1.png", {stepLimit("fail", 1)}, DiffExpect::Pass, true},
      // 1 of 256 pixels fails (0.39 %), allowed by 1 %; over the default warn: WARNING.
      {"10 steps, 1 % allowed", "a.png", "one10.png", {stepLimit("fail", 2), percentLimit("failpercent", 1)}, DiffExpect::Warning, true},
      {"10 steps, 1 % allowed, --hardfail 8/255", "a.png", "one10.png",
       {stepLimit("fail", 2), percentLimit("failpercent", 1), stepLimit("hardfail", 8)}, DiffExpect::Fail, false},
      // 64 of 256 pixels (25 %) over 2 steps: exactly the allowance passes, 20 % does not. (The warn
      // threshold is 4 steps: "more than 3/255" is decided in float, as idiff does, and some 3-step
      // differences of this image are over it.)
      {"25 % by 3 steps, 25 % allowed, warn 4/255", "a.png", "quarter3.png",
       {stepLimit("fail", 2), percentLimit("failpercent", 25), stepLimit("warn", 4)}, DiffExpect::Pass, true},
      {"25 % by 3 steps, 20 % allowed", "a.png", "quarter3.png", {stepLimit("fail", 2), percentLimit("failpercent", 20)},
       DiffExpect::Fail, false},
      {"25 % by 3 steps, 50 % allowed, warn 20 %", "a.png", "quarter3.png",
       {stepLimit("fail", 2), percentLimit("failpercent", 50), stepLimit("warn", 2), percentLimit("warnpercent", 20)}, DiffExpect::Warning,
       true},
      {"alpha 5 steps, defaults (any difference fails)", "a.png", "alpha5.png", {}, DiffExpect::Fail, false},
      {"another size", "a.png", "small.png", {}, DiffExpect::Error, false},
      {"RGB against RGBA", "a.png", "rgb.png", {}, DiffExpect::Error, false},
  };
  std::vector<std::string> commands;
  for (const DiffCase& c : cases) commands.push_back(diffCommand(c)), commands.push_back(idiffCommand(c));
  const std::vector<Ran> ran = runAll(dir, commands);
  std::string table = "pair | thresholds | idiff | motorbench\n";
  for (size_t i = 0; i < cases.size(); ++i) {
    const DiffCase& c = cases[i];
    const Ran& mine = ran[2 * i];
    const Ran& theirs = ran[2 * i + 1];
    const int rc = c.diff == DiffExpect::Fail ? 1 : c.diff == DiffExpect::Error ? 2 : 0;
    EXPECT_EQ(mine.rc, rc) << c.name << "\n" << diffCommand(c) << "\n" << mine.out;
    EXPECT_EQ(theirs.rc == 0 || theirs.rc == 1, c.idiffPasses) << c.name << "\n" << idiffCommand(c) << "\n" << theirs.out;
    EXPECT_EQ(theirs.rc == 0 || theirs.rc == 1, mine.rc == 0) << c.name << ": idiff rc " << theirs.rc << ", diff rc "
                                                             << mine.rc << "\n" << theirs.out << "\n" << mine.out;
    // WARNING where idiff warns (rc 1), PASS where it passes.
    if (c.diff == DiffExpect::Warning) {
      EXPECT_EQ(theirs.rc, 1) << c.name << "\n" << theirs.out;
      EXPECT_TRUE(contains(mine.out, "-> WARNING (")) << c.name << "\n" << mine.out;
    }
    if (c.diff == DiffExpect::Pass) {
      EXPECT_EQ(theirs.rc, 0) << c.name << "\n" << theirs.out;
      EXPECT_TRUE(contains(mine.out, "-> PASS (")) << c.name << "\n" << mine.out;
    }
    if (c.diff == DiffExpect::Fail) EXPECT_TRUE(contains(mine.out, "-> FAIL (")) << c.name << "\n" << mine.out;
    std::string given;
    for (const DiffLimit& l : c.limits) given += "--" + l.option + " " + l.text + " ";
    table += c.name + " | " + given + "| idiff rc " + std::to_string(theirs.rc) + " | diff rc " +
             std::to_string(mine.rc) + "\n";
  }
  EXPECT_TRUE(contains(ran[2 * 8].out, "a.png is 16x16, small.png is 16x8: the sizes differ")) << ran[2 * 8].out;
  EXPECT_TRUE(contains(ran[2 * 9].out, "a.png has 4 channels, rgb.png has 3: the channel counts differ"))
      << ran[2 * 9].out;
  std::printf("%s", table.c_str());  // the agreement table, for the log
  fs::remove_all(dir);
}

// FLIP thresholds judge on their own; --out writes the maps and metrics.json; an unreadable
// file and a file given as --out are errors (exit 2), the latter before any image is read.
TEST(CliDiff, FlipThresholdsMapsMetricsAndErrors) {
  const fs::path dir = mb::cli_test::scratchDir("diff_flip");
  const RgbaImage a = diffBaseImage();
  ASSERT_TRUE(mb::writeImage((dir / "a.png").string(), a));
  ASSERT_TRUE(mb::writeImage((dir / "one10.png").string(), withChannelRaised(a, 7, 2, 2, 10)));
  std::ofstream(dir / "not.png") << "not an image";
  const std::string mb = mb::cli_test::motorbench() + "diff ";
  const std::vector<Ran> ran = runAll(
      dir, {mb + "a.png one10.png --fail 10/255 --flip-max 0.001 --out out",  // passes idiff, fails FLIP max
            mb + "a.png one10.png --fail 10/255 --flip-mean 0.5 --flip-max 1",
            mb + "a.png not.png", mb + "a.png a.png --out a.png"});
  EXPECT_EQ(ran[0].rc, 1) << ran[0].out;
  EXPECT_TRUE(contains(ran[0].out, "-> FAIL (FLIP max ")) << ran[0].out;
  EXPECT_TRUE(contains(ran[0].out, "exceeds --flip-max 0.001")) << ran[0].out;
  EXPECT_EQ(ran[1].rc, 0) << ran[1].out;
  EXPECT_TRUE(contains(ran[1].out, "-> PASS (")) << ran[1].out;
  for (const char* f : {"diff.png", "diff_legend.png", "flip.png", "metrics.json"})
    EXPECT_TRUE(fs::is_regular_file(dir / "out" / f)) << f;
  const auto j = mb::cli_test::readJson(dir / "out" / "metrics.json");
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j["verdict"]["text"], "fail") << j.dump();
  EXPECT_EQ(j["verdict"]["idiff"], "PASS") << j.dump();
  EXPECT_EQ(j["verdict"]["exit"], 1);
  EXPECT_NEAR(j["metrics"]["maxError"].get<double>(), 10 / 255.0, 1e-7) << j["metrics"].dump();  // float
  EXPECT_GT(j["metrics"]["flip"]["max"].get<double>(), 0.001);
  EXPECT_DOUBLE_EQ(j["thresholds"]["fail"].get<double>(), 10 / 255.0);
  EXPECT_TRUE(j["thresholds"]["hardfail"].is_null());
  EXPECT_DOUBLE_EQ(j["thresholds"]["flipMax"].get<double>(), 0.001);
  auto map = mb::readImage((dir / "out" / "diff.png").string());
  ASSERT_TRUE(map);
  EXPECT_EQ(map->width, kDiffSide);
  EXPECT_EQ(ran[2].rc, 2) << ran[2].out;
  EXPECT_TRUE(contains(ran[2].out, "not.png: cannot read image")) << ran[2].out;
  EXPECT_EQ(ran[3].rc, 2) << ran[3].out;
  EXPECT_TRUE(contains(ran[3].out, "--out a.png: is a file")) << ran[3].out;
  fs::remove_all(dir);
}

}  // namespace
