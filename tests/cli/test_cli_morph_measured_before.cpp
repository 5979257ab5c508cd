// `motorbench morph DOC.json ...`: scenes measured before (a committed input measured where a
// corpus was present) are taken as they are, in the order given, and the figures are computed
// over them again; checked on hand-made documents against hand-derived worst frames. Nothing
// is measured here, so no GL context is opened.
#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/cli_test_support.h"

namespace fs = std::filesystem;
using namespace mb::cli_test;
using nlohmann::json;

namespace {

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
