// The option parser every command shares (harness/options)
// and the frame options of render/compare. Each test runs a command as a user typed it and
// asserts the behaviour; the Args tests run the parser in-process.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "harness/options/args.h"
#include "harness/render/frame_options.h"
#include "harness/render/image_metrics.h"
#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::corpusDir;
using mb::cli_test::runMb;
using mb::cli_test::quoted;

bool sameImage(const fs::path& a, const fs::path& b) {
  auto x = mb::readImage(a.string()), y = mb::readImage(b.string());
  return x && y && x->width == y->width && x->height == y->height && x->rgba == y->rgba;
}

// --- the parser, in-process -----------------------------------------------------------------

TEST(CliArgs, UnknownOptionAtTheEndIsUnknownNotMissingItsValue) {
  mb::Args a({"scene", "--frames", "3", "--no-bnech"}, {{"frames"}, {"no-bench"}, {}});
  EXPECT_EQ(a.error(), "unknown option --no-bnech");
}

TEST(CliArgs, OptionFollowedByAnOptionIsMissingItsValue) {
  mb::Args a({"normal_torus", "--size", "-o", "x.png"}, {{"size", "o"}, {}, {}});
  EXPECT_EQ(a.error().rfind("option --size needs a value (found the option -o", 0), 0u) << a.error();
  mb::Args end({"--size"}, {{"size"}, {}, {}});
  EXPECT_EQ(end.error(), "option --size needs a value");
}

TEST(CliArgs, NegativeNumbersAreValuesThatReachTheRangeCheck) {
  mb::Args a({"--time", "-1"}, {{"time"}, {}, {}});
  EXPECT_EQ(a.error(), "");
  EXPECT_EQ(a.get("time", ""), "-1");
  EXPECT_THROW(a.real("time", 0, 0, 1e9, "a time in seconds"), mb::OptionError);
}

TEST(CliArgs, RepeatedOptionIsAnErrorNamingBothValues) {
  mb::Args a({"--time", "0.5", "--time", "1"}, {{"time"}, {}, {{"time", "one frame per run"}}});
  EXPECT_EQ(a.error(), "option --time given twice ('0.5', '1'); one frame per run");
}

TEST(CliArgs, ListOptionsCollectRepeatsOthersStillRefuseThem) {
  // `report --anim a,b --anim c`: a list option joins its repeats with ','.
  mb::Args a({"--anim", "candy_wrapper,0", "--time", "1", "--anim=twist"}, {{"anim", "time"}, {}, {}, {"anim"}});
  EXPECT_EQ(a.error(), "");
  EXPECT_EQ(a.get("anim", ""), "candy_wrapper,0,twist");
  EXPECT_EQ(mb::splitList(a.get("anim", "")), (std::vector<std::string>{"candy_wrapper", "0", "twist"}));
  mb::Args b({"--anim", "a", "--time", "1", "--time", "2"}, {{"anim", "time"}, {}, {}, {"anim"}});
  EXPECT_EQ(b.error(), "option --time given twice ('1', '2'); give it once");
}

TEST(CliArgs, FlagsTakeNoValueAndKeyValueFormWorks) {
  mb::Args a({"--update=1"}, {{}, {"update"}, {}});
  EXPECT_EQ(a.error(), "option --update takes no value");
  mb::Args b({"--size=64x32", "--update"}, {{"size"}, {"update"}, {}});
  EXPECT_EQ(b.error(), "");
  EXPECT_EQ(b.size("size", 1, 1), std::make_pair(64, 32));
  EXPECT_TRUE(b.has("update"));
}

TEST(CliArgs, NumbersAreRangeCheckedWithTheOptionNamed) {
  mb::Args a({"--frames", "abc", "--jobs", "0", "--w", "0.5", "--big", "1000000"},
             {{"frames", "jobs", "w", "big"}, {}, {}});
  auto message = [](auto f) {
    try {
      f();
    } catch (const mb::OptionError& e) {
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
  EXPECT_EQ(mb::parseSize("640x480"), std::make_optional(std::make_pair(640, 480)));
  EXPECT_EQ(mb::parseSize("16384x1"), std::make_optional(std::make_pair(16384, 1)));
  for (const char* bad : {"640", "0x0", "0x10", "10x0", "-5x5", "16385x1", "10x10x", "ax10", "", "10*10"})
    EXPECT_FALSE(mb::parseSize(bad)) << bad;
}

// --- commands as users typed them ------------------------------------------------------------

// "`time BoxAnimated.gltf --frames abc` prints `error: stod`."
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

// "A misspelt flag at the end of the line (`--no-bnech`) is reported as 'option --no-bnech
// needs a value'."
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

// "an option missing its value (`--size -o x.png`) swallows the next flag and yields
// 'expected one SCENE'."
TEST(CliOptions, SizeWithoutValueDoesNotSwallowTheNextOption) {
  const fs::path dir = mb::cli_test::scratchDir("options_size");
  const auto r = runMb("render normal_torus --size -o " + quoted(dir / "x.png"));
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "option --size needs a value")) << r.out;
  EXPECT_FALSE(contains(r.out, "expected one SCENE")) << r.out;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
  fs::remove_all(dir);
}

// "`render BoxAnimated.gltf --time 1.5` without `--anim` ignores the time silently (the image
// equals the rest pose)." Now: animation 0 at 1.5 s, said on stderr, the same image as
// --anim 0 --time 1.5 and not the rest pose.
TEST(CliOptions, RenderTimeWithoutAnimPosesTheFirstAnimation) {
  const fs::path corpus = corpusDir();
  if (corpus.empty()) GTEST_SKIP() << "no ../shared/corpus";
  const fs::path dir = mb::cli_test::scratchDir("options_time");
  const std::string box = quoted(corpus / "BoxAnimated.gltf");
  const auto timed = runMb("render " + box + " --time 1.5 -o " + quoted(dir / "t.png"));
  ASSERT_EQ(timed.rc, 0) << timed.out;
  EXPECT_TRUE(contains(timed.out, "--time without --anim: using animation 0")) << timed.out;
  EXPECT_TRUE(contains(timed.out, "at t = 1.5 s")) << timed.out;
  ASSERT_EQ(runMb("render " + box + " -o " + quoted(dir / "rest.png")).rc, 0);
  ASSERT_EQ(runMb("render " + box + " --anim 0 --time 1.5 -o " + quoted(dir / "a0.png")).rc, 0);
  EXPECT_FALSE(sameImage(dir / "t.png", dir / "rest.png")) << "--time 1.5 drew the rest pose";
  EXPECT_TRUE(sameImage(dir / "t.png", dir / "a0.png")) << "--time alone must equal --anim 0 --time 1.5";
  // A scene without animations rejects --time instead of ignoring it.
  const auto still = runMb("render normal_torus --time 1.5 -o " + quoted(dir / "s.png"));
  EXPECT_EQ(still.rc, 2) << still.out;
  EXPECT_TRUE(contains(still.out, "has no animations")) << still.out;
  fs::remove_all(dir);
}

// "`compare BoxAnimated.gltf --time 0.5` writes "time": 0.5 into metrics.json for a frame that
// was never posed." Now the frame is posed by animation 0 and metrics.json says so.
TEST(CliOptions, CompareTimeWithoutAnimRecordsThePosedAnimation) {
  const fs::path corpus = corpusDir();
  if (corpus.empty()) GTEST_SKIP() << "no ../shared/corpus";
  const fs::path dir = mb::cli_test::scratchDir("options_compare_time");
  const std::string box = quoted(corpus / "BoxAnimated.gltf");
  const auto r = runMb("compare " + box + " --time 0.5 -o " + quoted(dir / "c"));
  ASSERT_EQ(r.rc, 0) << r.out;
  const auto j = mb::cli_test::readJson(dir / "c" / "metrics.json");
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j["settings"]["anim"], 0);
  EXPECT_DOUBLE_EQ(j["settings"]["time"].get<double>(), 0.5);
  EXPECT_EQ(j["animation"]["index"], 0);
  ASSERT_EQ(runMb("render " + box + " --anim 0 --time 0.5 --pipeline matrix -o " + quoted(dir / "m.png")).rc, 0);
  EXPECT_TRUE(sameImage(dir / "c" / "matrix.png", dir / "m.png")) << "compare's frame is not the posed one";
  fs::remove_all(dir);
}

// "Repeating `--time` (as the usage line `[--anim A --time T ...]` suggests) keeps only the
// last value." Now: rejected with the reason, and the usage no longer suggests repeating.
TEST(CliOptions, RepeatedTimeIsRejected) {
  const fs::path dir = mb::cli_test::scratchDir("options_repeat");
  for (const char* cmd : {"render", "compare"}) {
    const auto r = runMb(std::string(cmd) + " skinned_tube --time 0.5 --time 1 -o " + quoted(dir / "x.png"));
    EXPECT_EQ(r.rc, 2) << r.out;
    EXPECT_TRUE(contains(r.out, "option --time given twice ('0.5', '1')")) << r.out;
    EXPECT_TRUE(contains(r.out, "once per time")) << r.out;
    const auto help = runMb(std::string(cmd) + " --help");
    EXPECT_FALSE(contains(help.out, "--time T ...")) << help.out;
  }
  fs::remove_all(dir);
}

// "`render` without `--pipeline` is an error or its default is in the usage"; "--version".
TEST(CliOptions, RenderUsageNamesTheDefaultPipelineAndVersionPrints) {
  const auto help = runMb("render --help");
  EXPECT_TRUE(contains(help.out, "--pipeline NAME (default matrix")) << help.out;
  const auto v = runMb("--version");
  EXPECT_EQ(v.rc, 0) << v.out;
  EXPECT_EQ(v.out.rfind("motorbench 0.", 0), 0u) << v.out;
  EXPECT_TRUE(contains(v.out, "(git ")) << v.out;
  EXPECT_TRUE(contains(runMb("--help").out, "--version"));
}

}  // namespace
