// `motorbench report` and `motorbench claims`, end to end: the report on a small
// built-in scene writes report.json with the keys documented in README.md (section Report),
// its images exist and are referenced by relative paths, a bad file in the arguments is
// recorded with its error while the run goes on; the claims JSON holds every claim id with a
// measured value and a verdict. Never asserts timings or ratios, only that they are there.
#include <gtest/gtest.h>


#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/cli_test_support.h"
#include "pipelines/pipeline.h"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using mb::cli_test::motorbench;
using mb::cli_test::quoted;
using mb::cli_test::readJson;
using mb::cli_test::readText;
using mb::cli_test::runCommand;

TEST(CliReport, SmallSceneWithBadFileWritesDocumentedReport) {
  const fs::path dir = mb::cli_test::scratchDir("report");
  const fs::path bad = dir / "broken.gltf";
  std::ofstream(bad) << "{ this is not json";
  const fs::path out = dir / "out";
  std::string log;
  // The bad file first: the good scene after it must still be measured.
  const int rc = runCommand(motorbench() + "report " + quoted(bad) + " textured_box -o " + quoted(out) +
                                " --no-bench --no-isa --frames 3 --size 64x48 --jobs 2",
                            &log);
  // Written in full, but a scene failed: exit 1, as inspect.
  ASSERT_EQ(rc, 1) << log;
  EXPECT_NE(log.find("[2/2] textured_box: rendering motor t=0"), std::string::npos) << log;

  const json r = readJson(out / "report.json");
  ASSERT_FALSE(r.is_discarded()) << log;
  for (const char* key : {"schema", "tool", "machine", "settings", "summary", "scenes", "opsPerVertex", "kernels",
                          "plots", "files"})
    EXPECT_TRUE(r.contains(key)) << key;
  EXPECT_EQ(r["schema"], "motorbench-report/1");
  for (const char* key : {"cpu", "logicalCores", "gl", "lpNumThreads"}) EXPECT_TRUE(r["machine"].contains(key)) << key;
  EXPECT_EQ(r["settings"]["pipelines"], json(mb::pipelineNames()));  // every registered one, matrix first
  EXPECT_EQ(r["settings"]["width"], 64);
  ASSERT_EQ(r["scenes"].size(), 2u);

  const json& broken = r["scenes"][0];
  EXPECT_EQ(broken["status"], "failed");
  ASSERT_TRUE(broken["error"].is_string());
  EXPECT_NE(broken["error"].get<std::string>().find("broken.gltf"), std::string::npos) << broken["error"];

  const json& box = r["scenes"][1];
  EXPECT_EQ(box["id"], "textured_box");
  EXPECT_EQ(box["status"], "ok") << box.dump(1);
  for (const char* key : {"stats", "vertexMix", "times", "frames", "pipelines", "timing", "opsPerVertex"})
    EXPECT_TRUE(box.contains(key)) << key;
  ASSERT_FALSE(box["frames"].empty());
  for (const json& f : box["frames"]) {
    for (const char* p : {"matrix", "motor"}) {
      ASSERT_TRUE(f["images"][p].is_string()) << f.dump();
      const std::string rel = f["images"][p];
      EXPECT_FALSE(fs::path(rel).is_absolute()) << rel;
      EXPECT_TRUE(fs::is_regular_file(out / rel)) << rel;
    }
    ASSERT_TRUE(f["diffs"]["motor"].is_string());
    EXPECT_TRUE(fs::is_regular_file(out / f["diffs"]["motor"].get<std::string>()));
    for (const char* key : {"rmse", "psnr", "identical", "maxError", "fractionOver1"})
      EXPECT_TRUE(f["metrics"]["motor"].contains(key)) << key;
  }
  // Memory as uploaded: 12 vs 9 floats per vertex on this normal-mapped box.
  const json& mm = box["pipelines"]["matrix"]["memory"];
  const json& qm = box["pipelines"]["motor"]["memory"];
  for (const char* key : {"bytesPerVertex", "floatsPerVertex", "floatsPerTransform", "floatsPerJoint", "vertexBytes"})
    EXPECT_TRUE(mm.contains(key) && qm.contains(key)) << key;
  EXPECT_EQ(mm["floatsPerVertex"], 12.0);
  EXPECT_EQ(qm["floatsPerVertex"], 9.0);
  EXPECT_TRUE(box["pipelines"]["motor"].contains("fallbacks"));
  EXPECT_TRUE(box["pipelines"]["motor"]["conversionMs"]["median"].is_number());
  EXPECT_TRUE(box["timing"]["ratio_motor_matrix"].is_number()) << box["timing"].dump();
  EXPECT_TRUE(box["opsPerVertex"]["motor"]["counted"]["mul"].is_number());
  EXPECT_EQ(box["stats"]["geometry"]["vertices"], 24);

  EXPECT_EQ(r["kernels"]["source"], "skipped");
  EXPECT_TRUE(r["kernels"]["error"].is_string());
  EXPECT_EQ(r["summary"]["failed"], 1);
  EXPECT_EQ(r["summary"]["ok"], 1);

  // The documents: relative image paths, the failure named.
  for (const char* doc : {"report.md", "report.html"}) {
    const std::string text = readText(out / doc);
    EXPECT_NE(text.find("images/textured_box/t0_motor.png"), std::string::npos) << doc;
    EXPECT_EQ(text.find(out.string()), std::string::npos) << doc << " holds an absolute path";
    EXPECT_NE(text.find("broken.gltf"), std::string::npos) << doc;
    // A summary median says how many scenes it covers (one scene loaded here), and
    // the glossary explains every counter and the heat maps' colours.
    EXPECT_NE(text.find("36 over 1 scene"), std::string::npos) << doc << ": bytes per vertex without its scene count";
    EXPECT_NE(text.find("Glossary"), std::string::npos) << doc;
    EXPECT_NE(text.find("zeroScalarFrames"), std::string::npos) << doc;
    EXPECT_NE(text.find("Diff heat maps:"), std::string::npos) << doc;
  }
  EXPECT_TRUE(r["glossary"]["PipelineStats"].contains("zeroScalarFrames")) << r["glossary"].dump();

  // The ops step (a minute or more) reports progress up to its last item; every frame
  // records the pixels each pipeline drew (the box covers part of the image, never all of it).
  EXPECT_TRUE(std::regex_search(log, std::regex("report: counting ops per vertex: ([0-9]+)/\\1 kernels and shader variants")))
      << log;
  for (const json& f : box["frames"])
    for (const std::string& p : mb::pipelineNames()) {
      ASSERT_TRUE(f["drawnPixels"][p].is_number_integer()) << f.dump();
      EXPECT_GT(f["drawnPixels"][p].get<int64_t>(), 0) << p;
      EXPECT_LT(f["drawnPixels"][p].get<int64_t>(), 64 * 48) << p;
    }
  // image_error is grouped, one bar per compared pipeline on the scene, each at its
  // own x, read from the data plots/index.json records (when matplotlib is there).
  if (r["plots"]["available"] == true) {
    const json index = readJson(out / "plots" / "index.json");
    ASSERT_FALSE(index.is_discarded());
    json bars;
    for (const json& f : index["files"])
      if (f["name"] == "image_error") bars = f["bars"];
    ASSERT_TRUE(bars.is_array()) << index.dump(1);
    std::set<std::string> series;
    std::set<double> xs;
    for (const json& b : bars)
      if (b["panel"] == "psnr" && b["label"] == "textured_box") series.insert(b["series"].get<std::string>()), xs.insert(b["x"].get<double>());
    std::vector<std::string> compared = mb::pipelineNames();
    compared.erase(compared.begin());  // the baseline
    EXPECT_EQ(series, std::set<std::string>(compared.begin(), compared.end())) << bars.dump();
    EXPECT_EQ(xs.size(), compared.size()) << bars.dump();
  }
  EXPECT_EQ(r["diffLegend"]["stops"].size(), 7u);
  fs::remove_all(dir);
}

TEST(CliReport, MissingPythonIsReportedAndTheRunGoesOn) {
  const fs::path dir = mb::cli_test::scratchDir("report_nopython");
  std::string log;
  const int rc = runCommand(motorbench() + "report textured_box -o " + quoted(dir) +
                                " --no-bench --no-isa --frames 0 --size 32x24 --python /nonexistent/python3",
                            &log);
  ASSERT_EQ(rc, 0) << log;
  const json r = readJson(dir / "report.json");
  ASSERT_FALSE(r.is_discarded());
  EXPECT_FALSE(r["plots"]["available"].get<bool>());
  ASSERT_TRUE(r["plots"]["error"].is_string());
  EXPECT_NE(readText(dir / "report.md").find("No plots"), std::string::npos);
  EXPECT_TRUE(fs::is_regular_file(dir / "report.html"));
  fs::remove_all(dir);
}

TEST(CliReport, RejectsBadUsage) {
  std::string log;
  EXPECT_EQ(runCommand(motorbench() + "report textured_box", &log), 2) << log;  // no -o
  EXPECT_EQ(runCommand(motorbench() + "report -o /tmp/x --jobs 0", &log), 2) << log;
  EXPECT_EQ(runCommand(motorbench() + "report -o /tmp/x --pipelines nosuch", &log), 2) << log;
  EXPECT_EQ(runCommand(motorbench() + "report -o /tmp/x --bogus 1", &log), 2) << log;
}

TEST(CliClaims, JsonHoldsEveryClaimWithMeasuredValueAndVerdict) {
  const fs::path dir = mb::cli_test::scratchDir("claims");
  std::string log;
  // A tiny bench run for the speed claim (the claims command reads it instead of running one).
  ASSERT_EQ(runCommand(motorbench() + "bench --benchmark_filter='^vertex_frame/in_cache' --benchmark_min_time=0.01 --out " +
                           quoted(dir / "bench.json"),
                       &log),
            0)
      << log;
  log.clear();
  const int rc = runCommand(motorbench() + "claims -o " + quoted(dir / "claims.md") + " --json " +
                                quoted(dir / "claims.json") + " --bench-json " + quoted(dir / "bench.json") +
                                " --frames 3 --corpus " + quoted(fs::path(MB_SOURCE_DIR) / ".." / "shared" / "corpus"),
                            &log);
  ASSERT_EQ(rc, 0) << log;
  const json j = readJson(dir / "claims.json");
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j["schema"], "motorbench-claims/1");
  std::map<std::string, json> byId;
  for (const json& c : j["claims"]) byId[c["id"].get<std::string>()] = c;
  const std::set<std::string> verdicts = {"reproduced", "differs", "inconclusive", "not measurable here", "baseline"};
  // Every claim of the paper, and the reviewer baselines.
  for (const char* id : {"gp_mm", "gp_rr", "gp_tt", "gp_rt", "gp_tr", "gp_rm", "gp_mr", "gp_tm", "gp_mt",
                         "mat4_mul_mat4", "sw_mp_naive", "sw_mp", "mat4_mul_vec4", "sw_md", "sw_mx", "normalize_m",
                         "sqrt_m", "exp_b", "log_m", "extractNormalTangent", "vertex_frame_motor",
                         "vertex_frame_matrix", "floats_per_vertex", "floats_per_transform", "as_fast_as_matrices",
                         "animated_scale_corpus", "affine_matrix_vertex", "world_to_clip_matrix",
                         "world_to_clip_motor", "skinned_vertex_matrix", "skinned_vertex_motor", "composition",
                         "scene_graph_update", "quaternion_to_rotor", "uniform_scale_overhead", "handedness_rule",
                         "blend_vs_slerp"}) {
    ASSERT_TRUE(byId.count(id)) << id;
    const json& c = byId[id];
    for (const char* key : {"statement", "paper", "measured", "method", "verdict", "verdictText"})
      EXPECT_TRUE(c[key].is_string()) << id << " " << key;
    EXPECT_TRUE(verdicts.count(c["verdict"].get<std::string>())) << id << ": " << c["verdict"];
    EXPECT_FALSE(c["measuredValue"].is_null()) << id << ": " << c["verdictText"];
  }
  // Counted values, never typed in: gp_mm agrees with the paper's table.
  EXPECT_EQ(byId["gp_mm"]["measuredValue"]["mul"], 48);
  EXPECT_EQ(byId["floats_per_vertex"]["measuredValue"]["motor"], 9.0);
  EXPECT_NE(readText(dir / "claims.md").find("gp_mm"), std::string::npos);
  // Timed here: the curved frame-time row names the device that drew it.
  ASSERT_TRUE(byId.count("curved_frame_time"));
  const std::string curved = byId["curved_frame_time"]["measured"].get<std::string>();
  EXPECT_TRUE(curved.find("device: CPU rasterizer (") != std::string::npos ||
              curved.find("device: GPU (") != std::string::npos) << curved;
  // The skinned ops row also compares the two pipelines in the same skinning configuration.
  ASSERT_TRUE(byId.count("ops_skinned_vs_strongest"));
  const std::string skinned = byId["ops_skinned_vs_strongest"]["verdictText"].get<std::string>();
  EXPECT_NE(skinned.find("matched configurations, motor vs matrix: palette relative to the mesh node "),
            std::string::npos) << skinned;
  EXPECT_NE(skinned.find(", world palette "), std::string::npos) << skinned;
  fs::remove_all(dir);
}

// The speed claims' frame evidence from a report.json: the paired vertex-bound
// ratio per kind of scene (dense_torus rigid: paired 0.80, not 1.30) in the rigid row, the skinned
// scene in its own row, where a timing in the pipelines' different default skinning
// configurations is named asymmetric and not used.
TEST(CliClaims, FrameRatiosArePairedAndVertexBoundOnlyWhereMeasured) {
  const fs::path dir = mb::cli_test::scratchDir("claims_frames");
  const json report = {
      {"scenes",
       {{{"id", "a"},
         {"timing",
          {{"ratio_motor_matrix", 1.5},
           {"paired_ratio_motor_matrix", 0.9},
           {"vertexBound", {{"skipped", "not vertex-bound at 64x64"}}}}}},
        {{"id", "dense_torus"},
         {"timing",
          {{"ratio_motor_matrix", 0.95},
           {"vertexBound", {{"ratio_motor_matrix", 1.3}, {"paired_ratio_motor_matrix", 0.8}}}}}},
        {{"id", "crowd"},
         {"vertexMix", {{"rigid", 0}, {"skinned", 100}}},
         {"timing",
          {{"ratio_motor_matrix", 1.0},
           {"vertexBound", {{"paired_ratio_motor_matrix", 0.5}}}}}},
        // A curved scene times its own pair: not evidence for the glTF pipelines.
        {{"id", "s3_tiling"},
         {"space", "spherical (S3)"},
         {"timing", {{"ratio_motor_matrix", 0.1}, {"vertexBound", {{"paired_ratio_motor_matrix", 0.1}}}}}}}}};
  std::ofstream(dir / "report.json") << report.dump();
  std::string log;
  ASSERT_EQ(runCommand(motorbench() + "claims --no-run --report " + quoted(dir / "report.json") + " -o " +
                           quoted(dir / "claims.md") + " --json " + quoted(dir / "claims.json"),
                       &log),
            0)
      << log;
  const json j = readJson(dir / "claims.json");
  json speed, skinnedSpeed;
  for (const json& c : j["claims"]) {
    if (c["id"] == "as_fast_as_matrices") speed = c;
    if (c["id"] == "as_fast_as_matrices_skinned") skinnedSpeed = c;
  }
  ASSERT_TRUE(speed.is_object() && skinnedSpeed.is_object()) << j.dump(2);
  // The rigid sentence: dense_torus's paired vertex-bound ratio (0.80, not the 1.30 of medians);
  // neither scene "a" (not vertex-bound) nor the curved scene (0.1) is evidence.
  const json& kinds = speed["measuredValue"]["kinds"];
  const json& rigid = kinds["frame time, vertex-bound dense_torus (median of per-frame paired ratios)"];
  ASSERT_TRUE(rigid["costRatio"].is_number()) << kinds.dump(2);
  EXPECT_DOUBLE_EQ(rigid["costRatio"].get<double>(), 0.8);
  EXPECT_EQ(speed.dump().find("0.1,"), std::string::npos);
  // The skinned evidence is its own row, and a timing in the pipelines' default skinning
  // configurations (no skinSpace recorded) is named asymmetric and not used.
  const json& skinned = skinnedSpeed["measuredValue"]["kinds"]["frame time, vertex-bound crowd (median of per-frame paired ratios)"];
  ASSERT_TRUE(skinned.is_object()) << skinnedSpeed.dump(2);
  EXPECT_FALSE(skinned["usable"].get<bool>()) << skinned.dump(2);
  EXPECT_NE(skinned["caveat"].get<std::string>().find("asymmetric"), std::string::npos) << skinned.dump(2);
  fs::remove_all(dir);
}

}  // namespace
