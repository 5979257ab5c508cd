// The option parser every command shares (harness/options): values, flags, repeats, numbers
// and sizes read by one set of rules with the option named in every message; in-process on
// mb::options::Args, then on commands as a user typed them.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "harness/options/args.h"
#include "harness/render/frame_options.h"
#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::corpusDir;
using mb::cli_test::runMb;
using mb::cli_test::quoted;

// --- the parser, in-process -----------------------------------------------------------------

TEST(CliArgs, UnknownOptionAtTheEndIsUnknownNotMissingItsValue) {
  mb::options::Args a({"scene", "--frames", "3", "--no-bnech"}, {{"frames"}, {"no-bench"}, {}});
  EXPECT_EQ(a.error(), "unknown option --no-bnech");
}

TEST(CliArgs, OptionFollowedByAnOptionIsMissingItsValue) {
  mb::options::Args a({"normal_torus", "--size", "-o", "x.png"}, {{"size", "o"}, {}, {}});
  EXPECT_EQ(a.error().rfind("option --size needs a value (found the option -o", 0), 0u) << a.error();
  mb::options::Args end({"--size"}, {{"size"}, {}, {}});
  EXPECT_EQ(end.error(), "option --size needs a value");
}

TEST(CliArgs, NegativeNumbersAreValuesThatReachTheRangeCheck) {
  mb::options::Args a({"--time", "-1"}, {{"time"}, {}, {}});
  EXPECT_EQ(a.error(), "");
  EXPECT_EQ(a.get("time", ""), "-1");
  EXPECT_THROW(a.real("time", 0, 0, 1e9, "a time in seconds"), mb::options::OptionError);
}

TEST(CliArgs, RepeatedOptionIsAnErrorNamingBothValues) {
  mb::options::Args a({"--time", "0.5", "--time", "1"}, {{"time"}, {}, {{"time", "one frame per run"}}});
  EXPECT_EQ(a.error(), "option --time given twice ('0.5', '1'); one frame per run");
}

TEST(CliArgs, ListOptionsCollectRepeatsOthersStillRefuseThem) {
  // `report --anim a,b --anim c`: a list option joins its repeats with ','.
  mb::options::Args a({"--anim", "candy_wrapper,0", "--time", "1", "--anim=twist"}, {{"anim", "time"}, {}, {}, {"anim"}});
  EXPECT_EQ(a.error(), "");
  EXPECT_EQ(a.get("anim", ""), "candy_wrapper,0,twist");
  EXPECT_EQ(mb::splitList(a.get("anim", "")), (std::vector<std::string>{"candy_wrapper", "0", "twist"}));
  mb::options::Args b({"--anim", "a", "--time", "1", "--time", "2"}, {{"anim", "time"}, {}, {}, {"anim"}});
  EXPECT_EQ(b.error(), "option --time given twice ('1', '2'); give it once");
}

TEST(CliArgs, FlagsTakeNoValueAndKeyValueFormWorks) {
  mb::options::Args a({"--update=1"}, {{}, {"update"}, {}});
  EXPECT_EQ(a.error(), "option --update takes no value");
  mb::options::Args b({"--size=64x32", "--update"}, {{"size"}, {"update"}, {}});
  EXPECT_EQ(b.error(), "");
  EXPECT_EQ(b.size("size", 1, 1), std::make_pair(64, 32));
  EXPECT_TRUE(b.has("update"));
}

TEST(CliArgs, NumbersAreRangeCheckedWithTheOptionNamed) {
  mb::options::Args a({"--frames", "abc", "--jobs", "0", "--w", "0.5", "--big", "1000000"},
             {{"frames", "jobs", "w", "big"}, {}, {}});
  auto message = [](auto f) {
    try {
      f();
    } catch (const mb::options::OptionError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message([&] { a.integer("frames", 30, 1, 100000); }), "--frames: expected a whole number >= 1, got 'abc'");
  EXPECT_EQ(message([&] { a.integer("jobs", 1, 1, 256); }), "--jobs: expected a whole number in 1..256, got '0'");
  EXPECT_EQ(message([&] { a.integer("w", 1, 0, 10); }), "--w: expected a whole number in 0..10, got '0.5'");
  EXPECT_EQ(message([&] { a.integer("big", 1, 1, 100000); }), "--big: expected a whole number in 1..100000, got '1000000'");
  EXPECT_DOUBLE_EQ(a.real("w", 0, 0, 1), 0.5);
  EXPECT_EQ(a.integer("absent", 7, 1, 10), 7);
}

TEST(CliArgs, OneSizeRuleWxHBothPositive) {
  EXPECT_EQ(mb::options::parseSize("640x480"), std::make_optional(std::make_pair(640, 480)));
  EXPECT_EQ(mb::options::parseSize("16384x1"), std::make_optional(std::make_pair(16384, 1)));
  for (const char* bad : {"640", "0x0", "0x10", "10x0", "-5x5", "16385x1", "10x10x", "ax10", "", "10*10"})
    EXPECT_FALSE(mb::options::parseSize(bad)) << bad;
}

// --- commands as users typed them ------------------------------------------------------------

// A number option given text names the option and the rule, not the conversion that failed.
TEST(CliOptions, TimeFramesAbcNamesTheOptionAndTheRule) {
  const auto r = runMb("time normal_torus --frames abc");
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "--frames: expected a whole number >= 1, got 'abc'")) << r.out;
  EXPECT_FALSE(contains(r.out, "stod")) << r.out;
  const fs::path corpus = corpusDir();
  if (corpus.empty()) return;
  const auto box = runMb("time " + quoted(corpus / "BoxAnimated.gltf") + " --frames abc");
  EXPECT_EQ(box.rc, 2) << box.out;
  EXPECT_TRUE(contains(box.out, "--frames: expected a whole number >= 1, got 'abc'")) << box.out;
}

// A misspelt flag at the end of the line is an unknown option, not one missing its value.
TEST(CliOptions, MisspeltFlagAtTheEndIsAnUnknownOption) {
  const fs::path dir = mb::cli_test::scratchDir("options_nobnech");
  for (const std::string& cmd : std::vector<std::string>{"report normal_torus -o " + quoted(dir / "r") + " --no-bnech",
                                 "time normal_torus --frames 3 --no-bnech", "inspect normal_torus --no-bnech",
                                 "render normal_torus -o " + quoted(dir / "x.png") + " --no-bnech"}) {
    const auto r = runMb(cmd);
    EXPECT_EQ(r.rc, 2) << cmd << "\n" << r.out;
    EXPECT_TRUE(contains(r.out, "unknown option --no-bnech")) << cmd << "\n" << r.out;
    EXPECT_FALSE(contains(r.out, "needs a value")) << cmd << "\n" << r.out;
  }
  EXPECT_FALSE(fs::exists(dir / "r")) << "report started despite the bad option";
  fs::remove_all(dir);
}

// An option missing its value does not take the next option as its value.
TEST(CliOptions, SizeWithoutValueDoesNotSwallowTheNextOption) {
  const fs::path dir = mb::cli_test::scratchDir("options_size");
  const auto r = runMb("render normal_torus --size -o " + quoted(dir / "x.png"));
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "option --size needs a value")) << r.out;
  EXPECT_FALSE(contains(r.out, "expected one SCENE")) << r.out;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
  fs::remove_all(dir);
}

// --size is one rule with one message in every command: 0x0 and a single number are refused.
TEST(CliMessages, SizeIsOneRuleInEveryCommand) {
  const fs::path dir = mb::cli_test::scratchDir("messages_size");
  const std::string rule = "expected WIDTHxHEIGHT, both whole numbers in 1..16384";
  for (const char* size : {"0x0", "640"}) {
    for (const std::string& cmd : {"render normal_torus -o " + quoted(dir / "x.png"),
                                   "compare normal_torus -o " + quoted(dir / "c"), "report normal_torus -o " +
                                   quoted(dir / "r"), std::string("time normal_torus")}) {
      const auto r = runMb(cmd + " --size " + size);
      EXPECT_EQ(r.rc, 2) << cmd << " --size " << size << "\n" << r.out;
      EXPECT_TRUE(contains(r.out, "--size: " + rule + " (e.g. 640x480; a square is 640x640), got '" + size + "'"))
          << cmd << "\n" << r.out;
    }
  }
  EXPECT_FALSE(fs::exists(dir / "r"));
  fs::remove_all(dir);
}

}  // namespace
