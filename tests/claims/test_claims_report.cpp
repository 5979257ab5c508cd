// `motorbench claims --report` reads what it is given: a small hand-made report.json of four scenes
// timed at 128x96 on a CPU rasterizer, with an ISA section, kernel pairs and scene statistics, and
// each row's text checked against the fixture's numbers.
#include <gtest/gtest.h>

#include <map>

#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using mb::cli_test::motorbench;
using mb::cli_test::quoted;
using mb::cli_test::readJson;
using mb::cli_test::readText;
using mb::cli_test::runCommand;

json pipelines(std::map<std::string, double> frameMs, std::map<std::string, double> updateMs) {
  json p = json::object();
  for (const auto& [name, ms] : frameMs)
    p[name] = {{"medianMs", ms}, {"updateMedianMs", updateMs.at(name)},
               {"updatePhasesMedianMs", {{"hierarchy", updateMs.at(name)}}}};
  return p;
}

json stats(const std::string& file, int drawn, json scale) {
  return {{"file", file}, {"loaded", true}, {"geometry", {{"drawnVertices", drawn}}},
          {"skinning", {{"skins", 0}}}, {"materials", {{"normalMappedPrimitives", 0}}},
          {"animation", {{"channels", 0}}}, {"unsupported", json::array()}, {"fallbacks", json::object()},
          {"scale", scale}};
}

json uniformScale() {
  return {{"paperTolerance", 1e-4}, {"scaleChannels", 0}, {"changingScaleChannels", 0},
          {"nonUniformChangingChannels", 0}, {"innerNonUniformNodes", 0}};
}

json isaShader(const std::string& pipeline, int instructions, int vgprs) {
  return {{"pipeline", pipeline}, {"program", "rigid_normalmap"}, {"stage", "vertex"}, {"family", "polaris10"},
          {"ngg", false}, {"instructions", instructions}, {"vgprs", vgprs}, {"sgprs", 16}, {"wavesPerSimd", 10}};
}

json fixture() {
  const std::map<std::string, double> tiny = {{"matrix", 1e-4}, {"affine", 1e-4}, {"qtangent", 1e-4},
                                              {"motor", 1e-4}, {"motor_q", 1e-4}, {"hybrid", 1e-4}};
  json box = uniformScale();
  box["innerNonUniformNodes"] = 1;
  box["innerNonUniformityMax"] = 2.1459e-3;
  box["innerNonUniformExample"] = {{"node", 0}, {"name", "Hips"}, {"scale", {0.997854, 0.9999999, 1.0}}};
  json cow = uniformScale();
  cow["scaleChannels"] = 2, cow["changingScaleChannels"] = 1;
  json scenes = json::array();
  // dense_torus: vertex-bound on llvmpipe, every pipeline within 1 % although their ops differ.
  scenes.push_back({{"id", "dense_torus"}, {"spec", "dense_torus"}, {"stats", stats("dense_torus", 40000, uniformScale())},
                    {"timing", {{"width", 128}, {"height", 96}, {"paired_ratio_motor_matrix", 1.0},
                                {"pipelines", pipelines({{"matrix", 4.0}, {"affine", 4.0}, {"qtangent", 3.98}, {"motor", 4.02},
                                                         {"motor_q", 4.0}, {"hybrid", 3.98}}, tiny)},
                                {"vertexBound", {{"width", 64}, {"height", 64}, {"paired_ratio_motor_matrix", 1.01},
                                                 {"pipelines", pipelines({{"matrix", 10.33}, {"affine", 10.35},
                                                                          {"qtangent", 10.34}, {"motor", 10.41},
                                                                          {"motor_q", 10.36}, {"hybrid", 10.34}}, tiny)}}}}}});
  // crowd: the one scene with update work enough to count (0.12..0.2 ms).
  scenes.push_back({{"id", "crowd"}, {"spec", "crowd"}, {"stats", stats("crowd", 50000, uniformScale())},
                    {"timing", {{"width", 128}, {"height", 96}, {"paired_ratio_motor_matrix", 0.9},
                                {"pipelines", pipelines({{"matrix", 5.0}, {"affine", 5.0}, {"qtangent", 4.5}, {"motor", 4.6},
                                                         {"motor_q", 4.5}, {"hybrid", 4.5}},
                                                        {{"matrix", 0.2}, {"affine", 0.15}, {"qtangent", 0.16}, {"motor", 0.12},
                                                         {"motor_q", 0.13}, {"hybrid", 0.14}})}}}});
  // Two small files: an inner node scaled (0.997854, 0.9999999, 1), a changing scale channel.
  scenes.push_back({{"id", "box"}, {"spec", "/nonexistent/box.glb"}, {"stats", stats("/nonexistent/box.glb", 24, box)},
                    {"timing", {{"width", 128}, {"height", 96}, {"paired_ratio_motor_matrix", 1.0},
                                {"pipelines", pipelines({{"matrix", 2.0}, {"affine", 2.0}, {"qtangent", 2.0}, {"motor", 2.0},
                                                         {"motor_q", 2.0}, {"hybrid", 2.0}}, tiny)}}}});
  scenes.push_back({{"id", "cow"}, {"spec", "/nonexistent/cow.glb"}, {"stats", stats("/nonexistent/cow.glb", 3000, cow)}});
  // The uploads the report recorded (claims reads them, renders nothing): hand values
  // unlike any render's (motor 10 floats per transform with its scale, 3 more than without).
  const json matrixStats = {{"floatsPerVertex", 12.0}, {"floatsPerTransform", 32.0}, {"floatsPerTransformWithScale", 32.0},
                            {"vertexBytes", 4800}, {"vertices", 100}};
  const json motorStats = {{"floatsPerVertex", 9.0}, {"floatsPerTransform", 7.0}, {"floatsPerTransformWithScale", 10.0},
                           {"vertexBytes", 3000}, {"vertices", 100}};
  json uploads = json::object();
  uploads["matrix"]["stats"] = matrixStats;
  uploads["motor"]["stats"] = motorStats;
  scenes.push_back({{"id", "normal_torus"}, {"spec", "normal_torus"}, {"stats", stats("normal_torus", 100, uniformScale())},
                    {"pipelines", uploads}});
  json isa = {{"schema", "motorbench-isa/1"},
              {"families", json::array({{{"family", "polaris10"}, {"ngg", false}, {"generation", "GCN 4"}}})},
              {"shaders", json::array({isaShader("matrix", 60, 12), isaShader("affine", 50, 10), isaShader("qtangent", 55, 11),
                                       isaShader("hybrid", 55, 11), isaShader("motor", 120, 24), isaShader("motor_q", 110, 20)})}};
  json kernels = {{"pairs", json::array({{{"kernel", "vertex_frame"}, {"size", "in_cache"},
                                          {"simd_matrix", {{"items_per_second", 100.0}}},
                                          {"simd_motor", {{"items_per_second", 125.0}}}},
                                         {{"kernel", "compose"},
                                          {"simd_affine", {{"items_per_second", 360.0}}},
                                          {"simd_matrix", {{"items_per_second", 215.0}}},
                                          {"simd_motor", {{"items_per_second", 548.0}}},
                                          {"motor", {{"items_per_second", 87.0}}}}})},
                  {"file", "fixture bench"}};
  return {{"machine", {{"cpu", "Test CPU Model 9000"}, {"logicalCores", 3},
                       {"gl", {{"renderer", "llvmpipe (LLVM 15.0.6, 256 bits)"}, {"kind", "cpu-rasterizer"}}}}},
          {"settings", {{"timeWidth", 128}, {"timeHeight", 96}, {"width", 160}, {"height", 120}}},
          // The compact pipelines' image summary: motor_c worst 53.5 dB, matrix_c identical.
          {"summary", {{"images", {{"motor_c", {{"comparedFrames", 4}, {"identicalFrames", 1}, {"psnr", {{"min", 53.5}}}}},
                                   {"matrix_c", {{"comparedFrames", 4}, {"identicalFrames", 4}}}}}}},
          {"scenes", scenes}, {"isa", isa}, {"kernels", kernels}};
}

TEST(ClaimsReport, RowsReadTheReportTheyAreGiven) {
  const fs::path dir = mb::cli_test::scratchDir("claims_report");
  std::ofstream(dir / "report.json") << fixture().dump();
  std::string log;
  ASSERT_EQ(runCommand(motorbench() + "claims --no-run --report " + quoted(dir / "report.json") +
                           " --corpus /nonexistent -o " + quoted(dir / "claims.md") + " --json " + quoted(dir / "claims.json"),
                       &log),
            0)
      << log;
  const json j = readJson(dir / "claims.json");
  ASSERT_FALSE(j.is_discarded()) << log;
  std::map<std::string, json> byId;
  for (const json& c : j["claims"]) {
    byId[c["id"].get<std::string>()] = c;
    // --report was given: no row asks for it; no row quotes a size the report was not timed at.
    EXPECT_EQ(c["verdictText"].get<std::string>().find("give --report"), std::string::npos) << c["id"];
    EXPECT_EQ(c["measured"].get<std::string>().find("512x512"), std::string::npos) << c["id"];
  }
  // Speed, the paper's row: motor against the 4x4 matrix on the rigid vertex:
  // ISA motor 120 / matrix 60 = 2.0 instructions, waves 10 / 10 = 1.0 occupancy (VGPRs 24 vs 12
  // only quoted); the CPU kernel simd_motor against simd_matrix (100 / 125 = 0.8); llvmpipe puts
  // pipelines whose counted ops differ by more than 25 % within 1 %: unable to discriminate, not
  // counted; the usable kinds split, so the verdict is inconclusive.
  const json& speed = byId["as_fast_as_matrices"];
  const json& v = speed["measuredValue"]["kinds"];
  EXPECT_NE(speed["measured"].get<std::string>().find("at 64x64"), std::string::npos) << speed["measured"];
  EXPECT_NE(speed["paper"].get<std::string>().find("just as fast as 4x4 matrices"), std::string::npos);
  EXPECT_DOUBLE_EQ(v["AMD ISA instructions, whole rigid vertex shader"]["costRatio"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(v["AMD ISA occupancy (waves per SIMD), whole rigid vertex shader"]["costRatio"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(v["CPU kernel vertex_frame, fastest motor vs fastest 4x4 matrix implementation"]["costRatio"].get<double>(), 0.8);
  // The same ISA as rows of their own beside the counted and SPIR-V ops rows: rigid 2.2 / 2.0 on
  // the one family given, does not hold; no skinned shader in the fixture: not measurable.
  const json& isaRigid = byId["ops_clip_vs_strongest_isa"];
  EXPECT_DOUBLE_EQ(isaRigid["measuredValue"]["instructions"].get<double>(), 2.2) << isaRigid;
  EXPECT_DOUBLE_EQ(isaRigid["measuredValue"]["vgprs"].get<double>(), 2.0) << isaRigid;
  EXPECT_EQ(isaRigid["verdict"], "differs") << isaRigid;
  EXPECT_NE(isaRigid["measured"].get<std::string>().find("polaris10 2.20x motor_q / affine"),
            std::string::npos) << isaRigid["measured"];
  EXPECT_EQ(byId["ops_skinned_vs_strongest_isa"]["verdict"], "not measurable here") << byId["ops_skinned_vs_strongest_isa"];
  const json& frame = v["frame time, vertex-bound dense_torus (median of per-frame paired ratios)"];
  ASSERT_TRUE(frame["caveat"].is_string()) << v.dump(2);
  EXPECT_NE(frame["caveat"].get<std::string>().find("unable to discriminate"), std::string::npos) << frame;
  EXPECT_NE(frame["detail"].get<std::string>().find("CPU rasterizer (llvmpipe"), std::string::npos) << frame;
  EXPECT_EQ(speed["verdict"], "inconclusive") << speed["verdictText"];
  EXPECT_EQ(speed["verdictText"].get<std::string>().find("within 10 %"), std::string::npos) << speed["verdictText"];
  // Timed "vs strongest" rows, the minimum of work per timed block as printed:
  // a 0.1 us update runs 1000 calls per block = 0.1 ms >= 50 us, so dense_torus counts beside
  // crowd (box draws 24 vertices: listed): motor median(1, 0.12 / 0.2) = 0.8, affine
  // median(1, 0.75) = 0.875.
  const json& update = byId["cpu_update_vs_strongest"];
  EXPECT_DOUBLE_EQ(update["measuredValue"]["values"]["motor"].get<double>(), 0.8);
  EXPECT_DOUBLE_EQ(update["measuredValue"]["values"]["affine"].get<double>(), 0.875);
  EXPECT_NE(update["method"].get<std::string>().find("median over 2 scenes"), std::string::npos) << update["method"];
  EXPECT_NE(update["method"].get<std::string>().find("box ("), std::string::npos) << update["method"];
  EXPECT_NE(byId["scene_graph_update"]["measured"].get<std::string>().find("listed, not counted: "), std::string::npos);
  EXPECT_NE(byId["frame_time_vs_strongest"]["verdictText"].get<std::string>().find("CPU rasterizer"), std::string::npos);
  // The compact vertices' image cost is the report's own figure, not a render of its own.
  const json& compactImage = byId["compact_image_cost"];
  EXPECT_DOUBLE_EQ(compactImage["measuredValue"]["motor_c"].get<double>(), 53.5) << compactImage;
  EXPECT_TRUE(compactImage["measuredValue"]["matrix_c"].is_null()) << compactImage;
  EXPECT_EQ(compactImage["measured"], "53.5 dB vs identical") << compactImage;
  EXPECT_NE(compactImage["method"].get<std::string>().find("the report's summary"), std::string::npos) << compactImage;
  EXPECT_NE(compactImage["method"].get<std::string>().find("160x120"), std::string::npos) << compactImage;
  // Composition: the bench pair's fastest sides, simd_motor 548 against simd_affine 360 items/s.
  const json& comp = byId["composition"]["measuredValue"]["bench"];
  EXPECT_EQ(comp["fastestMotor"], "simd_motor");
  EXPECT_EQ(comp["fastestMatrix"], "simd_affine");
  EXPECT_NEAR(comp["motorOverFastestMatrix"].get<double>(), 360.0 / 548.0, 1e-12);
  // Scene statistics from the report's two files (the built-in scenes are not counted): box.glb
  // has its inner node non-uniform by 0.21 % (beyond the paper's 1e-4, not beyond 1 %).
  const json& leaves = byId["nonuniform_scale_leaves"];
  EXPECT_EQ(leaves["measuredValue"]["files"], 5);  // dense_torus, crowd, box, cow, normal_torus
  EXPECT_EQ(leaves["measuredValue"]["judgedFiles"], 2);
  EXPECT_EQ(leaves["measuredValue"]["judgedWithInnerNonUniform"], 1);
  EXPECT_EQ(leaves["measuredValue"]["judgedBeyond1Percent"], 0);
  EXPECT_NE(leaves["measured"].get<std::string>().find("box.glb node Hips scale (0.997854, 0.9999999, 1)"), std::string::npos)
      << leaves["measured"];
  EXPECT_EQ(leaves["verdict"], "differs");
  const json& animated = byId["animated_scale_corpus"];
  EXPECT_EQ(animated["measuredValue"]["judgedWithChangingScale"], 1);
  EXPECT_EQ(animated["verdict"], "not measurable here");  // 2 files cannot resolve 0.5 %
  // Uploads are the report's (no render here): 7 vs 32 and 10 vs 32 floats, 30 vs 48 bytes; the
  // report has no skinned_tube, so the joint row says so instead of rendering it.
  EXPECT_EQ(byId["floats_per_transform"]["measuredValue"]["motor"], 7.0) << byId["floats_per_transform"];
  EXPECT_EQ(byId["floats_per_transform_with_scale"]["measuredValue"]["motor"], 10.0);
  EXPECT_EQ(byId["bytes_per_vertex_vs_strongest"]["measuredValue"]["values"]["motor"], 30.0);
  EXPECT_EQ(byId["floats_per_joint"]["verdict"], "not measurable here");
  EXPECT_NE(byId["floats_per_joint"]["verdictText"].get<std::string>().find("has no scene skinned_tube"), std::string::npos)
      << byId["floats_per_joint"]["verdictText"];
  EXPECT_NE(byId["uniform_scale_overhead"]["measured"].get<std::string>().find("7 + 3 float(s) per draw"), std::string::npos)
      << byId["uniform_scale_overhead"]["measured"];
  // Attribution: the 9th float is our design, a baseline, not the paper's claim.
  EXPECT_EQ(byId["floats_per_transform_with_scale"]["verdict"], "baseline");
  EXPECT_EQ(byId["floats_per_transform_with_scale"]["origin"], "own: our design");
  // The tally: the paper's claims apart from our own rows; the headline gives both and the CPU.
  for (const char* v : {"reproduced", "differs", "inconclusive", "not measurable here", "baseline"})
    EXPECT_EQ(j["paperCounts"][v].get<int>() + j["ownCounts"][v].get<int>(), j["counts"][v].get<int>()) << v;
  EXPECT_EQ(j["paperCounts"]["baseline"], 0);
  EXPECT_EQ(byId["curved_floats_per_instance"]["origin"], "own: curved");
  EXPECT_EQ(byId["ops_clip_vs_strongest"]["origin"], "own: vs strongest");
  EXPECT_EQ(byId["gp_mm"]["origin"], "paper");
  const std::string md = readText(dir / "claims.md");
  EXPECT_NE(md.find("The paper's claims (each row quotes the sentence or table row it tests"), std::string::npos);
  EXPECT_NE(md.find("Our own rows"), std::string::npos);
  EXPECT_NE(md.find("hold for the CPU they were measured on: Test CPU Model 9000 (3 logical cores"), std::string::npos);
  fs::remove_all(dir);
}

TEST(ClaimsReport, HelpSaysWhatNoRunSkips) {
  std::string out;
  ASSERT_EQ(runCommand(motorbench() + "claims --help", &out), 0) << out;
  EXPECT_NE(out.find("--no-run           run no benchmark and time no frame (no curved-space"), std::string::npos) << out;
  EXPECT_NE(out.find("with it claims opens no GL context, renders and times nothing"), std::string::npos) << out;
  EXPECT_NE(out.find("--scene-graphs"), std::string::npos) << out;
}

}  // namespace
