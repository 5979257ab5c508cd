// Skinned frames judged by their own skinning method (harness/render/skin_judgement.h), the
// judgement compare, report and survey share: which reference each registered pipeline is judged
// against; the decision and its texts on synthetic frames whose drawn pixels are set by hand;
// and skinned_tube drawn at 64x64, where motor leaves matrix by more than 1 % yet matches the
// motor-blend reference, and a wrong pose or a scaled mesh fails as one.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "harness/render/fixed_views.h"
#include "harness/render/render_frame.h"
#include "harness/render/skin_judgement.h"
#include "pipelines/pipeline.h"
#include "pipelines/scene/loader.h"
#include "pipelines/skin_method.h"

namespace {

using mb::RgbaImage;
using mb::SkinnedFrameJudgement;

// A 100x20 frame of the clear colour (bytes 51, 51, 56) whose first `drawn` pixels are red.
RgbaImage frame(int drawn) {
  RgbaImage img{100, 20, {}};
  for (int i = 0; i < img.width * img.height; ++i)
    img.rgba.insert(img.rgba.end(), {uint8_t(i < drawn ? 200 : 51), 51, uint8_t(i < drawn ? 10 : 56), 255});
  return img;
}

SkinnedFrameJudgement judged(const std::string& pipeline, const RgbaImage& image, const RgbaImage& matrix,
                             const RgbaImage* reference, const mb::Thresholds* t = nullptr) {
  auto j = mb::judgeSkinnedFrame(pipeline, image, matrix, reference, "", t);
  EXPECT_TRUE(j) << j.error();
  return j ? j.take() : SkinnedFrameJudgement{};
}

TEST(SkinJudgement, EachPipelineIsJudgedAgainstItsOwnMethodsReference) {
  for (const char* p : {"matrix", "affine", "qtangent", "hybrid", "matrix_c"}) {
    EXPECT_EQ(mb::skinMethodOf(p), mb::SkinMethod::LinearBlend) << p;
    EXPECT_STREQ(mb::skinReferenceOf(p), "matrix") << p;
  }
  for (const char* p : {"motor", "motor_q", "motor_c", "motor_cf"}) {
    EXPECT_EQ(mb::skinMethodOf(p), mb::SkinMethod::MotorBlend) << p;
    EXPECT_STREQ(mb::skinReferenceOf(p), "motor-blend reference") << p;
  }
  for (const std::string& p : {"s3_matrix", "h3_motor", "nonesuch"}) EXPECT_EQ(mb::skinMethodOf(p), mb::SkinMethod::None) << p;
  // Every glTF pipeline says its method in its registry line: a new one cannot be left unjudged.
  for (const std::string& p : mb::pipelineNames()) EXPECT_NE(mb::skinMethodOf(p), mb::SkinMethod::None) << p;
  EXPECT_TRUE(mb::skinMethodsDiffer("matrix", "motor"));
  EXPECT_TRUE(mb::skinMethodsDiffer("motor_cf", "hybrid"));
  EXPECT_FALSE(mb::skinMethodsDiffer("motor", "motor_c"));
  EXPECT_FALSE(mb::skinMethodsDiffer("matrix", "hybrid"));
  EXPECT_FALSE(mb::skinMethodsDiffer("s3_matrix", "motor"));
}

// 30 pixels more than matrix (2.91 % of 1030, more than 1 %) but exactly its reference's count.
TEST(SkinJudgement, MotorBlendFrameAtItsReferencePassesFarFromMatrix) {
  const RgbaImage matrix = frame(1000), motor = frame(1030), reference = frame(1030);
  const mb::Thresholds t{2.0 / 255.0, 0.1};
  const SkinnedFrameJudgement j = judged("motor", motor, matrix, &reference, &t);
  EXPECT_TRUE(j.judged);
  EXPECT_FALSE(j.failed) << j.reason;
  EXPECT_EQ(j.reference, "motor-blend reference");
  EXPECT_TRUE(j.thresholdsApplied);
  EXPECT_FALSE(j.thresholds.failed);
  EXPECT_EQ(j.vsReference.metrics.rmse, 0.0);
  EXPECT_EQ(j.vsReference.drawn.apartPercent, 0.0);
  // The figures against matrix: measured, apart, deciding nothing.
  EXPECT_TRUE(j.vsMatrix.drawn.failed);
  EXPECT_DOUBLE_EQ(j.vsMatrix.drawn.apartPercent, 100.0 * 30 / 1030);
  EXPECT_DOUBLE_EQ(j.vsMatrix.metrics.fractionOver2, 30.0 / 2000);
  EXPECT_TRUE(mb::judge(matrix, motor, t).failed) << "against matrix the same thresholds fail";
  const std::vector<std::string> lines = mb::judgementLines(j);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].rfind("motor against the motor-blend reference (its own method's: ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find("identical; drawn pixels motor 1030, reference 1030 (0.00 % apart)"), std::string::npos) << lines[0];
  EXPECT_EQ(lines[1].rfind("motor against matrix (the other method, measured, decides nothing): PSNR ", 0), 0u) << lines[1];
  EXPECT_NE(lines[1].find("drawn pixels motor 1030, matrix 1000 (2.91 % apart)"), std::string::npos) << lines[1];
}

TEST(SkinJudgement, MoreThanOnePercentFromItsOwnReferenceIsAWrongPose) {
  const RgbaImage matrix = frame(1030), motor = frame(1030), reference = frame(1000);
  const SkinnedFrameJudgement j = judged("motor", motor, matrix, &reference);
  EXPECT_TRUE(j.failed);
  EXPECT_EQ(j.reason, "motor against its own method's reference (motor-blend reference): drawn-pixel counts more than "
                      "1 % apart (motor 1030, motor-blend reference 1000: 2.91 %); 0.00 % from matrix: wrong pose, "
                      "scale or missing mesh");
  const RgbaImage empty = frame(0);
  const SkinnedFrameJudgement none = judged("motor_c", empty, matrix, &reference);
  EXPECT_TRUE(none.failed);
  EXPECT_EQ(none.reason, "motor_c against its own method's reference (motor-blend reference): motor_c drew nothing "
                         "(0 pixels) where motor-blend reference drew 1000; 100.00 % from matrix: wrong pose, scale or "
                         "missing mesh");
  // Within 1 % of the reference (5 of 1005), but over the thresholds given: 5 of 2000 pixels, 0.25 %.
  const RgbaImage near = frame(1005);
  const mb::Thresholds t{2.0 / 255.0, 0.1};
  const SkinnedFrameJudgement over = judged("motor", near, matrix, &reference, &t);
  EXPECT_FALSE(over.vsReference.drawn.failed);
  EXPECT_TRUE(over.failed);
  EXPECT_EQ(over.reason, "motor against its own method's reference (motor-blend reference): " + over.thresholds.reason);
  EXPECT_DOUBLE_EQ(over.thresholds.failPercent, 0.25);
}

TEST(SkinJudgement, LinearBlendPipelineIsJudgedAgainstMatrix) {
  const RgbaImage matrix = frame(1000), affine = frame(1030);
  const SkinnedFrameJudgement j = judged("affine", affine, matrix, nullptr);  // no motor-blend reference needed
  EXPECT_TRUE(j.judged);
  EXPECT_EQ(j.reference, "matrix");
  EXPECT_TRUE(j.failed);
  EXPECT_EQ(j.reason, "affine against its own method's reference (matrix): drawn-pixel counts more than 1 % apart "
                      "(affine 1030, matrix 1000: 2.91 %): wrong pose, scale or missing mesh");
  EXPECT_DOUBLE_EQ(j.vsReference.drawn.apartPercent, j.vsMatrix.drawn.apartPercent);
  EXPECT_EQ(mb::judgementLines(j).size(), 1u);
  EXPECT_EQ(mb::judgementLines(j)[0].rfind("affine against matrix (its own method's reference): ", 0), 0u);
}

TEST(SkinJudgement, WithoutItsReferenceAFrameIsNotJudgedAndSaysWhy) {
  const RgbaImage matrix = frame(1000), motor = frame(1300);
  auto j = mb::judgeSkinnedFrame("motor", motor, matrix, nullptr, "a skinned mesh drawn by more than one node", nullptr);
  ASSERT_TRUE(j) << j.error();
  EXPECT_FALSE(j->judged);
  EXPECT_FALSE(j->failed) << "nothing decided";
  EXPECT_EQ(j->why, "a skinned mesh drawn by more than one node");
  EXPECT_EQ(mb::judgementLines(*j)[0].rfind("motor not judged against the motor-blend reference (a skinned mesh drawn "
                                            "by more than one node); against matrix: ", 0), 0u);
  const nlohmann::json js = mb::toJson(*j);
  EXPECT_EQ(js["judged"], false);
  EXPECT_EQ(js["why"], "a skinned mesh drawn by more than one node");
  EXPECT_TRUE(js["vsReference"].is_null());
  EXPECT_EQ(js["vsMatrix"]["drawnPixels"], 1300);
  EXPECT_EQ(js["vsMatrix"]["referenceDrawnPixels"], 1000);
  // Images of different sizes are an error, not a verdict.
  EXPECT_FALSE(mb::judgeSkinnedFrame("motor", RgbaImage{10, 10, std::vector<uint8_t>(400, 51)}, matrix, nullptr, "", nullptr));
}

TEST(SkinJudgement, JsonCarriesTheReferenceAndBothFigures) {
  const RgbaImage matrix = frame(1000), motor = frame(1030), reference = frame(1031);
  const mb::Thresholds t{2.0 / 255.0, 0.1};
  const nlohmann::json j = mb::toJson(judged("motor", motor, matrix, &reference, &t));
  EXPECT_EQ(j["pipeline"], "motor");
  EXPECT_EQ(j["reference"], "motor-blend reference");
  EXPECT_EQ(j["judged"], true);
  EXPECT_TRUE(j["why"].is_null());
  EXPECT_EQ(j["vsMatrix"]["referenceDrawnPixels"], 1000);
  EXPECT_DOUBLE_EQ(j["vsMatrix"]["drawnApartPercent"].get<double>(), 100.0 * 30 / 1030);
  EXPECT_EQ(j["vsReference"]["referenceDrawnPixels"], 1031);
  EXPECT_EQ(j["vsReference"]["identical"], false);
  EXPECT_DOUBLE_EQ(j["vsReference"]["fractionOver2"].get<double>(), 1.0 / 2000);
  EXPECT_EQ(j["thresholds"]["applied"], true);
  EXPECT_EQ(j["thresholds"]["failed"], false);
  EXPECT_EQ(j["failed"], false);
  EXPECT_TRUE(j["reason"].is_null());
}

// skinned_tube at 64x64: the candy wrapper's near half turn (t = 1.97), where linear blend
// skinning collapses the ring and motor blending keeps it.
mb::FrameSettings tubeFrame(int anim, float time) {
  mb::FrameSettings s;
  s.width = s.height = 64;
  s.anim = mb::AnimState{anim, time};
  return s;
}
constexpr int kBend = 0, kCandyWrapper = 2;

RgbaImage draw(const mb::Scene& scene, const std::string& pipeline, const mb::FrameSettings& s) {
  auto f = mb::renderFrame(scene, pipeline, s);
  EXPECT_TRUE(f) << f.error();
  return f ? f->image : RgbaImage{};
}

TEST(SkinJudgementTube, MotorMatchesTheMotorBlendReferenceWhereItLeavesMatrix) {
  auto scene = mb::loadScene("skinned_tube");
  ASSERT_TRUE(scene) << scene.error();
  const mb::FrameSettings s = tubeFrame(kCandyWrapper, 1.97f);
  const RgbaImage matrix = draw(*scene, "matrix", s), motor = draw(*scene, "motor", s);
  const std::vector<glm::vec3> positions = scene->meshes[0].primitives[0].positions;
  const mb::MotorBlendFrames own = mb::motorBlendReferenceFrames(*scene, {s});
  ASSERT_TRUE(own.available()) << own.why;
  ASSERT_EQ(own.images.size(), 1u);
  // The scene is restored: skins back, positions as loaded.
  EXPECT_EQ(scene->meshes[0].primitives[0].positions, positions);
  EXPECT_TRUE(mb::drawsSkinned(*scene));
  const mb::Thresholds t{2.0 / 255.0, 0.1};
  const SkinnedFrameJudgement j = judged("motor", motor, matrix, &own.images[0], &t);
  EXPECT_TRUE(j.judged);
  EXPECT_FALSE(j.failed) << j.reason;
  EXPECT_LE(j.vsReference.drawn.apartPercent, 1.0);
  EXPECT_TRUE(j.vsMatrix.drawn.failed) << "the frame no longer separates the methods (" << j.vsMatrix.drawn.apartPercent << " %)";
  EXPECT_TRUE(mb::judge(matrix, motor, t).failed);
}

TEST(SkinJudgementTube, AnotherPoseOrAScaledMeshFailsAsAWrongPose) {
  auto scene = mb::loadScene("skinned_tube");
  ASSERT_TRUE(scene) << scene.error();
  // motor drawing the bent tube where the rest pose was asked for (the camera frames the scene
  // at the pose asked for, as renderFrame does), against the rest pose's reference.
  const mb::FrameSettings bent = tubeFrame(kBend, 1.0f), rest = tubeFrame(kBend, 0.0f);
  const RgbaImage matrix = draw(*scene, "matrix", rest);
  auto wrongPose = mb::drawFromViews(*scene, "motor", {bent}, mb::framings(*scene, {rest}));
  ASSERT_TRUE(wrongPose) << wrongPose.error();
  const mb::MotorBlendFrames restReference = mb::motorBlendReferenceFrames(*scene, {rest});
  ASSERT_TRUE(restReference.available()) << restReference.why;
  const SkinnedFrameJudgement pose = judged("motor", wrongPose->front(), matrix, &restReference.images[0]);
  EXPECT_TRUE(pose.failed);
  EXPECT_NE(pose.reason.find(": wrong pose, scale or missing mesh"), std::string::npos) << pose.reason;
  EXPECT_FALSE(judged("motor", draw(*scene, "motor", rest), matrix, &restReference.images[0]).failed) << "the right pose";
  // motor drawing the mesh scaled by 0.8 against the reference of the pose it was asked for.
  const mb::MotorBlendFrames reference = mb::motorBlendReferenceFrames(*scene, {bent});
  ASSERT_TRUE(reference.available()) << reference.why;
  const std::vector<mb::View> views = mb::framings(*scene, {bent});  // the camera of the unscaled scene
  const RgbaImage matrixBent = draw(*scene, "matrix", bent);
  for (glm::vec3& p : scene->meshes[0].primitives[0].positions) p *= 0.8f;
  auto drawn = mb::drawFromViews(*scene, "motor", {bent}, views);
  ASSERT_TRUE(drawn) << drawn.error();
  const RgbaImage scaled = drawn->front();
  const SkinnedFrameJudgement small = judged("motor", scaled, matrixBent, &reference.images[0]);
  EXPECT_TRUE(small.failed);
  EXPECT_EQ(small.reason.rfind("motor against its own method's reference (motor-blend reference): drawn-pixel counts "
                               "more than 1 % apart (motor ", 0), 0u) << small.reason;
  EXPECT_NE(small.reason.find(": wrong pose, scale or missing mesh"), std::string::npos) << small.reason;
}

}  // namespace
