// `motorbench morph`: its figures recomputed here from its own per-frame rows and upload
// counts, bytes against the hand-derived vertex formats, the default method, bad input; and
// `morph DOC.json ...`, scenes measured before (a committed input measured where a corpus was
// present) taken as they are, in the order given, with the figures computed over them again,
// checked on hand-made documents against hand-derived worst frames (no GL context opened).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include "tests/support/cli_test_support.h"

namespace fs = std::filesystem;
using namespace mb::cli_test;
using nlohmann::json;

namespace {

double figureValue(const json& doc, const std::string& name) {
  const json& f = doc["figures"][name];
  return f["value"].is_null() ? std::nan("") : f["value"].get<double>();
}

// One unskinned scene with one frame per (morph draws, frame psnr, rotor psnr, frame error).
json scene(const std::string& name, const std::vector<std::tuple<int, json, json, double>>& frames) {
  json s = {{"scene", name}, {"skinned", false}, {"frames", json::array()}};
  for (const auto& [draws, framePsnr, rotorPsnr, error] : frames)
    s["frames"].push_back({{"anim", 0}, {"time", 0.5}, {"morphDraws", draws},
                           {"methods", {{"motor_frame", {{"psnr", framePsnr}, {"maxError", error}}},
                                        {"motor_rotor", {{"psnr", rotorPsnr}, {"maxError", 2 * error}}}}}});
  return s;
}

void write(const fs::path& p, const json& scenes) {
  std::ofstream(p) << json{{"schema", "motorbench-morph/1"}, {"size", 64}, {"gl", {{"renderer", "hand-made"}}},
                           {"scenes", scenes}}.dump();
}

double value(const json& doc, const std::string& figure) { return doc["figures"][figure]["value"].get<double>(); }

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
  // The frame method (the rotor re-formed from the morphed frame) stays at or above 50 dB on rigid morph frames.
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

TEST(CliMorphMeasuredBefore, ScenesKeptInOrderAndFiguresOverAllOfThem) {
  const fs::path dir = scratchDir("morph_before");
  // a: 60 dB / 40 dB where a draw morphs, a frame without morph draws that must not count;
  // b failed to load; c: 55 dB, rotor identical; a again in the second document (not counted).
  write(dir / "one.json", json::array({scene("a.glb", {{1, 60.0, 40.0, 0.1}, {0, 10.0, 10.0, 0.9}}),
                                       {{"scene", "b.glb"}, {"error", "cannot load"}}}));
  write(dir / "two.json", json::array({scene("c.glb", {{2, 55.0, nullptr, 0.2}}), scene("a.glb", {{1, 1.0, 1.0, 0.5}})}));
  std::string out;
  // Exit 1: b.glb is a failed scene, recorded with its reason.
  ASSERT_EQ(runCommand(motorbench() + "morph " + quoted(dir / "one.json") + " " + quoted(dir / "two.json") +
                           " --size 64 --json " + quoted(dir / "m.json"), &out), 1) << out;
  EXPECT_NE(out.find("b.glb: not measured: cannot load"), std::string::npos) << out;
  EXPECT_NE(out.find("on 3 scene(s)"), std::string::npos) << out;
  const json doc = readJson(dir / "m.json");
  ASSERT_FALSE(doc.is_discarded()) << out;
  ASSERT_EQ(doc["scenes"].size(), 3u);
  EXPECT_EQ(doc["scenes"][0]["scene"], "a.glb");
  EXPECT_EQ(doc["scenes"][1]["scene"], "b.glb");
  EXPECT_EQ(doc["scenes"][2]["scene"], "c.glb");
  EXPECT_EQ(doc["gl"]["renderer"], "hand-made");  // nothing drawn now: the documents' GL
  EXPECT_DOUBLE_EQ(value(doc, "morph.worst_psnr.rigid.motor_frame"), 55.0);  // min(60, 55)
  EXPECT_EQ(doc["figures"]["morph.worst_psnr.rigid.motor_frame"]["n"], 2);
  EXPECT_EQ(doc["worst"]["morph.worst_psnr.rigid.motor_frame"]["scene"], "c.glb");
  EXPECT_DOUBLE_EQ(value(doc, "morph.max_error.rigid.motor_frame"), 0.2);   // max(0.1, 0.2)
  EXPECT_DOUBLE_EQ(value(doc, "morph.worst_psnr.rigid.motor_rotor"), 40.0);  // min(40, identical)
  EXPECT_EQ(doc["worst"]["morph.worst_psnr.rigid.motor_rotor"]["scene"], "a.glb");
  EXPECT_DOUBLE_EQ(value(doc, "morph.max_error.rigid.motor_rotor"), 0.4);
  fs::remove_all(dir);
}

TEST(CliMorphMeasuredBefore, AnotherFrameSizeOrNotAMorphDocumentIsRefused) {
  const fs::path dir = scratchDir("morph_before_bad");
  write(dir / "one.json", json::array({scene("a.glb", {{1, 60.0, 40.0, 0.1}})}));
  std::ofstream(dir / "other.json") << R"({"schema": "motorbench-isa/1"})";
  std::string out;
  EXPECT_EQ(runCommand(motorbench() + "morph " + quoted(dir / "one.json"), &out), 2);  // default 128 px
  EXPECT_NE(out.find("measured at 64 x 64 px, this run at 128: give --size 64"), std::string::npos) << out;
  out.clear();
  EXPECT_EQ(runCommand(motorbench() + "morph " + quoted(dir / "other.json"), &out), 2);
  EXPECT_NE(out.find("not a motorbench-morph/1 JSON"), std::string::npos) << out;
  fs::remove_all(dir);
}
