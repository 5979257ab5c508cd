// What `motorbench report` shows beyond one animation of Euclidean built-ins: an animated scene
// gets one looping GIF per compared pipeline (24 frames of [baseline | pipeline | diff] over one
// loop of its first animation), a scene without animation none; --anim chooses animations
// (several, by name or index, per scene), an unknown one stops the run naming the scene's
// animations; curved scenes are measured with their own space's pipelines into a "curved space"
// section; statistics keep built-in scenes apart from files. Asserts structure and hand-derived
// values, never a timing.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>

#include "harness/report/report_sources.h"
#include "pipelines/pipeline.h"
#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using mb::cli_test::motorbench;
using mb::cli_test::quoted;
using mb::cli_test::readJson;
using mb::cli_test::readText;
using mb::cli_test::runCommand;
using mb::cli_test::scratchDir;

const char* const kSmall = " --no-bench --no-isa --no-plots --frames 0 --size 48x32 --pipelines matrix,motor";

TEST(AnimatedComparison, ReportHasOneLoopPerAnimatedScene) {
  const fs::path dir = scratchDir("animated");
  std::string out;
  ASSERT_EQ(runCommand(motorbench() + "report skinned_tube textured_box --frames 0 --no-bench --no-isa --no-plots --size 64x48 -o " +
                           quoted(dir), &out), 0) << out;
  const nlohmann::json r = readJson(dir / "report.json");
  ASSERT_FALSE(r.is_discarded());
  const nlohmann::json& tube = r["scenes"][0];
  ASSERT_EQ(tube["id"], "skinned_tube");
  const nlohmann::json& a = tube["animated"]["motor"];
  ASSERT_TRUE(a.contains("file")) << a.dump();
  EXPECT_EQ(a["frames"], 24);
  EXPECT_GT(a["maxPixelsOver2"].get<double>(), 0.0);  // LBS and motor skinning part on the bend
  EXPECT_TRUE(r["scenes"][1]["animated"].is_null());  // textured_box has no animation

  auto in = OIIO::ImageInput::open((dir / a["file"].get<std::string>()).string());
  ASSERT_TRUE(in) << OIIO::geterror();
  EXPECT_EQ(in->spec().width, 3 * 64);
  EXPECT_EQ(in->spec().height, 48);
  int subimages = 0;
  while (in->seek_subimage(subimages, 0)) ++subimages;
  EXPECT_EQ(subimages, 24);
  in->close();
  EXPECT_NE(readText(dir / "report.md").find(a["file"].get<std::string>()), std::string::npos);
  fs::remove_all(dir);
}

TEST(CliReportAnim, SeveralAnimationsByNameAndIndexCommaOrRepeated) {
  const fs::path dir = mb::cli_test::scratchDir("report_anim");
  std::string log;
  // skinned_tube: 0 bend, 1 twist, 2 candy_wrapper (pipelines/scene/builtin/builtin_tube.cpp).
  ASSERT_EQ(runCommand(motorbench() + "report skinned_tube --anim candy_wrapper,0 --anim skinned_tube:candy_wrapper" +
                           kSmall + " -o " + quoted(dir), &log), 0) << log;
  const json r = readJson(dir / "report.json");
  ASSERT_FALSE(r.is_discarded()) << log;
  const json& tube = r["scenes"][0];
  ASSERT_EQ(tube["animations"].size(), 2u) << tube["animations"].dump();  // the repeat is shown once
  EXPECT_EQ(tube["animations"][0]["name"], "candy_wrapper");
  EXPECT_EQ(tube["animations"][0]["index"], 2);
  EXPECT_EQ(tube["animations"][1]["name"], "bend");
  EXPECT_EQ(tube["animation"]["name"], "candy_wrapper");
  ASSERT_EQ(tube["frames"].size(), 6u);  // three times of each
  for (size_t k = 0; k < 6; ++k) EXPECT_EQ(tube["frames"][k]["animation"], k < 3 ? 2 : 0) << k;
  // One loop per animation, each its own file.
  const json& candy = tube["animations"][0]["animated"]["motor"];
  const json& bend = tube["animations"][1]["animated"]["motor"];
  ASSERT_TRUE(candy.contains("file") && bend.contains("file")) << tube["animations"].dump();
  EXPECT_NE(candy["file"], bend["file"]);
  EXPECT_TRUE(fs::is_regular_file(dir / candy["file"].get<std::string>()));
  EXPECT_TRUE(fs::is_regular_file(dir / bend["file"].get<std::string>()));
  EXPECT_EQ(tube["animated"], tube["animations"][0]["animated"]);
  // LBS (matrix) against motor blending: every skinned frame judged against motor's own method's
  // reference, none set aside; the methods' difference from matrix measured apart and labelled.
  EXPECT_EQ(tube["pipelines"]["matrix"]["skinBlend"], "linear blend skinning");
  EXPECT_EQ(tube["pipelines"]["motor"]["skinBlend"], "motor blending");
  EXPECT_EQ(r["summary"]["skinningMethodImages"]["motor"]["comparedFrames"], 6);
  const json& images = r["summary"]["images"]["motor"];
  EXPECT_EQ(images["comparedFrames"], 6);
  EXPECT_EQ(images["judgedAgainst"], json({{"motor-blend reference", 6}}));
  EXPECT_EQ(images["notJudgedFrames"], 0);
  for (const json& f : tube["frames"]) {
    EXPECT_EQ(f["skinJudgement"]["motor"]["reference"], "motor-blend reference");
    EXPECT_EQ(f["skinJudgement"]["motor"]["judged"], true);
    EXPECT_EQ(f["skinJudgement"]["motor"]["vsMatrix"]["drawnPixels"], f["drawnPixels"]["motor"]);
    EXPECT_EQ(f["skinJudgement"]["motor"]["vsMatrix"]["referenceDrawnPixels"], f["drawnPixels"]["matrix"]);
    EXPECT_TRUE(f["referenceMetrics"]["motor"].is_object()) << f.dump(1).substr(0, 1000);
    EXPECT_EQ(f["drawnCheck"]["motor"]["against"], "motor-blend reference");
  }
  // The answer's image row: its figures count the skinned frames, with their reference.
  EXPECT_EQ(r["figures"]["image.identical_frames.motor"]["n"], 6);
  EXPECT_EQ(r["figures"]["image.skinned_frames_own_reference.motor"]["value"], 6);
  EXPECT_EQ(r["figures"]["image.frames_not_judged.motor"]["value"], 0);
  const std::string md = readText(dir / "report.md");
  EXPECT_NE(md.find("frames identical (of them <span title=\"image.skinned_frames_own_reference.motor\">6 frames</span> "
                    "skinned, against the motor-blend reference: motor's own skinning method, not matrix's)"), std::string::npos) << md.substr(0, 3000);
  EXPECT_NE(md.find("candy_wrapper, t = 0.667 s"), std::string::npos);
  EXPECT_NE(md.find("the methods' expected difference"), std::string::npos);
  EXPECT_NE(md.find("| motor (skinning method difference) | "), std::string::npos);
  EXPECT_NE(md.find("| motor vs motor-blend reference (its own skinning method's) | "), std::string::npos);
  EXPECT_NE(md.find("(6 skinned against the motor-blend reference)"), std::string::npos);
  fs::remove_all(dir);
}

TEST(CliReportAnim, UnknownAnimationListsTheScenesAnimations) {
  const fs::path dir = mb::cli_test::scratchDir("report_anim_bad");
  const std::string list = "0 'bend', 1 'twist', 2 'candy_wrapper'";
  std::string log;
  EXPECT_EQ(runCommand(motorbench() + "report skinned_tube --anim candy,bend" + kSmall + " -o " + quoted(dir), &log), 2);
  EXPECT_NE(log.find("--anim candy: no scene of this run has that animation (skinned_tube: " + list + ")"),
            std::string::npos) << log;
  log.clear();
  EXPECT_EQ(runCommand(motorbench() + "report skinned_tube textured_box --anim skinned_tube:7" + kSmall + " -o " +
                           quoted(dir), &log), 2);
  EXPECT_NE(log.find("--anim skinned_tube:7: skinned_tube has no animation '7' (its animations: " + list + ")"),
            std::string::npos) << log;
  log.clear();
  EXPECT_EQ(runCommand(motorbench() + "report skinned_tube --anim crowd:0" + kSmall + " -o " + quoted(dir), &log), 2);
  EXPECT_NE(log.find("no scene 'crowd' in this run (scenes: skinned_tube)"), std::string::npos) << log;
  log.clear();
  EXPECT_EQ(runCommand(motorbench() + "report skinned_tube --anim bend,,twist" + kSmall + " -o " + quoted(dir), &log), 2);
  EXPECT_NE(log.find("an empty item"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir / "report.json"));  // checked before anything is measured
  fs::remove_all(dir);
}

TEST(CliReportCurved, CurvedScenesGetTheirSpacesPipelinesAndASection) {
  const fs::path dir = mb::cli_test::scratchDir("report_curved");
  std::string log;
  ASSERT_EQ(runCommand(motorbench() + "report textured_box s3_tiling h3_tiling --no-bench --no-isa --no-plots --frames 2 "
                           "--size 48x32 --time-size 64x64 -o " + quoted(dir), &log), 0) << log;
  const json r = readJson(dir / "report.json");
  ASSERT_FALSE(r.is_discarded()) << log;
  EXPECT_EQ(r["summary"]["ok"], 3) << log;
  for (size_t k = 1; k < 3; ++k) {
    const json& s = r["scenes"][k];
    const std::string prefix = k == 1 ? "s3_" : "h3_";
    EXPECT_EQ(s["pipelineOrder"], json({prefix + "matrix", prefix + "motor"}));
    EXPECT_EQ(s["space"], k == 1 ? "spherical (S3)" : "hyperbolic (H3)");
    // Floats per instance as uploaded: an O(4) / O(3,1) mat4 against an 8-float motor.
    EXPECT_EQ(s["pipelines"][prefix + "matrix"]["memory"]["floatsPerTransform"], 16.0);
    EXPECT_EQ(s["pipelines"][prefix + "motor"]["memory"]["floatsPerTransform"], 8.0);
    for (const json& f : s["frames"]) {
      const json& m = f["metrics"][prefix + "motor"];
      ASSERT_TRUE(m.is_object()) << f.dump();
      if (!m["identical"].get<bool>()) EXPECT_GE(m["psnr"].get<double>(), 50.0);
    }
    // Ops of the scene's own space only (the curved matrix transform's 64 mul, 48 add per vertex counted).
    ASSERT_EQ(s["opsPerVertex"].size(), 2u) << s["opsPerVertex"].dump();
    EXPECT_EQ(s["opsPerVertex"][prefix + "matrix"]["counted"]["mul"], 64.0);
    EXPECT_TRUE(s["timing"]["paired_ratio_motor_matrix"].is_number()) << s["timing"].dump();
  }
  ASSERT_EQ(r["summary"]["curved"].size(), 2u);
  EXPECT_EQ(r["summary"]["curved"][0]["floatsPerInstance"]["s3_motor"], 8.0);
  EXPECT_EQ(r["summary"]["frameTimeRatio"]["n"], 1);  // the Euclidean scene only
  ASSERT_EQ(r["curved"]["drift"]["spaces"].size(), 2u);
  for (const json& sp : r["curved"]["drift"]["spaces"]) EXPECT_LT(sp["motor"]["renormalised"].get<double>(), 1e-5);
  const std::string md = readText(dir / "report.md");
  EXPECT_NE(md.find("## Curved space"), std::string::npos);
  EXPECT_NE(md.find("| [s3_tiling](#scene-s3_tiling) | spherical (S3) | s3_matrix | 16 |"), std::string::npos);
  EXPECT_NE(md.find("Camera drift after 1000000"), std::string::npos);
  fs::remove_all(dir);
}

TEST(CliReportSources, StatisticsKeepBuiltInScenesApartFromFiles) {
  const fs::path dir = mb::cli_test::scratchDir("report_sources");
  std::string log;
  // A real file: textured_box written out as .glb (normal-mapped, not skinned); the built-in
  // skinned_tube by name (skinned, normal-mapped).
  ASSERT_EQ(runCommand(motorbench() + "scenes textured_box -o " + quoted(dir / "files"), &log), 0) << log;
  ASSERT_EQ(runCommand(motorbench() + "report " + quoted(dir / "files") + " skinned_tube" + kSmall + " -o " +
                           quoted(dir / "out"), &log), 0) << log;
  const json r = readJson(dir / "out" / "report.json");
  ASSERT_FALSE(r.is_discarded()) << log;
  EXPECT_EQ(r["scenes"][0]["origin"], "file");
  EXPECT_EQ(r["scenes"][1]["origin"], "built-in");
  EXPECT_EQ(r["summary"]["origins"], json({{"built-in", 1}, {"file", 1}}));
  const json& b = r["summary"]["statistics"]["builtIn"];
  const json& f = r["summary"]["statistics"]["files"];
  EXPECT_EQ(b["loaded"], 1);
  EXPECT_EQ(f["loaded"], 1);
  EXPECT_EQ(b["filesSkinned"], 1);
  EXPECT_EQ(f["filesSkinned"], 0);
  EXPECT_EQ(f["filesNormalMapped"], 1);
  EXPECT_EQ(f["vertices"], 24);  // the box: 6 faces x 4 corners
  EXPECT_NE(readText(dir / "out" / "report.md").find("Scene statistics by origin"), std::string::npos);
  fs::remove_all(dir);
}

TEST(ReportSources, EveryGltfPipelineNamesHowItBlendsJoints) {
  // From the vertex shaders: matrix.vs and affine.vs (affine, qtangent, hybrid) blend a matrix
  // palette, motor.vs (motor, motor_q) joint motors. A new glTF pipeline must be entered.
  for (const std::string& p : mb::pipelineNames()) EXPECT_FALSE(mb::report::skinBlendOf(p).empty()) << p;
  for (const char* p : {"matrix", "affine", "qtangent", "hybrid"})
    EXPECT_EQ(mb::report::skinBlendOf(p), "linear blend skinning") << p;
  for (const char* p : {"motor", "motor_q"}) EXPECT_EQ(mb::report::skinBlendOf(p), "motor blending") << p;
  for (const std::string& p : mb::pipelineNames(mb::Space::Spherical)) EXPECT_EQ(mb::report::skinBlendOf(p), "") << p;
  EXPECT_EQ(mb::report::sceneOrigin("skinned_tube"), "built-in");
  EXPECT_EQ(mb::report::sceneOrigin("s3_tiling"), "built-in");
  EXPECT_EQ(mb::report::sceneOrigin("/some/where/barrel.glb"), "file");
}

}  // namespace
