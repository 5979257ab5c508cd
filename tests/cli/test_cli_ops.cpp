// `motorbench ops` end to end: the per-vertex section counts every pipeline's kernels both ways
// (counted and from SPIR-V, agreeing or saying why not) and the run prints its progress steps.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::exe;
using mb::cli_test::readJson;
using mb::cli_test::runCommand;
using mb::cli_test::scratchFile;

TEST(CliOps, PerVertexSectionHasBothWaysForEveryPipeline) {
  const fs::path json = scratchFile("ops.json");
  std::string log;
  ASSERT_EQ(runCommand(exe() + "ops --json '" + json.string() + "'", &log), 0) << log;
  EXPECT_NE(log.find("Ops per vertex"), std::string::npos) << log;
  // ops says where it is (a silent run of a minute looks hung; checked here to run the whole of ops once).
  for (const char* step : {"ops: 1/4 steps done (kernels counted", "ops: 2/4 steps done (per-vertex",
                           "ops: 3/4 steps done (per-pipeline", "ops: 4/4 steps done ("})
    EXPECT_NE(log.find(step), std::string::npos) << step << "\n" << log;
  const nlohmann::json j = readJson(json);
  ASSERT_FALSE(j.is_discarded()) << log;
  ASSERT_TRUE(j.contains("per_vertex")) << j.dump();
  const auto& pv = j["per_vertex"];
  const bool tools = pv["tools_problem"].get<std::string>().empty();
  std::set<std::string> seen;
  for (const auto& k : pv["kernels"]) {
    seen.insert(k["pipeline"].get<std::string>() + "/" + k["kernel"].get<std::string>());
    EXPECT_GT(k["counted"]["mul"].get<int>(), 0) << k.dump();
    if (tools) {
      EXPECT_TRUE(k["spirv"].is_object()) << k.dump();
      // Counted and SPIR-V agree, or the difference is explained.
      EXPECT_TRUE(k["agree"].get<bool>() || !k["why"].get<std::string>().empty()) << k.dump();
    }
  }
  for (const char* p : {"matrix", "motor"})
    for (const char* k : {"rigid vertex with frame", "skinned vertex (4 joints)", "world to clip"})
      EXPECT_TRUE(seen.count(std::string(p) + "/" + k)) << p << " " << k;
  EXPECT_TRUE(seen.count("matrix-affine/rigid vertex with frame"));
  for (const auto& v : pv["variants"]) {
    if (tools) {
      EXPECT_TRUE(v["spirv"].is_object()) << v.dump();
    }
  }
  fs::remove(json);
}

}  // namespace
