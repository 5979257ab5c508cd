// Image thresholds read by one rule wherever they are given (compare, diff, check's
// golden.json): byte steps ("2/255") and fractions read alike, and a plain number that reads as
// byte steps ("--fail 1": 255/255, any image passes) is refused with the hint, before any work;
// idiff's verdict rules by hand. The processes of a test run at once (cli_parallel.h).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "harness/options/args.h"
#include "harness/render/image_metrics.h"
#include "harness/render/thresholds.h"
#include "tests/support/cli_test_support.h"
#include "tests/support/cli_parallel.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::quoted;
using mb::cli_test::Ran;

mb::options::Args thresholdArgs(const std::vector<std::string>& line) {
  return mb::options::Args(line, mb::options::OptionSpec{{"fail", "hardfail", "warn", "hardwarn", "failpercent", "warnpercent"}, {}, {}, {}});
}

// The OptionError's message of reading --key from `line`, "" when it reads.
std::string thresholdRefusal(const std::vector<std::string>& line, const std::string& key) {
  try {
    mb::channelDifference(thresholdArgs(line), key, 0);
  } catch (const mb::options::OptionError& e) {
    return e.what();
  }
  return "";
}

TEST(CliThresholds, ByteStepsAndFractionsReadAlikeAndAPlainOneIsRefused) {
  EXPECT_DOUBLE_EQ(mb::channelDifference(thresholdArgs({"--fail", "2/255"}), "fail", 0), 2 / 255.0);
  EXPECT_DOUBLE_EQ(mb::channelDifference(thresholdArgs({"--fail", "0.0078"}), "fail", 0), 0.0078);
  EXPECT_DOUBLE_EQ(mb::channelDifference(thresholdArgs({"--fail", "255/255"}), "fail", 0), 1.0);  // as written
  EXPECT_DOUBLE_EQ(mb::channelDifference(thresholdArgs({}), "fail", 0.25), 0.25);
  EXPECT_TRUE(contains(thresholdRefusal({"--fail", "1"}, "fail"), "got '1': 1 reads as byte steps")) << thresholdRefusal({"--fail", "1"}, "fail");
  EXPECT_TRUE(contains(thresholdRefusal({"--fail", "1"}, "fail"), "Did you mean 1/255 (0.003922)?"));
  EXPECT_TRUE(contains(thresholdRefusal({"--fail", "1.0"}, "fail"), "Did you mean 1/255"));
  EXPECT_TRUE(contains(thresholdRefusal({"--hardfail", "16"}, "hardfail"), "--hardfail: expected"));
  EXPECT_TRUE(contains(thresholdRefusal({"--hardfail", "16"}, "hardfail"), "Did you mean 16/255"));
  EXPECT_FALSE(contains(thresholdRefusal({"--fail", "1.5"}, "fail"), "Did you mean"));  // not a whole step: no guess
  EXPECT_FALSE(thresholdRefusal({"--fail", "1.5"}, "fail").empty());
  EXPECT_FALSE(thresholdRefusal({"--fail", "300/255"}, "fail").empty());
  EXPECT_FALSE(thresholdRefusal({"--fail", "-1/255"}, "fail").empty());
  EXPECT_TRUE(mb::channelDifferenceError("golden.json fail", 0.004).empty());
  EXPECT_TRUE(contains(mb::channelDifferenceError("golden.json fail", 2), "Did you mean 2/255"));
  // idiff's rule: --hardfail below --fail is refused (between them a difference would pass).
  EXPECT_THROW(mb::idiffThresholds(thresholdArgs({"--fail", "4/255", "--hardfail", "2/255"})), mb::options::OptionError);
  EXPECT_NO_THROW(mb::idiffThresholds(thresholdArgs({"--hardfail", "0"})));  // below the 1e-6 default: no byte step
}

// idiff's verdict by hand on 2x1 images: no pixel over --fail passes, whatever --hardfail says.
TEST(CliThresholds, IdiffVerdictLooksPastFailOnlyWhenAPixelIsOverIt) {
  const mb::RgbaImage a{2, 1, {100, 100, 100, 255, 100, 100, 100, 255}};
  const mb::RgbaImage b{2, 1, {103, 100, 100, 255, 100, 100, 100, 255}};  // one pixel 3 steps off
  mb::IdiffThresholds t;
  EXPECT_EQ(mb::judgeIdiff(a, b, t).outcome, mb::IdiffOutcome::Failure);  // defaults: any difference
  t.fail.fail = 5 / 255.0;
  EXPECT_EQ(mb::judgeIdiff(a, b, t).outcome, mb::IdiffOutcome::Pass);  // over the default warn, yet PASS
  t.fail.fail = 2 / 255.0, t.fail.failPercent = 50;                     // 1 of 2 pixels allowed
  EXPECT_EQ(mb::judgeIdiff(a, b, t).outcome, mb::IdiffOutcome::Warning);
  t.warn.fail = 3 / 255.0 + 1e-6;
  EXPECT_EQ(mb::judgeIdiff(a, b, t).outcome, mb::IdiffOutcome::Pass);
  t.fail.hardFail = 2.5 / 255;
  EXPECT_EQ(mb::judgeIdiff(a, b, t).outcome, mb::IdiffOutcome::Failure);
}

// The same refusals from the commands, before any work: no scene is framed, no image read; and
// golden.json's "fail": 1 is refused naming the file, the scene and the level.
TEST(CliThresholds, CommandsRefuseByteStepsWrittenPlain) {
  const fs::path dir = mb::cli_test::scratchDir("traps_thresholds");
  const mb::RgbaImage img{2, 2, std::vector<uint8_t>(16, 200)};
  ASSERT_TRUE(mb::writeImage((dir / "a.png").string(), img));
  std::ifstream in(fs::path(MB_SOURCE_DIR) / "tests/golden/golden.json");
  nlohmann::json golden = nlohmann::json::parse(in);
  golden["thresholds"]["normal_torus"]["exact"]["fail"] = 1;
  fs::create_directories(dir / "golden");
  std::ofstream(dir / "golden/golden.json") << golden.dump();
  const std::string mb = mb::cli_test::motorbench();
  const std::vector<Ran> ran = mb::cli_test::runAll(
      dir, {mb + "compare normal_torus --hardfail 2/255 --fail 1 -o cmp", mb + "diff a.png a.png --fail 2/255 --warn 3",
            mb + "check --golden golden --scenes normal_torus --pipelines matrix --out out"});
  EXPECT_EQ(ran[0].rc, 2) << ran[0].out;
  EXPECT_FALSE(contains(ran[0].out, "camera:")) << ran[0].out;  // refused before the scene was framed
  EXPECT_TRUE(contains(ran[0].out, "--fail: expected")) << ran[0].out;
  EXPECT_TRUE(contains(ran[0].out, "Did you mean 1/255")) << ran[0].out;
  EXPECT_FALSE(fs::exists(dir / "cmp"));
  EXPECT_EQ(ran[1].rc, 2) << ran[1].out;
  EXPECT_TRUE(contains(ran[1].out, "--warn: expected")) << ran[1].out;
  EXPECT_TRUE(contains(ran[1].out, "Did you mean 3/255")) << ran[1].out;
  EXPECT_EQ(ran[2].rc, 2) << ran[2].out;
  EXPECT_TRUE(contains(ran[2].out, "golden.json: thresholds normal_torus exact fail: expected")) << ran[2].out;
  EXPECT_TRUE(contains(ran[2].out, "Did you mean 1/255")) << ran[2].out;
  fs::remove_all(dir);
}

}  // namespace
