// Sharded runs: `report`, `inspect` and `check` with --shard I/N run as GNU parallel would run
// them, then `motorbench merge`, against one unsharded run of the same inputs. Everything but the
// timings must be equal; a missing or duplicated shard must be an error; a shard holding no input
// says so.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "tests/support/cli_test_support.h"

namespace mb::cli_test {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

bool haveParallel() { return std::system("command -v parallel >/dev/null 2>&1") == 0; }

// `json` without the members that are timed (they differ between any two runs).
json untimed(json j) {
  if (j.is_object()) {
    for (const char* k : {"conversionMs", "updateMs", "timing"}) j.erase(k);
    for (auto& [k, v] : j.items()) v = untimed(v);
  } else if (j.is_array()) {
    for (auto& v : j) v = untimed(v);
  }
  return j;
}

// Runs `args` three times through GNU parallel with --shard {}/3 and -o/--json <dir>/s{}<suffix>.
void runShards(const fs::path& dir, const std::string& args, const std::string& outFlag, const std::string& suffix) {
  std::string out;
  const std::string cmd = "parallel -j3 --halt now,fail=1 " + motorbench() + args + " --shard {}/3 " + outFlag + " " +
                          quoted(dir / "s") + "{}" + suffix + " ::: 1 2 3";
  const int rc = runCommand(cmd, &out);
  ASSERT_TRUE(rc == 0 || rc == 1) << cmd << "\n" << out;  // inspect/check: 1 = a threshold, not a crash
}

const char* kScenes = "textured_box normal_torus scaled_hierarchy skinned_tube";

TEST(Shard, ReportShardsMergeToTheSingleRunsFigures) {
  if (!haveParallel()) GTEST_SKIP() << "GNU parallel not installed (scripts/setup.sh installs it)";
  const fs::path dir = scratchDir("shard_report");
  const std::string args = std::string("report ") + kScenes + " --frames 0 --no-bench --no-isa --no-plots --size 64x48";
  runShards(dir, args, "-o", "");
  std::string out;
  ASSERT_EQ(runCommand(motorbench() + args + " -o " + quoted(dir / "single"), &out), 0) << out;
  ASSERT_EQ(runCommand(motorbench() + "merge " + quoted(dir / "s1") + " " + quoted(dir / "s2") + " " +
                           quoted(dir / "s3") + " -o " + quoted(dir / "merged") + " --no-plots", &out), 0) << out;
  const json single = readJson(dir / "single" / "report.json"), merged = readJson(dir / "merged" / "report.json");
  ASSERT_FALSE(single.is_discarded());
  ASSERT_FALSE(merged.is_discarded());
  // Each shard measured only its part; together, every scene once.
  size_t parts = 0;
  for (const char* s : {"s1", "s2", "s3"}) parts += readJson(dir / s / "report.json")["scenes"].size();
  EXPECT_EQ(parts, 4u);
  ASSERT_EQ(merged["scenes"].size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    const json& a = single["scenes"][i];
    const json& b = merged["scenes"][i];
    EXPECT_EQ(a["id"], b["id"]);
    EXPECT_EQ(untimed(a), untimed(b)) << a["id"];
    for (const json& frame : b["frames"])
      for (const auto& [pipeline, png] : frame["images"].items()) {
        const std::string bytes = readText(dir / "merged" / png.get<std::string>());
        EXPECT_FALSE(bytes.empty()) << png;
        EXPECT_EQ(bytes, readText(dir / "single" / png.get<std::string>())) << png;
      }
  }
  EXPECT_EQ(untimed(single["summary"]), untimed(merged["summary"]));
  EXPECT_EQ(merged["settings"]["shard"]["count"], 3);
  EXPECT_TRUE(fs::exists(dir / "merged" / "report.html"));
  EXPECT_TRUE(fs::exists(dir / "merged" / "report.md"));

  // A missing shard and a duplicated shard are errors, and nothing is written.
  out.clear();
  EXPECT_EQ(runCommand(motorbench() + "merge " + quoted(dir / "s1") + " " + quoted(dir / "s3") + " -o " +
                           quoted(dir / "m2"), &out), 2);
  EXPECT_NE(out.find("shard 2/3 missing"), std::string::npos) << out;
  out.clear();
  EXPECT_EQ(runCommand(motorbench() + "merge " + quoted(dir / "s1") + " " + quoted(dir / "s2") + " " +
                           quoted(dir / "s2") + " -o " + quoted(dir / "m2"), &out), 2);
  EXPECT_NE(out.find("shard 2/3 given twice"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir / "m2" / "report.json"));
  // Shards of a different input list do not merge.
  out.clear();
  ASSERT_EQ(runCommand(motorbench() + "report textured_box --frames 0 --no-bench --no-isa --no-plots --size 64x48 --shard 2/3 -o " +
                           quoted(dir / "other"), &out), 0) << out;
  out.clear();
  EXPECT_EQ(runCommand(motorbench() + "merge " + quoted(dir / "s1") + " " + quoted(dir / "other") + " " +
                           quoted(dir / "s3") + " -o " + quoted(dir / "m2"), &out), 2);
  EXPECT_NE(out.find("different input lists"), std::string::npos) << out;
  fs::remove_all(dir);
}

TEST(Shard, InspectShardsMergeToTheSingleRunsJson) {
  if (!haveParallel()) GTEST_SKIP() << "GNU parallel not installed (scripts/setup.sh installs it)";
  const fs::path dir = scratchDir("shard_inspect");
  runShards(dir, std::string("inspect ") + kScenes + " crowd", "--json", ".json");
  std::string out;
  runCommand(motorbench() + "inspect " + kScenes + " crowd --json " + quoted(dir / "single.json"), &out);
  ASSERT_EQ(runCommand(motorbench() + "merge " + quoted(dir / "s1.json") + " " + quoted(dir / "s2.json") + " " +
                           quoted(dir / "s3.json") + " -o " + quoted(dir / "merged.json"), &out), 0) << out;
  const json single = readJson(dir / "single.json"), merged = readJson(dir / "merged.json");
  ASSERT_FALSE(merged.is_discarded());
  EXPECT_EQ(merged["files"].size(), 5u);
  EXPECT_EQ(single["files"], merged["files"]);
  EXPECT_EQ(single["aggregate"], merged["aggregate"]);
  out.clear();
  EXPECT_EQ(runCommand(motorbench() + "merge " + quoted(dir / "s1.json") + " " + quoted(dir / "s2.json") +
                           " -o " + quoted(dir / "m2.json"), &out), 2);
  EXPECT_NE(out.find("shard 3/3 missing"), std::string::npos) << out;
  fs::remove_all(dir);
}

TEST(Shard, CheckShardsMergeToTheSingleRunsResult) {
  if (!haveParallel()) GTEST_SKIP() << "GNU parallel not installed (scripts/setup.sh installs it)";
  const fs::path dir = scratchDir("shard_check");
  const std::string golden = quoted(fs::path(MB_SOURCE_DIR) / "tests" / "golden");
  const std::string args = "check --golden " + golden + " --scenes textured_box,normal_torus,scaled_hierarchy";
  runShards(dir, args, "--out", "");
  std::string out;
  ASSERT_EQ(runCommand(motorbench() + args + " --out " + quoted(dir / "single"), &out), 0) << out;
  out.clear();
  ASSERT_EQ(runCommand(motorbench() + "merge " + quoted(dir / "s1") + " " + quoted(dir / "s2") + " " +
                           quoted(dir / "s3") + " -o " + quoted(dir / "merged"), &out), 0) << out;
  const json single = readJson(dir / "single" / "check.json"), merged = readJson(dir / "merged" / "check.json");
  ASSERT_FALSE(merged.is_discarded());
  EXPECT_EQ(single["counts"], merged["counts"]);
  EXPECT_EQ(single["images"], merged["images"]);
  EXPECT_TRUE(fs::exists(dir / "merged" / "summary.html"));
  out.clear();
  EXPECT_EQ(runCommand(motorbench() + "merge " + quoted(dir / "s1") + " " + quoted(dir / "s1") + " " +
                           quoted(dir / "s3") + " -o " + quoted(dir / "m2"), &out), 2);
  EXPECT_NE(out.find("given twice"), std::string::npos) << out;
  fs::remove_all(dir);
}

TEST(Shard, BadShardSpecIsAnError) {
  for (const char* bad : {"0/3", "4/3", "1/0", "x", "1/3/2"}) {
    std::string out;
    EXPECT_EQ(runCommand(motorbench() + "inspect textured_box --shard " + bad, &out), 2) << bad;
    EXPECT_NE(out.find("--shard"), std::string::npos) << out;
  }
}

// A shard that holds none of the inputs says so (inspect, check, report); inspect still writes
// its JSON.
TEST(CliInputText, AnEmptyShardSaysSo) {
  const fs::path dir = mb::cli_test::scratchDir("input_shard");
  const auto r = runMb("inspect normal_torus textured_box --shard 3/3 --json " + quoted(dir / "s3.json"));
  EXPECT_EQ(r.rc, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "shard 3/3 holds none of the 2 input(s) (more shards than inputs)")) << r.out;
  EXPECT_TRUE(fs::is_regular_file(dir / "s3.json"));
  const auto check = runMb("check --golden " + quoted(fs::path(MB_SOURCE_DIR) / "tests" / "golden") +
                           " --scenes normal_torus --pipelines matrix --shard 2/2 --out " + quoted(dir / "c"));
  EXPECT_EQ(check.rc, 0) << check.out;
  EXPECT_TRUE(contains(check.out, "shard 2/2 holds none of the 1 input(s)")) << check.out;
  const auto report = runMb("report normal_torus --shard 3/3 --frames 0 --no-bench --no-isa --no-plots -o " + quoted(dir / "r"));
  EXPECT_EQ(report.rc, 0) << report.out;
  EXPECT_TRUE(contains(report.out, "warning: shard 3/3 holds none of the 1 input(s)")) << report.out;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mb::cli_test
