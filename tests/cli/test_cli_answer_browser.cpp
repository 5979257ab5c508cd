// The answer above the fold: report.html opened in headless Chromium at 1400x900; the
// page's inline script (report_html.cpp) writes on <body> where the answer heading, its table and
// the design-space figure end (data-layout "id:bottom ...", page coordinates) and how wide the
// page is (data-scroll-width). The block and the figure must end within the first 900 px.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <regex>

#include "tests/support/chromium.h"
#include "tests/support/cli_test_support.h"

namespace mb::cli_test {
namespace {

namespace fs = std::filesystem;

std::map<std::string, int> layoutOf(const std::string& dom) {
  std::map<std::string, int> out;
  std::smatch m;
  if (!std::regex_search(dom, m, std::regex("data-layout=\"([^\"]*)\""))) return out;
  const std::string list = m[1];
  const std::regex item("([a-z-]+):(-?\\d+)");
  for (auto it = std::sregex_iterator(list.begin(), list.end(), item); it != std::sregex_iterator(); ++it)
    out[(*it)[1]] = std::stoi((*it)[2]);
  return out;
}

// The answer heading, its table and the design-space figure end within the first 900 px of
// `page` opened at 1400x900, in that order, and the page does not scroll sideways.
void expectAnswerAboveTheFold(const std::string& exe, const fs::path& dir, const fs::path& page) {
  int status = 0;
  const std::string dom = runChromium(exe, dir / "profile", page, "--dump-dom", &status, "1400,900");
  ASSERT_EQ(status, 0);
  const std::map<std::string, int> layout = layoutOf(dom);
  for (const char* id : {"answer", "answer-table", "design-space"}) {
    ASSERT_TRUE(layout.count(id)) << id << " not on " << page << ": " << dom.substr(0, 400);
    EXPECT_GT(layout.at(id), 0) << id;
    EXPECT_LE(layout.at(id), 900) << id << " ends below the first screen of " << page;
  }
  EXPECT_LT(layout.at("answer"), layout.at("answer-table"));
  EXPECT_LT(layout.at("answer-table"), layout.at("design-space"));
  // The small multiples wrap: the page is no wider than the window (wide tables scroll inside).
  std::smatch m;
  ASSERT_TRUE(std::regex_search(dom, m, std::regex("data-scroll-width=\"(\\d+)\"")));
  EXPECT_LE(std::stoi(m[1]), 1400) << page << " scrolls sideways at 1400 px";
}

TEST(AnswerBrowser, AnswerBlockAndDesignSpaceAboveTheFoldAt1400x900) {
  const std::string exe = chromiumExe();
  if (exe.empty()) GTEST_SKIP() << "Chromium not installed (scripts/setup.sh installs it)";
  const fs::path dir = scratchDir("answer_browser");
  const fs::path isa = fs::path(MB_SOURCE_DIR) / "results" / "isa.json";  // AMD ISA line and the figure's y
  std::string out;
  ASSERT_EQ(runCommand(motorbench() + "report normal_torus --frames 2 --no-bench " +
                           (fs::exists(isa) ? "--isa-json " + quoted(isa) + " " : std::string()) + "-o " +
                           quoted(dir / "report"), &out), 0) << out;
  expectAnswerAboveTheFold(exe, dir, dir / "report" / "report.html");
  fs::remove_all(dir);
}

// The committed results/report.html (scripts/reproduce.sh: every built-in scene, the ISA line,
// the design-space plot) passes the same check, as the closing note's screenshot shows it.
TEST(AnswerBrowser, CommittedResultsReportAboveTheFold) {
  const std::string exe = chromiumExe();
  if (exe.empty()) GTEST_SKIP() << "Chromium not installed (scripts/setup.sh installs it)";
  const fs::path page = fs::path(MB_SOURCE_DIR) / "results" / "report.html";
  if (!fs::exists(page)) GTEST_SKIP() << page << " not written (scripts/reproduce.sh)";
  const fs::path dir = scratchDir("answer_browser_results");
  expectAnswerAboveTheFold(exe, dir, page);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mb::cli_test
