// `motorbench check` end to end: the committed goldens pass; a deliberate shader change (tangent
// handedness flipped in a temporary copy of shaders/) fails with a report; a one-step change only
// warns; a missing golden is an error naming the file, a wrong --golden folder is named with what
// a golden folder holds, and outside a checkout check asks for --golden DIR (never advising
// --update); --update writes goldens that then pass and keeps hand-tuned thresholds.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "harness/render/image_metrics.h"
#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;

const fs::path kGolden = fs::path(MB_SOURCE_DIR) / "tests" / "golden";

using mb::cli_test::contains;
using mb::cli_test::quoted;
using mb::cli_test::readText;
using mb::cli_test::runMb;
using mb::cli_test::runCommand;
std::string q(const fs::path& p) { return mb::cli_test::quoted(p); }
int run(const std::string& cmd, std::string* output) { return runCommand(cmd, output); }
std::string check(const std::string& options) { return mb::cli_test::motorbench() + "check " + options; }
fs::path scratch(const std::string& name) { return mb::cli_test::scratchDir("check_" + name); }

// Copies the committed goldens so a test can damage them.
fs::path copyGoldens(const fs::path& root) {
  fs::copy(kGolden, root / "golden", fs::copy_options::recursive);
  return root / "golden";
}

TEST(CliCheck, CommittedGoldensPass) {
  fs::path root = scratch("pass");
  std::string out;
  int rc = run(check("--golden " + q(kGolden) + " --out " + q(root / "out")), &out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find(" 0 failed, 0 errors"), std::string::npos) << out;
  EXPECT_TRUE(fs::exists(root / "out" / "summary.html"));
  EXPECT_TRUE(fs::exists(root / "out" / "check.json"));
  fs::remove_all(root);
}

// A copy of shaders/ whose shared fragment shader builds the bitangent as
// -handedness * cross(n, t), on both of its paths (frame_shading.glsl: the TBN path and
// motor_cf's rotor path): the deliberate regression of the acceptance criterion.
fs::path flippedHandednessShaders(const fs::path& root) {
  fs::copy(fs::path(MB_SOURCE_DIR) / "shaders", root / "shaders", fs::copy_options::recursive);
  const fs::path fsPath = root / "shaders" / "frame_shading.glsl";
  std::string text = readText(fsPath);
  for (const std::string from : {"* cross(n, t)", "cross(nt[0], nt[1]) *"}) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << fsPath << " no longer contains '" << from << "'; update this test";
    if (at != std::string::npos) text.replace(at, from.size(), from[0] == '*' ? "* -cross(n, t)" : "-cross(nt[0], nt[1]) *");
  }
  std::ofstream(fsPath) << text;
  return root / "shaders";
}

TEST(CliCheck, FlippedTangentHandednessFailsWithReport) {
  fs::path root = scratch("handedness");
  fs::path shaders = flippedHandednessShaders(root);
  std::string out;
  int rc = run(check("--golden " + q(kGolden) + " --scenes normal_torus,skinned_tube --shader-dir " +
                     q(shaders) + " --out " + q(root / "out")), &out);
  EXPECT_EQ(rc, 1) << out;
  EXPECT_NE(out.find("FAIL  normal_torus.rest.matrix.png"), std::string::npos) << out;
  EXPECT_NE(out.find("FAIL  normal_torus.rest.motor.png"), std::string::npos) << out;
  EXPECT_NE(out.find("FAIL  normal_torus.rest.motor_cf.png"), std::string::npos) << out;
  EXPECT_NE(out.find("report: "), std::string::npos) << out;
  const std::string html = readText(root / "out" / "summary.html");
  EXPECT_NE(html.find("normal_torus.rest.matrix.diff.png"), std::string::npos);
  for (const char* f : {"expected", "actual", "diff"})
    EXPECT_TRUE(fs::exists(root / "out" / (std::string("normal_torus.rest.matrix.") + f + ".png"))) << f;
  fs::remove_all(root);
}

// Goldens recorded on another GL: the portable thresholds apply, with a warning naming both;
// the same images still pass, and the flipped handedness still fails.
TEST(CliCheck, OtherRendererUsesPortableThresholdsAndWarns) {
  fs::path root = scratch("portable");
  fs::path golden = copyGoldens(root);
  auto manifest = nlohmann::json::parse(readText(golden / "golden.json"));
  for (auto& e : manifest["images"]) e["gl"]["version"] = "4.5 (Core Profile) Mesa 0.0-elsewhere";
  std::ofstream(golden / "golden.json") << manifest.dump(2);
  std::string out;
  int rc = run(check("--golden " + q(golden) + " --scenes normal_torus --out " + q(root / "out")), &out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("[portable]"), std::string::npos) << out;
  EXPECT_NE(out.find("warning: GL differs from the goldens' (recorded"), std::string::npos) << out;
  EXPECT_NE(out.find("Mesa 0.0-elsewhere"), std::string::npos) << out;
  out.clear();
  rc = run(check("--golden " + q(golden) + " --scenes normal_torus --shader-dir " +
                 q(flippedHandednessShaders(root)) + " --out " + q(root / "out2")), &out);
  EXPECT_EQ(rc, 1) << out;
  fs::remove_all(root);
}

// One channel of one pixel moved by `steps` 8-bit steps in a copied golden.
int checkWithNudgedPixel(const fs::path& root, int steps, std::string* out) {
  fs::path golden = copyGoldens(root);
  const fs::path png = golden / "textured_box.rest.matrix.png";
  auto img = mb::readImage(png.string());
  EXPECT_TRUE(img) << img.error();
  if (!img) return -1;
  uint8_t& g = img->rgba[(size_t(img->height / 2) * size_t(img->width) + size_t(img->width / 2)) * 4 + 1];
  g = uint8_t(g >= 128 ? g - steps : g + steps);
  EXPECT_TRUE(mb::writeImage(png.string(), *img));
  return run(check("--golden " + q(golden) + " --scenes textured_box --pipelines matrix --out " +
                   q(root / "out")), out);
}

TEST(CliCheck, OneStepChangeWarnsButPasses) {
  fs::path root = scratch("warn");
  std::string out;
  EXPECT_EQ(checkWithNudgedPixel(root, 1, &out), 0) << out;
  EXPECT_NE(out.find("WARN  textured_box.rest.matrix.png"), std::string::npos) << out;
  EXPECT_NE(out.find("1 warned, 0 failed"), std::string::npos) << out;
  fs::remove_all(root);
}

TEST(CliCheck, LargerChangeOfOnePixelFails) {
  fs::path root = scratch("onepixel");
  std::string out;
  EXPECT_EQ(checkWithNudgedPixel(root, 3, &out), 1) << out;
  EXPECT_NE(out.find("FAIL  textured_box.rest.matrix.png"), std::string::npos) << out;
  fs::remove_all(root);
}

TEST(CliCheck, MissingGoldenIsAnErrorNamingTheFile) {
  fs::path root = scratch("missing");
  fs::path golden = copyGoldens(root);
  fs::remove(golden / "normal_torus.rest.motor.png");
  std::string out;
  int rc = run(check("--golden " + q(golden) + " --scenes normal_torus --out " + q(root / "out")), &out);
  EXPECT_EQ(rc, 2) << out;
  EXPECT_NE(out.find("normal_torus.rest.motor.png: missing golden"), std::string::npos) << out;

  out.clear();
  rc = run(check("--golden " + q(root / "nowhere") + " --out " + q(root / "out")), &out);
  EXPECT_EQ(rc, 2) << out;
  EXPECT_NE(out.find("golden.json"), std::string::npos) << out;
  fs::remove_all(root);
}

// A --golden folder without golden.json is named with what a golden folder holds, and check
// does not advise --update (it would write goldens there).
TEST(CliInputText, WrongGoldenFolderIsNamedWithoutAdvisingUpdate) {
  const fs::path dir = mb::cli_test::scratchDir("input_golden");
  const auto r = runMb("check --golden " + quoted(dir) + " --scenes normal_torus --out " + quoted(dir / "out"));
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "--golden " + dir.string() + ": not a golden folder (no golden.json there)")) << r.out;
  EXPECT_TRUE(contains(r.out, "one PNG per scene, pose and pipeline")) << r.out;
  EXPECT_FALSE(contains(r.out, "run check --update")) << r.out;
  EXPECT_FALSE(contains(r.out, "--update` creates it")) << r.out;
  EXPECT_FALSE(fs::exists(dir / "golden.json"));
  fs::remove_all(dir);
}

// Outside a checkout there are no default goldens: check (with or without --update) asks for
// --golden DIR and creates nothing, so goldens never land in the wrong place.
TEST(CliMessages, CheckOutsideACheckoutPointsToGolden) {
  const fs::path dir = mb::cli_test::scratchDir("messages_check");
  for (const char* args : {"check", "check --update"}) {
    std::string out;
    const int rc = mb::cli_test::runCommand("cd " + quoted(dir) + " && " + mb::cli_test::motorbench() + args, &out);
    EXPECT_EQ(rc, 2) << args << "\n" << out;
    EXPECT_TRUE(contains(out, "pass --golden DIR")) << out;
    EXPECT_FALSE(contains(out, "run check --update")) << out;
    EXPECT_FALSE(contains(out, "`motorbench check --update` creates it")) << out;
  }
  EXPECT_FALSE(fs::exists(dir / "tests")) << "check --update created goldens outside a checkout";
  fs::remove_all(dir);
}

TEST(CliCheck, BadOptionsAreErrors) {
  std::string out;
  EXPECT_EQ(run(check("--scenes no_such_scene"), &out), 2) << out;
  EXPECT_NE(out.find("no_such_scene"), std::string::npos) << out;
  out.clear();
  EXPECT_EQ(run(check("--pipelines no_such_pipeline"), &out), 2) << out;
  EXPECT_NE(out.find("no_such_pipeline"), std::string::npos) << out;
  out.clear();
  EXPECT_EQ(run(check("--shader-dir /no/such/folder"), &out), 2) << out;
}

TEST(CliCheck, UpdateWritesGoldensThatPassAndKeepsThresholds) {
  fs::path root = scratch("update");
  const fs::path golden = root / "golden";
  std::string out;
  ASSERT_EQ(run(check("--update --golden " + q(golden) + " --scenes scaled_hierarchy"), &out), 0) << out;
  auto manifest = nlohmann::json::parse(readText(golden / "golden.json"));
  ASSERT_TRUE(manifest["images"].is_array());
  EXPECT_GE(manifest["images"].size(), 2u * 3u);  // rest + two animation times, per pipeline
  for (const auto& e : manifest["images"]) {
    EXPECT_TRUE(fs::exists(golden / e["file"].get<std::string>())) << e["file"];
    EXPECT_FALSE(e["gl"]["renderer"].get<std::string>().empty());
  }
  // A hand-tuned threshold survives the next update.
  manifest["thresholds"]["scaled_hierarchy"]["portable"]["failpercent"] = 0.25;
  std::ofstream(golden / "golden.json") << manifest.dump(2);
  out.clear();
  ASSERT_EQ(run(check("--update --golden " + q(golden) + " --scenes scaled_hierarchy"), &out), 0) << out;
  EXPECT_NE(out.find("0 images changed"), std::string::npos) << out;  // deterministic re-render
  manifest = nlohmann::json::parse(readText(golden / "golden.json"));
  EXPECT_EQ(manifest["thresholds"]["scaled_hierarchy"]["portable"]["failpercent"].get<double>(), 0.25);

  out.clear();
  EXPECT_EQ(run(check("--golden " + q(golden) + " --scenes scaled_hierarchy --out " + q(root / "out")), &out), 0)
      << out;
  fs::remove_all(root);
}

}  // namespace
