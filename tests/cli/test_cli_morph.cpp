// `motorbench morph`: its figures recomputed here from its own per-frame rows and
// upload counts, bytes against the hand-derived vertex formats, the default method, bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tests/support/cli_test_support.h"

namespace fs = std::filesystem;
using namespace mb::cli_test;
using nlohmann::json;

namespace {

double figureValue(const json& doc, const std::string& name) {
  const json& f = doc["figures"][name];
  return f["value"].is_null() ? std::nan("") : f["value"].get<double>();
}

}  // namespace

TEST(CliMorph, FiguresAreTheFramesWorstAndTheUploadsBytes) {
  const fs::path dir = scratchDir("morph");
  std::string out;
  ASSERT_EQ(runCommand(motorbench() + "morph morph_torus --size 96 --json " + quoted(dir / "m.json"), &out), 0) << out;
  const json doc = readJson(dir / "m.json");
  ASSERT_FALSE(doc.is_discarded()) << out;
  EXPECT_EQ(doc["schema"], "motorbench-morph/1");
  ASSERT_EQ(doc["scenes"].size(), 1u);
  const json& scene = doc["scenes"][0];
  EXPECT_EQ(scene["targets"], 2);         // morph_torus: two targets...
  EXPECT_EQ(scene["weightChannels"], 1);  // ...and one animated weights channel
  int morphing = 0;
  for (const char* id : {"motor_frame", "motor_rotor"}) {
    double worst = std::numeric_limits<double>::infinity(), maxError = 0;
    int n = 0;
    for (const json& f : scene["frames"]) {
      if (f["morphDraws"].get<int>() == 0) continue;
      ++n;
      const json& m = f["methods"][id];
      worst = std::min(worst, m["psnr"].is_null() ? std::numeric_limits<double>::infinity() : m["psnr"].get<double>());
      maxError = std::max(maxError, m["maxError"].get<double>());
    }
    morphing = n;
    EXPECT_DOUBLE_EQ(figureValue(doc, std::string("morph.worst_psnr.rigid.") + id), worst) << id;
    EXPECT_DOUBLE_EQ(figureValue(doc, std::string("morph.max_error.rigid.") + id), maxError) << id;
    EXPECT_EQ(doc["figures"][std::string("morph.worst_psnr.rigid.") + id]["n"], n) << id;
  }
  EXPECT_EQ(morphing, 3);  // the animation at 1/4, 1/2 and 3/4: the rest weights are 0
  // The frame method is exact where matrix is: at least 50 dB on rigid morph frames.
  EXPECT_GE(figureValue(doc, "morph.worst_psnr.rigid.motor_frame"), 50.0);
  // No skinned scene here: the figures say so instead of a number.
  EXPECT_TRUE(doc["figures"]["morph.worst_psnr.skinned.motor_frame"]["value"].is_null());
  // Bytes: the uploads' ratios, and the formats by hand: matrix position 3 + normal 3 + tangent
  // 4 + uv 2 floats, motor position 3 + rotor 4 + uv 2; per target vertex 3 + 3 + 3 floats of
  // glTF deltas (matrix, frame method) or position 3 + rotor 4 (rotor method).
  const std::pair<const char*, std::pair<double, double>> formats[] = {
      {"matrix", {48, 36}}, {"motor_frame", {36, 36}}, {"motor_rotor", {36, 28}}};
  for (const auto& [id, bytes] : formats) {
    const json& b = scene["bytes"][id];
    EXPECT_DOUBLE_EQ(figureValue(doc, std::string("morph.bytes_per_vertex.") + id),
                     b["vertexBytes"].get<double>() / b["vertices"].get<double>()) << id;
    EXPECT_DOUBLE_EQ(figureValue(doc, std::string("morph.bytes_per_target_vertex.") + id),
                     b["morphBytes"].get<double>() / b["morphTargetVertices"].get<double>()) << id;
    EXPECT_DOUBLE_EQ(figureValue(doc, std::string("morph.bytes_per_vertex.") + id), bytes.first) << id;
    EXPECT_DOUBLE_EQ(figureValue(doc, std::string("morph.bytes_per_target_vertex.") + id), bytes.second) << id;
  }
  // The default upload matches the frame method's bytes, not the rotor method's.
  EXPECT_EQ(doc["motorDefault"], "motor_frame");
  fs::remove_all(dir);
}

TEST(CliMorph, BadInputIsNamed) {
  const fs::path dir = scratchDir("morph_bad");
  std::string out;
  EXPECT_EQ(runCommand(motorbench() + "morph " + quoted(dir), &out), 2);
  EXPECT_NE(out.find("MANIFEST.tsv"), std::string::npos) << out;
  out.clear();
  // A scene that does not load is recorded with its reason and the run goes on (exit 1).
  EXPECT_EQ(runCommand(motorbench() + "morph " + quoted(dir / "missing.glb") + " --json " + quoted(dir / "m.json"), &out),
            1);
  EXPECT_NE(out.find("not measured"), std::string::npos) << out;
  const json doc = readJson(dir / "m.json");
  ASSERT_FALSE(doc.is_discarded());
  EXPECT_TRUE(doc["scenes"][0].contains("error"));
  fs::remove_all(dir);
}
