// `motorbench accuracy`: the figures of the built-in scenes against hand-derived expectations
// (the quaternion conversion's sample count and bits, the candy wrapper's half turn collapsing
// linear blend skinning and not the motor, the closed form of a normalised blend of keys 90
// degrees apart, the handedness counts adding up), every figure described, and a skinned-files
// run over a folder without a skinned mesh or without a folder.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <glm/glm.hpp>

#include "pipelines/scene/builtin_scenes.h"
#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using mb::cli_test::contains;
using mb::cli_test::quoted;
using mb::cli_test::runMb;

double value(const json& doc, const std::string& name) {
  const json& f = doc["figures"][name];
  EXPECT_TRUE(f.is_object()) << "no figure " << name;
  return f.value("value", json()).is_number() ? f["value"].get<double>() : std::nan("");
}

}  // namespace

TEST(CliAccuracy, BuiltinFiguresAgainstHandDerivedValues) {
  const fs::path out = mb::cli_test::scratchDir("accuracy");
  const auto run = runMb("accuracy --drift-steps 1000 --json " + quoted(out / "accuracy.json"));
  ASSERT_EQ(run.rc, 0) << run.out;
  EXPECT_TRUE(contains(run.out, "accuracy: 5/5 measurements (curved camera drift)")) << run.out;  // progress
  const json doc = mb::cli_test::readJson(out / "accuracy.json");
  ASSERT_TRUE(doc.is_object()) << run.out;
  EXPECT_EQ(doc["schema"], "motorbench-accuracy/1");
  for (const auto& [name, f] : doc["figures"].items()) {
    for (const char* key : {"statistic", "scope", "definition", "device"})
      EXPECT_FALSE(f.value(key, "").empty()) << name << " has no " << key;
    EXPECT_TRUE(f["value"].is_number()) << name;
    EXPECT_TRUE(contains(run.out, "  " + name + " ")) << name << " not printed";
  }
  // 16 axis-aligned and signed-zero quaternions and 100000 random ones, every one bit-exact.
  EXPECT_EQ(value(doc, "conversion.quat_to_rotor.samples"), 100016);
  EXPECT_EQ(value(doc, "conversion.quat_to_rotor.mismatches"), 0);
  // Half a turn of the middle joint: a ring weighted half to each side is, blended linearly, the
  // mean of p and p turned 180 degrees, its centroid; a rotor halfway keeps its radius.
  EXPECT_LT(value(doc, "skin.ring_radius.candy_wrapper.lbs.min"), 0.1);
  EXPECT_NEAR(value(doc, "skin.ring_radius.candy_wrapper.motor.min"), 1.0, 0.01);
  // Keys 90 degrees apart (candy_wrapper, teapot's lid...): the normalised blend's half-angle
  // atan2(t sin 45, 1 - t + t cos 45) against slerp's t 45 degrees, the largest over t = k/32.
  double want = 0;
  for (int k = 1; k < 32; ++k) {
    const double t = k / 32.0, A = glm::radians(90.0);
    want = std::max(want, glm::degrees(2 * std::fabs(std::atan2(t * std::sin(A / 2), 1 - t + t * std::cos(A / 2)) - t * A / 2)));
  }
  EXPECT_NEAR(value(doc, "blend.max_angle_error_deg"), want, 2e-3);
  // The handedness figures are the sums of the per-scene counts; a frame is wrong only where the
  // float64 scalar is exactly zero.
  int frames = 0, wrong = 0;
  for (const auto& [scene, c] : doc["details"]["handedness"].items())
    frames += c["frames"].get<int>(), wrong += c["wrong"].get<int>();
  EXPECT_EQ(value(doc, "handedness.frames"), frames);
  EXPECT_EQ(value(doc, "handedness.frames_wrong"), wrong);
  EXPECT_GT(wrong, 0);
  EXPECT_LE(value(doc, "handedness.frames_wrong"), value(doc, "handedness.frames_zero_scalar"));
  // Renormalised after every step, both sides stay on the group.
  for (const char* s : {"s3", "h3"})
    for (const char* side : {"matrix", "motor"}) {
      const std::string p = std::string("drift.") + s + "." + side + ".";
      EXPECT_LT(value(doc, p + "renormalised"), 1e-5) << p;
      EXPECT_TRUE(contains(doc["figures"][p + "raw"]["scope"].get<std::string>(), "1000 float steps")) << p;
    }
}

TEST(CliAccuracy, SkinnedFilesWithoutASkinOrAFolder) {
  const fs::path dir = mb::cli_test::scratchDir("accuracy_files");
  auto glb = mb::builtinSceneGlb("textured_box");
  ASSERT_TRUE(glb) << glb.error();
  std::ofstream(dir / "box.glb", std::ios::binary).write(reinterpret_cast<const char*>(glb->data()), std::streamsize(glb->size()));
  const auto run = runMb("accuracy --skinned-files " + quoted(dir) + " --json " + quoted(dir / "out" / "accuracy.json"));
  ASSERT_EQ(run.rc, 0) << run.out;
  const json doc = mb::cli_test::readJson(dir / "out" / "accuracy.json");
  EXPECT_EQ(value(doc, "skin.volume.files.files"), 1);
  EXPECT_EQ(value(doc, "skin.volume.files.meshes"), 0);
  EXPECT_TRUE(doc["figures"]["skin.volume.files.motor.max_deviation"]["value"].is_null());
  EXPECT_TRUE(contains(doc["figures"]["skin.volume.files.motor.max_deviation"].value("why", ""), "no animated skinned mesh"));
  EXPECT_FALSE(doc["figures"].contains("handedness.frames"));  // the built-in figures: another run
  const auto missing = runMb("accuracy --skinned-files " + quoted(dir / "nope"));
  EXPECT_EQ(missing.rc, 2) << missing.out;
  EXPECT_TRUE(contains(missing.out, (dir / "nope").string() + ": not a folder")) << missing.out;
}
