// `motorbench isa` end to end on RADV's null device (no AMD hardware): every registered
// pipeline's vertex shaders for the six families (navi21 with NGG culling off and on), our
// occupancy rule against RADV's own figure for every shader, byte-identical reruns, and the
// error when RADV is missing.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "pipelines/pipeline.h"
#include "tests/isa/isa_cache_runs.h"
#include "tests/support/cli_test_support.h"

namespace {

using namespace mb::cli_test;
using nlohmann::json;

const std::vector<std::string> kFamilyIds = {"tahiti", "polaris10", "vega10", "navi10",
                                             "navi21-nonggc", "navi21-ngg", "gfx1100"};

int radvUnits(const json& s) {
  const std::string gen = s.at("generation");
  const int waves = s.at("wavesPerSimd");
  return gen.rfind("RDNA", 0) == 0 ? waves * s.at("waveSize").get<int>() / 32 : waves;
}

// Run a compiles every shader with glslang (its SPIR-V cache starts empty and it stores every
// module there); run b takes every module from that cache: identical files say the reruns agree
// and the cache returns what glslang makes (isa_cache_runs.h: the room's later runs reuse it).
TEST(CliIsa, TwoRunsGiveIdenticalFiles) {
  const auto& runs = mb::isa_test::coldThenCachedRuns();
  const auto& dir = runs.dir;
  for (int i = 0; i < 2; ++i) ASSERT_EQ(runs.rc[i], 0) << runs.output[i];
  // Run a stored the modules run b read.
  EXPECT_FALSE(std::filesystem::is_empty(dir / "cache" / "spirv"));
  const std::string a = readText(dir / "a.json");
  EXPECT_FALSE(a.empty());
  EXPECT_EQ(a, readText(dir / "b.json"));
  const std::string isa = readText(dir / "a_isa" / "motor.rigid.vertex.polaris10.txt");
  EXPECT_NE(isa.find("v_"), std::string::npos) << isa.substr(0, 400);  // vector instructions
  EXPECT_EQ(isa, readText(dir / "b_isa" / "motor.rigid.vertex.polaris10.txt"));
}

TEST(CliIsa, EveryPipelineEveryFamilyAndOurRuleAgreesWithRadv) {
  const auto dir = scratchDir("isa_full");
  std::string out;
  const int rc = runCommand(mb::isa_test::filledIsaCacheIfAny() + motorbench() + "isa --json " + quoted(dir / "a.json"), &out);
  ASSERT_EQ(rc, 0) << out;
  const json j = readJson(dir / "a.json");
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j.at("schema"), "motorbench-isa/1");
  EXPECT_EQ(j.at("driver").get<std::string>().rfind("Mesa ", 0), 0u) << j.at("driver");
  ASSERT_EQ(j.at("families").size(), kFamilyIds.size());
  for (size_t i = 0; i < kFamilyIds.size(); ++i) EXPECT_EQ(j["families"][i].at("id"), kFamilyIds[i]);

  std::map<std::string, std::set<std::string>> vertexFamilies;  // pipeline -> family ids
  std::map<std::string, int> nggInstructions;                    // "navi21-ngg" -> matrix rigid
  int checked = 0;
  for (const json& s : j.at("shaders")) {
    const std::string where = s.at("pipeline").get<std::string>() + " " + s.at("program").get<std::string>() +
                              " " + s.at("stage").get<std::string>() + " " + s.at("familyId").get<std::string>();
    EXPECT_GT(s.at("instructions").get<int>(), 0) << where;
    EXPECT_GT(s.at("vgprs").get<int>(), 0) << where;
    EXPECT_GT(s.at("codeSizeBytes").get<int>(), 0) << where;
    EXPECT_EQ(s.at("spilledVgprs"), 0) << where;
    // Our rule, in RADV's units, against RADV's "Subgroups per SIMD".
    EXPECT_EQ(radvUnits(s), s.at("subgroupsPerSimd").get<int>()) << where << ": " << s.dump();
    ++checked;
    if (s.at("stage") == "vertex") vertexFamilies[s.at("pipeline")].insert(s.at("familyId"));
    if (s.at("stage") == "vertex" && s.at("pipeline") == "matrix" && s.at("program") == "rigid")
      nggInstructions[s.at("familyId")] = s.at("instructions");
  }
  EXPECT_GT(checked, 300);
  for (const std::string& p : mb::allPipelineNames())
    EXPECT_EQ(vertexFamilies[p], std::set<std::string>(kFamilyIds.begin(), kFamilyIds.end())) << p;
  // NGG culling really changes the vertex shader (it adds the culling code).
  EXPECT_GT(nggInstructions["navi21-ngg"], nggInstructions["navi21-nonggc"] + 50);
  EXPECT_NE(out.find("vertex shaders"), std::string::npos) << out;
}

TEST(CliIsa, MissingRadvIsAnErrorNamingIt) {
  std::string out;
  const int rc = runCommand("VK_ICD_FILENAMES=/nonexistent/radeon_icd.json " + motorbench() + "isa", &out);
  EXPECT_EQ(rc, 2) << out;
  EXPECT_NE(out.find("/nonexistent/radeon_icd.json"), std::string::npos) << out;
  EXPECT_NE(out.find("does not exist"), std::string::npos) << out;
}

TEST(CliIsa, UnknownFamilyIsRefused) {
  std::string out;
  EXPECT_EQ(runCommand(motorbench() + "isa --family navi31", &out), 2) << out;
  EXPECT_NE(out.find("unknown family 'navi31'"), std::string::npos) << out;
}

}  // namespace
