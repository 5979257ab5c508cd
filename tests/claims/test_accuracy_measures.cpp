// The accuracy room's measurements (harness/accuracy, `motorbench accuracy`), each against an
// independent reference: the paper's rule on frames worked by hand, the closed form of a
// normalised linear blend against slerp, volumes of known solids, a half turn that collapses a
// linear blend, GLM's rotation of a quaternion, and each figure as its measurement counted it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include <glm/gtc/quaternion.hpp>

#include "harness/accuracy/blending.h"
#include "harness/accuracy/conversion.h"
#include "harness/accuracy/drift.h"
#include "harness/accuracy/handedness.h"
#include "harness/accuracy/skinning.h"
#include "harness/figures/figure.h"
#include "pipelines/motor/companion.h"
#include "pipelines/motor/motor_kernels.h"

using namespace mb;
using json = nlohmann::json;

namespace {

double figureValue(const json& figures, const std::string& name) {
  const auto f = figures::figureNamed(figures, name);
  EXPECT_TRUE(f.has_value()) << "no figure " << name;
  return f ? f->value : std::nan("");
}

// Every figure says what it is.
void expectDescribed(const json& figures) {
  for (const auto& [name, f] : figures.items()) {
    EXPECT_FALSE(f.value("statistic", "").empty()) << name;
    EXPECT_FALSE(f.value("scope", "").empty()) << name;
    EXPECT_FALSE(f.value("definition", "").empty()) << name;
    EXPECT_FALSE(f.value("device", "").empty()) << name;
  }
}

// The closed form of a normalised linear blend of two rotations A apart against slerp: the
// blend's half-angle from the first key is atan2(t sin(A/2), 1 - t + t cos(A/2)), slerp's t A / 2,
// so the rotations differ by 2 |difference| (degrees).
double closedFormDegrees(double A, double t) {
  return glm::degrees(2 * std::fabs(std::atan2(t * std::sin(A / 2), 1 - t + t * std::cos(A / 2)) - t * A / 2));
}

}  // namespace

// The paper's rule on a half turn about y (normal -z, tangent -x): worked by hand, fromMatrix3
// takes its third branch and the scalar is m02 - m20 = 0 - 0 = +0; Math.sign(+0) = +0 != w for
// both w, so the rotor is negated to -0 and decodes as -1: wrong for w = +1, right for w = -1.
// The identity frame (scalar 1) is right both ways.
TEST(AccuracyHandedness, PaperRuleOnHandWorkedFrames) {
  const glm::vec3 n(0, 0, -1);
  const accuracy::PaperFrame plus = accuracy::paperLoadRule(n, glm::vec4(-1, 0, 0, 1));
  EXPECT_TRUE(plus.scalarZero);
  EXPECT_TRUE(std::signbit(plus.rotor.x));
  EXPECT_EQ(plus.handedness, -1.0f);
  EXPECT_EQ(accuracy::paperLoadRule(n, glm::vec4(-1, 0, 0, -1)).handedness, -1.0f);
  for (float w : {1.0f, -1.0f}) {
    const accuracy::PaperFrame id = accuracy::paperLoadRule(glm::vec3(0, 0, 1), glm::vec4(1, 0, 0, w));
    EXPECT_FALSE(id.scalarZero);
    EXPECT_EQ(id.handedness, w);
    EXPECT_NEAR(std::fabs(id.rotor.x), 1.0f, 1e-7f);
  }
}

// Over the 24 axis-aligned frames: both handedness values of a frame store the same rotor (the
// rule negates a zero scalar either way), so exactly one of the two is wrong for each of the 9
// half turns (PgaTangentRotor.AxisAlignedFramesIncludingZeroScalarExhaustive: 9 x 2 zero
// scalars) and none is wrong elsewhere: 9 wrong of 48.
TEST(AccuracyHandedness, NineWrongOfTheFortyEightAxisAlignedFrames) {
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  int frames = 0, zero = 0, wrong = 0;
  for (const glm::vec3& n : axes)
    for (const glm::vec3& t : axes) {
      if (glm::dot(n, t) != 0.0f) continue;
      for (float w : {1.0f, -1.0f}) {
        const accuracy::PaperFrame f = accuracy::paperLoadRule(n, glm::vec4(t, w));
        ++frames, zero += f.scalarZero, wrong += f.handedness != w;
        if (f.handedness != w) EXPECT_TRUE(f.scalarZero);
      }
    }
  EXPECT_EQ(frames, 48);
  EXPECT_EQ(zero, 18);
  EXPECT_EQ(wrong, 9);
}

// On the built-in scenes: a frame is wrong only where the scalar was exactly zero, at most one per
// zero-scalar frame; the axis-aligned textured_box has such frames; the figures are the sums.
TEST(AccuracyHandedness, BuiltinFramesWrongOnlyAmongZeroScalars) {
  const auto counts = accuracy::measureHandedness({"textured_box", "skinned_tube"});
  ASSERT_EQ(counts.size(), 2u);
  int frames = 0, wrong = 0;
  for (const accuracy::HandednessCount& c : counts) {
    EXPECT_LE(c.wrong, c.zeroScalar) << c.scene;
    EXPECT_LE(c.wrongNormalMapped, c.wrong) << c.scene;
    frames += c.frames, wrong += c.wrong;
  }
  EXPECT_EQ(counts[0].scene, "textured_box");
  EXPECT_EQ(counts[0].frames, 24);  // six faces of four vertices
  EXPECT_GT(counts[0].wrong, 0);
  json figures = json::object(), details = json::object();
  accuracy::putHandednessFigures(counts, figures, details);
  EXPECT_EQ(figureValue(figures, "handedness.frames"), frames);
  EXPECT_EQ(figureValue(figures, "handedness.frames_wrong"), wrong);
  EXPECT_EQ(figures["handedness.frames_wrong"]["n"], 2);  // scenes
  EXPECT_EQ(details["handedness"]["textured_box"]["wrong"], counts[0].wrong);
  expectDescribed(figures);
}

TEST(AccuracyBlending, MotorBlendAgainstSlerpMatchesTheClosedForm) {
  const glm::vec3 axis = glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f));
  const glm::quat base = glm::angleAxis(0.4f, glm::normalize(glm::vec3(1, 2, 3)));
  for (double deg : {20.0, 90.0, 170.0})
    for (float t : {0.1f, 0.25f, 0.5f, 0.8f}) {
      const double A = glm::radians(deg);
      const glm::quat q1 = glm::angleAxis(float(A), axis) * base;
      EXPECT_NEAR(accuracy::blendVsSlerpDegrees(base, q1, t), closedFormDegrees(A, t), 2e-3) << deg << " deg, t " << t;
    }
}

// candy_wrapper's keys are 90 degrees apart, so its largest difference is the closed form's
// maximum over t = k / 32; the figure is the worst animation of the scene.
TEST(AccuracyBlending, CandyWrapperLargestDifferenceIsTheClosedFormsMaximum) {
  const auto animations = accuracy::measureBlending({"skinned_tube"});
  const accuracy::BlendDeviation* candy = nullptr;
  for (const auto& a : animations)
    if (a.animation == "skinned_tube/candy_wrapper") candy = &a;
  ASSERT_NE(candy, nullptr);
  const double A = glm::radians(candy->keyAngleDegrees);
  EXPECT_NEAR(candy->keyAngleDegrees, 90.0, 1e-3);
  double want = 0;
  for (int k = 1; k < accuracy::kBlendSteps; ++k) want = std::max(want, closedFormDegrees(A, double(k) / accuracy::kBlendSteps));
  EXPECT_NEAR(candy->largestDegrees, want, 2e-3);
  json figures = json::object(), details = json::object();
  accuracy::putBlendFigures(animations, figures, details);
  EXPECT_NEAR(figureValue(figures, "blend.max_angle_error_deg"), want, 2e-3);
  EXPECT_EQ(figures["blend.max_angle_error_deg"]["n"], int(animations.size()));
  expectDescribed(figures);
  // Nothing to blend: not measured, and says why.
  json none = json::object();
  accuracy::putBlendFigures({}, none, details);
  EXPECT_TRUE(none["blend.max_angle_error_deg"]["value"].is_null());
  EXPECT_FALSE(none["blend.max_angle_error_deg"].value("why", "").empty());
}

// Volumes of known solids: the unit cube 1, a 2-cube 8, one face missing: not closed.
TEST(AccuracySkinning, EnclosedVolumeAndClosedness) {
  std::vector<glm::vec3> p;
  for (int i = 0; i < 8; ++i) p.emplace_back(float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1));
  // Outward-wound quads, two triangles each.
  const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::vector<uint32_t> idx;
  for (const auto& q : quads) idx.insert(idx.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
  EXPECT_NEAR(accuracy::enclosedVolume(p, idx), 1.0, 1e-12);
  EXPECT_TRUE(accuracy::isClosed(p, idx));
  std::vector<glm::vec3> big = p;
  for (glm::vec3& x : big) x = 2.0f * x + glm::vec3(5, -3, 1);  // off the origin: still 8
  EXPECT_NEAR(accuracy::enclosedVolume(big, idx), 8.0, 1e-9);
  idx.resize(idx.size() - 6);
  EXPECT_FALSE(accuracy::isClosed(p, idx));
}

// The candy wrapper turns the middle joint by half a turn about the tube's axis: a ring weighted
// half to each joint is, under a linear blend, the mean of p and p turned by 180 degrees, its
// centroid: the radius collapses towards 0. A rotation keeps every radius, so the motor blend
// (a rotor halfway, a quarter turn) keeps it within 1 %.
TEST(AccuracySkinning, CandyWrapperLbsCollapsesTheRingMotorKeepsIt) {
  const accuracy::RingRadii r = accuracy::measureCandyWrapper();
  ASSERT_TRUE(r.measured) << r.why;
  EXPECT_EQ(r.times, 64);
  EXPECT_GT(r.rings, 2);
  EXPECT_LT(r.lbs, 0.1);
  EXPECT_GE(r.motor, 0.99);
  EXPECT_LE(r.motor, 1.01);
  json figures = json::object(), details = json::object();
  accuracy::putCandyWrapperFigures(r, figures, details);
  EXPECT_EQ(figureValue(figures, "skin.ring_radius.candy_wrapper.lbs.min"), r.lbs);
  EXPECT_EQ(figureValue(figures, "skin.ring_radius.candy_wrapper.motor.min"), r.motor);
  EXPECT_EQ(figures["skin.ring_radius.candy_wrapper.motor.min"]["n"], 64);
  expectDescribed(figures);
}

// A measurement made by hand: two files, three meshes; the figures are its extremes, the largest
// deviation from the rest volume and the counts.
TEST(AccuracySkinning, FileFiguresAreTheMeasurementsExtremes) {
  auto mesh = [](const std::string& file, bool closed, double lbsLo, double lbsHi, double motLo, double motHi) {
    return json{{"id", file + "/m"}, {"file", file}, {"closed", closed}, {"lbs", {{"min", lbsLo}, {"max", lbsHi}}},
                {"motor", {{"min", motLo}, {"max", motHi}}}};
  };
  const json volumes = {{"folder", "some/corpus"}, {"files", {"a.glb", "b.gltf", "c.glb"}},
                        {"meshes", {mesh("a.glb", true, 0.90, 1.0, 0.99, 1.0), mesh("b.gltf", false, 0.98, 1.01, 0.999, 1.001),
                                    mesh("b.gltf", false, 0.97, 1.0, 0.998, 1.03)}}};
  json figures = json::object(), details = json::object();
  accuracy::putSkinnedFileFigures(volumes, figures, details);
  EXPECT_EQ(figureValue(figures, "skin.volume.files.lbs.min"), 0.90);
  EXPECT_EQ(figureValue(figures, "skin.volume.files.lbs.max"), 1.01);
  EXPECT_NEAR(figureValue(figures, "skin.volume.files.lbs.max_deviation"), 0.10, 1e-12);
  EXPECT_EQ(figureValue(figures, "skin.volume.files.motor.min"), 0.99);
  EXPECT_NEAR(figureValue(figures, "skin.volume.files.motor.max_deviation"), 0.03, 1e-12);
  EXPECT_EQ(figureValue(figures, "skin.volume.files.files"), 3);
  EXPECT_EQ(figureValue(figures, "skin.volume.files.skinned_files"), 2);
  EXPECT_EQ(figureValue(figures, "skin.volume.files.meshes"), 3);
  EXPECT_EQ(figures["skin.volume.files.motor.min"]["n"], 3);
  EXPECT_EQ(details["skinned_files"], volumes);
  expectDescribed(figures);
  json none = json::object();
  accuracy::putSkinnedFileFigures({{"folder", "empty"}, {"files", json::array()}, {"meshes", json::array()}}, none, details);
  EXPECT_TRUE(none["skin.volume.files.motor.max_deviation"]["value"].is_null());
}

// Without a folder the measurement says so; with the corpus (MB_CORPUS_DIR, else
// ../shared/corpus) the motor-skinned volume of RiggedSimple stays within 5 % of its rest volume
// at every time.
TEST(AccuracySkinning, SkinnedFilesNameAMissingFolderOrMeasureRiggedSimple) {
  const auto none = accuracy::measureSkinnedFileVolumes("/nonexistent/corpus");
  ASSERT_FALSE(none);
  EXPECT_EQ(none.error(), "/nonexistent/corpus: not a folder");
  const char* env = std::getenv("MB_CORPUS_DIR");
  const std::filesystem::path dir = env ? env : std::filesystem::path(MB_SOURCE_DIR) / ".." / "shared" / "corpus";
  if (!std::filesystem::exists(dir / "RiggedSimple.gltf")) GTEST_SKIP() << "no corpus at " << dir;
  auto measured = accuracy::measureSkinnedFileVolumes(dir.string());
  ASSERT_TRUE(measured) << measured.error();
  bool rigged = false;
  for (const json& m : (*measured)["meshes"]) {
    if (m["file"] != "RiggedSimple.gltf") continue;
    rigged = true;
    EXPECT_EQ(m["measure"], "enclosed volume") << m;  // a closed cylinder
    EXPECT_GE(m["motor"]["min"].get<double>(), 0.95) << m;
    EXPECT_LE(m["motor"]["max"].get<double>(), 1.05) << m;
  }
  EXPECT_TRUE(rigged) << measured->dump();
}

// Quaternion -> rotor: bit-exact on the special and random quaternions, and the rotor it gives
// rotates as GLM's quaternion does (so the free conversion is also the right one).
TEST(AccuracyConversion, QuaternionToRotorIsExactAndRotatesAsGlm) {
  const accuracy::QuatRotorCheck bits = accuracy::checkRotorFromQuat(2000);
  EXPECT_EQ(bits.samples, 2016);
  EXPECT_EQ(bits.mismatches, 0);
  const glm::quat q = glm::normalize(glm::quat(0.7f, -0.2f, 0.5f, 0.4f));
  const glm::vec3 v(0.3f, -1.2f, 2.0f);
  const Motor r = companion::rotorFromQuat(q);
  const MK::vec3 got = mk().sw_md(r, MK::vec3(v.x, v.y, v.z));
  const glm::vec3 want = q * v;
  EXPECT_NEAR(got.x, want.x, 1e-5f);
  EXPECT_NEAR(got.y, want.y, 1e-5f);
  EXPECT_NEAR(got.z, want.z, 1e-5f);
  json figures = json::object();
  accuracy::putConversionFigures(bits, figures);
  EXPECT_EQ(figureValue(figures, "conversion.quat_to_rotor.samples"), 2016);
  EXPECT_EQ(figureValue(figures, "conversion.quat_to_rotor.mismatches"), 0);
  expectDescribed(figures);
}

// The drift's figures are its JSON's numbers under their names, ops the sum of the columns.
TEST(AccuracyDrift, FiguresNameEachSpaceAndSide) {
  const json side = {{"raw", 0.02}, {"renormalised", 1e-7}, {"renormalisation", "Gram-Schmidt"},
                     {"renormOps", {{"mul", 80}, {"add", 54}, {"div", 0}, {"sqrt", 4}, {"other", 0}}}};
  const json drift = {{"steps", 10}, {"step", "a turn"},
                      {"spaces", {{{"space", "S3"}, {"matrix", side}, {"motor", side}}, {{"space", "H3"}, {"matrix", side}, {"motor", side}}}}};
  json figures = json::object(), details = json::object();
  accuracy::putDriftFigures(drift, figures, details);
  EXPECT_EQ(figures.size(), 12u);
  EXPECT_EQ(figureValue(figures, "drift.s3.matrix.raw"), 0.02);
  EXPECT_EQ(figureValue(figures, "drift.h3.motor.renormalised"), 1e-7);
  EXPECT_EQ(figureValue(figures, "drift.h3.matrix.renorm_ops"), 138);
  EXPECT_NE(figures["drift.s3.motor.raw"]["scope"].get<std::string>().find("10 float steps"), std::string::npos);
  expectDescribed(figures);
}
