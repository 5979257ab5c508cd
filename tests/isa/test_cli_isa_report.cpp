// `motorbench report --isa-json FILE`: the isa file is embedded as report.json "isa" as it is and
// report.md gets the per-pipeline ISA tables; a missing or foreign file is refused before the run.
#include <gtest/gtest.h>

#include "tests/isa/isa_cache_runs.h"
#include "tests/support/cli_test_support.h"

namespace {

using namespace mb::cli_test;
using nlohmann::json;

TEST(CliIsaReport, EmbedsTheIsaFileAndShowsItsTables) {
  const auto dir = scratchDir("isa_report");
  std::string out;
  ASSERT_EQ(runCommand(mb::isa_test::filledIsaCacheIfAny() + motorbench() + "isa --family vega10 --json " + quoted(dir / "isa.json"), &out), 0) << out;
  ASSERT_EQ(runCommand(motorbench() + "report textured_box -o " + quoted(dir / "r") +
                           " --pipelines matrix,motor --no-bench --no-plots --frames 0 --size 32x24 --isa-json " + quoted(dir / "isa.json"),
                       &out),
            0)
      << out;
  const json isa = readJson(dir / "isa.json");
  const json r = readJson(dir / "r" / "report.json");
  ASSERT_FALSE(r.is_discarded()) << out;
  EXPECT_EQ(r.at("isa"), isa);
  // The matrix rigid vertex shader's row: "<instructions> / <VGPRs> / <waves>w" from the file.
  json rigid;
  for (const json& s : isa.at("shaders"))
    if (s.at("pipeline") == "matrix" && s.at("program") == "rigid" && s.at("stage") == "vertex") rigid = s;
  ASSERT_TRUE(rigid.is_object());
  const std::string cell = std::to_string(rigid.at("instructions").get<int>()) + " / " +
                           std::to_string(rigid.at("vgprs").get<int>()) + " / " +
                           std::to_string(rigid.at("wavesPerSimd").get<int>()) + "w";
  const std::string md = readText(dir / "r" / "report.md");
  EXPECT_NE(md.find("AMD ISA per vertex shader"), std::string::npos);
  // The first row of the matrix table: its counted ops (as the ops section) beside the ISA cell.
  const size_t table = md.find("ISA: matrix");
  ASSERT_NE(table, std::string::npos);
  const size_t row = md.find("\n| rigid | ", table);
  ASSERT_NE(row, std::string::npos);
  const std::string line = md.substr(row + 1, md.find('\n', row + 1) - row - 1);
  EXPECT_NE(line.find(" mul / "), std::string::npos) << line;
  EXPECT_NE(line.find("| " + cell + " |"), std::string::npos) << line << " vs " << cell;
}

TEST(CliIsaReport, MissingOrForeignIsaFileIsRefused) {
  const auto dir = scratchDir("isa_report_bad");
  std::string out;
  EXPECT_EQ(runCommand(motorbench() + "report textured_box -o " + quoted(dir / "r") + " --isa-json " +
                           quoted(dir / "none.json"), &out), 2) << out;
  EXPECT_NE(out.find("none.json: no such file"), std::string::npos) << out;
  std::ofstream(dir / "other.json") << "{\"schema\": \"motorbench-report/1\"}";
  EXPECT_EQ(runCommand(motorbench() + "report textured_box -o " + quoted(dir / "r") + " --isa-json " +
                           quoted(dir / "other.json"), &out), 2) << out;
  EXPECT_NE(out.find("not a `motorbench isa --json` file"), std::string::npos) << out;
}

}  // namespace
