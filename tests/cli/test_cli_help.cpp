// The help texts: `motorbench`, `motorbench --help` and `--version` (usage on stdout, exit 0; a
// missing or unknown command exits 2), `motorbench help CMD` and `CMD --help` (the command's
// options, the pipeline names it accepts and one example, and nothing run); a pipeline name is
// checked before the scene is loaded and framed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <string>
#include <vector>

#include "pipelines/pipeline.h"
#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::motorbench;
using mb::cli_test::quoted;
using mb::cli_test::runCommand;
using mb::cli_test::runMb;

const std::vector<std::string> kCommands = {"accuracy", "bench", "check", "claims", "compare", "diff", "drift", "inspect",
                                            "merge", "ops",   "render", "report",  "scenes", "survey", "time"};

// The --options of `text` (each once, in order).
std::vector<std::string> optionsIn(const std::string& text) {
  std::vector<std::string> out;
  for (size_t at = text.find("--"); at != std::string::npos; at = text.find("--", at + 2)) {
    size_t end = at + 2;
    while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '-' || text[end] == '_' ||
                                 text[end] == '*'))
      ++end;
    const std::string o = text.substr(at, end - at);
    if (o.size() > 2 && std::find(out.begin(), out.end(), o) == out.end()) out.push_back(o);
  }
  return out;
}

// Every --option of the usage line is explained under "options:", and every option an options
// line starts with ("  --x", "  -o, --output") is in the usage line (-o stands for --output).
void expectUsageAndOptionsAgree(const std::string& command, const std::string& help) {
  const std::string usage = help.substr(0, help.find('\n'));
  const size_t from = help.find("\noptions:\n"), to = help.find("\nexample:\n");
  ASSERT_NE(from, std::string::npos) << command;
  const std::string options = help.substr(from, to - from);
  for (const std::string& o : optionsIn(usage))
    EXPECT_TRUE(contains(options, o + " ") || contains(options, o + "=")) << command << ": " << o
                                                                          << " is in the usage line only\n" << help;
  for (size_t line = options.find("\n  -"); line != std::string::npos; line = options.find("\n  -", line + 1)) {
    std::string first = options.substr(line + 3, options.find_first_of(" ,=", line + 3) - line - 3);
    if (first == "-o") first = "--output";
    if (first.rfind("--", 0) != 0) continue;
    EXPECT_TRUE(contains(usage, first) || (first == "--output" && contains(usage, "-o ")))
        << command << ": " << first << " is under options only\n" << help;
  }
}

TEST(CliUsage, TopLevelHelpListsEveryCommand) {
  std::string out;
  EXPECT_EQ(runCommand(motorbench() + "--help", &out), 0) << out;
  for (const char* c : {"bench", "check", "claims", "compare", "inspect", "ops", "render", "report", "scenes", "time"})
    EXPECT_NE(out.find(std::string("  ") + c + " "), std::string::npos) << c << " missing from:\n" << out;
  std::string none;
  EXPECT_EQ(runCommand(motorbench(), &none), 2) << none;
}

TEST(CliUsage, UnknownCommandIsAnError) {
  std::string out;
  EXPECT_EQ(runCommand(motorbench() + "frobnicate", &out), 2) << out;
  EXPECT_NE(out.find("unknown command 'frobnicate'"), std::string::npos) << out;
}

// render's usage names its default pipeline; --version prints the version and the git commit.
TEST(CliOptions, RenderUsageNamesTheDefaultPipelineAndVersionPrints) {
  const auto help = runMb("render --help");
  EXPECT_TRUE(contains(help.out, "--pipeline NAME (default matrix")) << help.out;
  const auto v = runMb("--version");
  EXPECT_EQ(v.rc, 0) << v.out;
  EXPECT_EQ(v.out.rfind("motorbench 0.", 0), 0u) << v.out;
  EXPECT_TRUE(contains(v.out, "(git ")) << v.out;
  EXPECT_TRUE(contains(runMb("--help").out, "--version"));
}

TEST(CliHelp, HelpCommandPrintsThatCommandsHelpNotTheGlobalOne) {
  const auto help = runMb("help render");
  EXPECT_EQ(help.rc, 0) << help.out;
  EXPECT_EQ(help.out.rfind("usage: motorbench render SCENE", 0), 0u) << help.out;
  EXPECT_FALSE(contains(help.out, "commands:")) << help.out;  // the global list
  EXPECT_EQ(help.out, runMb("render --help").out);
  const auto unknown = runMb("help nope");
  EXPECT_EQ(unknown.rc, 2) << unknown.out;
  EXPECT_TRUE(contains(unknown.out, "unknown command 'nope'")) << unknown.out;
}

TEST(CliHelp, HelpIsaAndHelpHelp) {
  const auto isa = runMb("help isa");
  EXPECT_EQ(isa.rc, 0) << isa.out;
  for (const char* part : {"\noptions:\n", "--family F,...", "--json FILE", "--isa-text DIR", "--device", "--jobs N",
                           "\nexample:\n  motorbench isa "})
    EXPECT_TRUE(contains(isa.out, part)) << part << "\n" << isa.out;
  const auto help = runMb("help help");
  EXPECT_EQ(help.rc, 0) << help.out;
  EXPECT_TRUE(contains(help.out, "usage: motorbench help <command>")) << help.out;
  EXPECT_TRUE(contains(help.out, "commands:")) << help.out;
}

// The help is the usage line, then options and an example (see
// EveryCommandListsItsOptionsAndOneExample); nothing runs: none of the lines a run prints (time's
// machine line, report's progress, bench's "Running" line) appears.
TEST(CliUsage, CommandHelpPrintsThatCommandsUsageAndRunsNothing) {
  for (const char* c : {"time", "report", "render", "bench"}) {
    std::string out;
    EXPECT_EQ(runCommand(motorbench() + c + " --help", &out), 0) << c << ": " << out;
    EXPECT_EQ(out.rfind(std::string("usage: motorbench ") + c + " ", 0), 0u) << out;
    for (const char* ran : {"machine:", "report: ", "Running ", "GL_RENDERER"})
      EXPECT_EQ(out.find(ran), std::string::npos) << c << " ran instead of printing its help:\n" << out;
  }
  std::string out;
  EXPECT_EQ(runCommand(motorbench() + "time --frames 3 -h", &out), 0) << out;
  EXPECT_NE(out.find("usage: motorbench time"), std::string::npos) << out;
}

// One `help` process per command; each lists its options and one example, and the commands that
// take pipelines list every registered name.
TEST(CliHelp, EveryCommandListsItsOptionsAndOneExample) {
  std::map<std::string, std::string> helps;  // one `help` process per command
  for (const std::string& c : kCommands) {
    const auto help = runMb("help " + c);
    EXPECT_EQ(help.rc, 0) << c << ": " << help.out;
    EXPECT_TRUE(contains(help.out, "\noptions:\n  ")) << c << ": " << help.out;
    EXPECT_TRUE(contains(help.out, "\nexample:\n  motorbench " + c + " ")) << c << ": " << help.out;
    helps[c] = help.out;
    expectUsageAndOptionsAgree(c, help.out);
  }
  // Options as the parser knows them (one per line) and the command's own rules.
  const std::string& time = helps.at("time");
  for (const char* option : {"--frames N", "--warmup W", "--best-of K", "--json FILE", "< 1: motor faster"})
    EXPECT_TRUE(contains(time, option)) << option << "\n" << time;
  // Options the usage line named but the list left out, and defaults it did not give.
  for (const char* c : {"render", "compare", "time"})
    for (const char* option : {"\n  --instances N ", "\n  --gpu auto|llvmpipe|N "})
      EXPECT_TRUE(contains(helps.at(c), option)) << c << ": " << option << "\n" << helps.at(c);
  const std::string& report = helps.at("report");
  for (const char* text : {"--frames N         timed frames per pipeline and scene (default 30;",
                           "--time-size WxH    the timing viewport (default 512x512", "\n  --isa-json FILE ",
                           "--timeout S        seconds each scene's worker process may take (default 900)"})
    EXPECT_TRUE(contains(report, text)) << text << "\n" << report;
  for (const char* text : {"[--python P]", "[--timeout S]", "[--plot-script FILE]"})
    EXPECT_TRUE(contains(report.substr(0, report.find('\n')), text)) << text << "\n" << report;
  // claims reads a run's figures: the results folder or each source file on its own, and says
  // that it measures nothing and who writes a missing file.
  const std::string& claims = helps.at("claims");
  for (const char* text : {"--results DIR", "--report F", "--ops F", "--morph F", "--accuracy F", "--scene-graphs F",
                           "--corpus-report F", "--corpus-accuracy F", "-o FILE", "--json FILE", "measures nothing",
                           "names the command that writes it"})
    EXPECT_TRUE(contains(claims, text)) << text << "\n" << claims;
  // The commands that take pipelines list every registered name on one line; inspect takes none.
  // (Read from the same help texts: a motorbench process costs ~0.5 s of CPU before main.)
  for (const char* c : {"render", "compare", "report", "check"}) {
    const std::string& help = helps.at(c);
    const size_t at = help.find("\npipelines: ");
    ASSERT_NE(at, std::string::npos) << c << ": " << help;
    const std::string line = help.substr(at + 1, help.find('\n', at + 1) - at - 1);
    for (const std::string& p : mb::allPipelineNames()) EXPECT_TRUE(contains(line, p)) << c << ": " << p << " in " << line;
  }
  EXPECT_FALSE(contains(helps.at("inspect"), "\npipelines: "));
}

// An unknown pipeline name is refused, with the registered names, before anything is framed or
// written.
TEST(CliHelp, PipelineNameIsCheckedBeforeTheSceneIsLoaded) {
  const fs::path dir = mb::cli_test::scratchDir("help_pipeline");
  const auto render = runMb("render skinned_tube --time 0.5 --pipeline Motor -o " + quoted(dir / "x.png"));
  EXPECT_EQ(render.rc, 2) << render.out;
  EXPECT_TRUE(contains(render.out, "--pipeline Motor: unknown pipeline (registered: matrix, motor")) << render.out;
  for (const char* framed : {"camera:", "size:", "animation 0", "pipeline: "})
    EXPECT_FALSE(contains(render.out, framed)) << framed << " printed before the error:\n" << render.out;
  const auto compare = runMb("compare skinned_tube --pipelines matrix,Motor -o " + quoted(dir / "c"));
  EXPECT_EQ(compare.rc, 2) << compare.out;
  EXPECT_TRUE(contains(compare.out, "--pipelines Motor: unknown pipeline (registered: ")) << compare.out;
  EXPECT_FALSE(contains(compare.out, "camera:")) << compare.out;
  EXPECT_FALSE(fs::exists(dir / "c")) << "the output folder was made for a refused run";
  fs::remove_all(dir);
}

}  // namespace
