// harness/cli/README.md's "Everyday use" section, the command reference. Every example in its ```sh
// blocks runs here exactly as written from the repository root, with only the binary path
// (build/harness/motorbench -> the built one) and the output folder (out/ -> a scratch
// folder) substituted; the section names the binary's place, the built-in scenes, every
// metrics.json key and every counter of the glossary.
#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "harness/render/counter_glossary.h"
#include "pipelines/scene/builtin_scenes.h"
#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::contains;
using mb::cli_test::quoted;

// The text of harness/cli/README.md from "## Everyday use" to the next "## " heading.
std::string everydaySection() {
  const std::string readme = mb::cli_test::readText(fs::path(MB_SOURCE_DIR) / "harness" / "cli" / "README.md");
  const size_t start = readme.find("\n## Everyday use\n");
  if (start == std::string::npos) return "";
  const size_t end = readme.find("\n## ", start + 1);
  return readme.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

// The command lines of the ```sh blocks of `text`.
std::vector<std::string> shCommands(const std::string& text) {
  std::vector<std::string> out;
  bool inSh = false;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("```", 0) == 0) {
      inSh = !inSh && line == "```sh";
      continue;
    }
    if (inSh && !line.empty() && line[0] != '#') out.push_back(line);
  }
  return out;
}

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
  for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size())) s.replace(at, from.size(), to);
  return s;
}

TEST(CliReadme, EverydayUseSectionExists) {
  const std::string section = everydaySection();
  ASSERT_FALSE(section.empty()) << "harness/cli/README.md has no '## Everyday use' section";
  EXPECT_TRUE(contains(section, "build/harness/motorbench")) << "where the binary is";
  for (const std::string& name : mb::builtinSceneNames()) EXPECT_TRUE(contains(section, "`" + name + "`")) << name;
  for (const char* c : {"render", "compare", "inspect", "check", "time"})
    EXPECT_TRUE(contains(section, std::string("build/harness/motorbench ") + c + " ")) << "no example of " << c;
}

TEST(CliReadme, EveryEverydayExampleRuns) {
  const std::vector<std::string> commands = shCommands(everydaySection());
  ASSERT_GE(commands.size(), 5u);
  const fs::path out = mb::cli_test::scratchDir("readme");
  for (const std::string& line : commands) {
    ASSERT_EQ(line.rfind("build/harness/motorbench ", 0), 0u) << "not a motorbench example: " << line;
    std::string cmd = mb::cli_test::motorbench() + line.substr(std::string("build/harness/motorbench ").size());
    cmd = replaceAll(cmd, " out/", " " + out.string() + "/");
    std::string log;
    const int rc = mb::cli_test::runCommand("cd " + quoted(MB_SOURCE_DIR) + " && " + cmd, &log);
    EXPECT_EQ(rc, 0) << line << "\n" << log;
  }
  // The examples wrote where they say.
  EXPECT_TRUE(fs::is_regular_file(out / "tube.png"));
  EXPECT_TRUE(fs::is_regular_file(out / "box" / "metrics.json"));
  EXPECT_TRUE(fs::is_regular_file(out / "inspect.json"));
  EXPECT_TRUE(fs::is_regular_file(out / "check" / "summary.html"));
  EXPECT_TRUE(fs::is_regular_file(out / "time.json"));

  // Every top-level key of the metrics.json the compare example wrote is documented.
  const auto metrics = mb::cli_test::readJson(out / "box" / "metrics.json");
  ASSERT_FALSE(metrics.is_discarded());
  const std::string section = everydaySection();
  for (const auto& [key, value] : metrics.items())
    EXPECT_TRUE(contains(section, "`" + key + "`")) << "metrics.json key '" << key << "' missing from README";
  fs::remove_all(out);
}

TEST(CliReadme, GlossaryListsEveryCounter) {
  const std::string section = everydaySection();
  for (const mb::CounterEntry& e : mb::counterGlossary())
    EXPECT_TRUE(contains(section, "| `" + e.key + "` |")) << e.group << "." << e.key << " missing from the README glossary";
}

}  // namespace
