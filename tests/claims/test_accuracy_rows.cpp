// The accuracy rows (claim_rows_accuracy.cpp) judged on figures made by the accuracy room's own
// functions from hand-made measurements: the printed rule decides (the motor within 5 % of the
// rest volume, LBS beyond it, the handedness rule's wrong frames at 0), a missing measurement is
// "not measurable" with its reason, and the baseline rows print their figures.
#include <gtest/gtest.h>

#include <map>

#include "harness/accuracy/blending.h"
#include "harness/accuracy/drift.h"
#include "harness/accuracy/handedness.h"
#include "harness/accuracy/skinning.h"
#include "harness/claims/evaluate.h"
#include "tests/claims/claims_test_support.h"

using namespace mb;
using json = nlohmann::json;
using mb::claims_test::only;

namespace {

json mesh(const std::string& file, const std::string& name, bool closed, double lbsLo, double lbsHi, double motLo,
          double motHi) {
  return {{"id", file + "/" + name}, {"file", file}, {"closed", closed},
          {"measure", closed ? "enclosed volume" : "local volume (Jacobian det)"},
          {"lbs", {{"min", lbsLo}, {"max", lbsHi}}}, {"motor", {{"min", motLo}, {"max", motHi}}}};
}

// The rows judged on `source`'s figures.
std::vector<claims::Claim> judgedOn(const std::string& source, const json& figures) {
  claims::FigureSet set;
  set.figures[source] = figures;
  return claims::evaluateAll(claims::accuracyRows(), set);
}

std::vector<claims::Claim> judgedFiles(const json& meshes) {
  json figures = json::object(), details = json::object();
  accuracy::putSkinnedFileFigures({{"folder", "some/corpus"}, {"files", {"a.glb", "b.gltf"}}, {"meshes", meshes}}, figures,
                                  details);
  return judgedOn("corpus_accuracy", figures);
}

}  // namespace

// a.glb: a closed mesh where LBS loses 10 % and the motor 1 %; b.gltf: two open meshes.
TEST(AccuracyRows, SkinnedFileRowsJudgedByThePrintedRule) {
  const auto rows = judgedFiles(json::array({mesh("a.glb", "body", true, 0.90, 1.0, 0.99, 1.0),
                                             mesh("b.gltf", "arm", false, 0.98, 1.01, 0.999, 1.001),
                                             mesh("b.gltf", "leg", false, 0.97, 1.0, 0.998, 1.002)}));
  const claims::Claim motor = only(rows, "skinning_volume_file"), lbs = only(rows, "skinning_volume_file_lbs");
  EXPECT_EQ(motor.verdict, claims::Verdict::Reproduced) << motor.verdictText;
  EXPECT_NE(motor.measured.find("0.01 of rest"), std::string::npos) << motor.measured;
  EXPECT_EQ(lbs.verdict, claims::Verdict::Reproduced) << lbs.verdictText;
  EXPECT_NE(lbs.measured.find("0.1 of rest"), std::string::npos) << lbs.measured;
  // The motor leaving 5 % differs; LBS within 5 % too: the files' motion does not pinch.
  EXPECT_EQ(only(judgedFiles(json::array({mesh("a.glb", "body", true, 0.90, 1.0, 0.94, 1.0)})), "skinning_volume_file").verdict,
            claims::Verdict::Differs);
  EXPECT_EQ(only(judgedFiles(json::array({mesh("a.glb", "body", true, 0.96, 1.0, 0.99, 1.0)})), "skinning_volume_file_lbs").verdict,
            claims::Verdict::Differs);
  const claims::Claim none = only(judgedFiles(json::array()), "skinning_volume_file");
  EXPECT_EQ(none.verdict, claims::Verdict::NotMeasurable);
  EXPECT_NE(none.verdictText.find("no animated skinned mesh under some/corpus"), std::string::npos) << none.verdictText;
}

// The built-in rows: the handedness rule judged at 0 wrong frames; the candy wrapper's motor
// above 95 % and LBS below; the built-in rows read no corpus figure and the file rows no
// built-in one.
TEST(AccuracyRows, BuiltinRowsJudgedByThePrintedRule) {
  json figures = json::object(), details = json::object();
  accuracy::HandednessCount box{"textured_box", 24, 8, 8, 8, 8, 1.3};
  accuracy::putHandednessFigures({box}, figures, details);
  accuracy::RingRadii r;
  r.measured = true, r.lbs = 0.025, r.motor = 0.9999, r.rings = 9, r.times = 64;
  accuracy::putCandyWrapperFigures(r, figures, details);
  auto rows = judgedOn("accuracy", figures);
  const claims::Claim h = only(rows, "handedness_rule");
  EXPECT_EQ(h.verdict, claims::Verdict::Differs) << h.verdictText;
  EXPECT_NE(h.measured.find("(8 frames / 24 frames)"), std::string::npos) << h.measured;
  EXPECT_EQ(only(rows, "skinning_volume").verdict, claims::Verdict::Reproduced);
  EXPECT_EQ(only(rows, "skinning_volume_lbs").verdict, claims::Verdict::Reproduced);
  EXPECT_EQ(only(rows, "skinning_volume_file").verdict, claims::Verdict::NotMeasurable);
  box.wrong = box.wrongNormalMapped = 0;
  json right = json::object();
  accuracy::putHandednessFigures({box}, right, details);
  EXPECT_EQ(only(judgedOn("accuracy", right), "handedness_rule").verdict, claims::Verdict::Reproduced);
  r.motor = 0.9;  // the motor ring shrinks too
  accuracy::putCandyWrapperFigures(r, figures, details);
  EXPECT_EQ(only(judgedOn("accuracy", figures), "skinning_volume").verdict, claims::Verdict::Differs);
}

// The drift row is a baseline over its twelve figures: each space and side's raw and
// renormalised distance and renormalisation ops.
TEST(AccuracyRows, DriftRowIsABaselineOverEverySpaceAndSide) {
  const json side = {{"raw", 0.02}, {"renormalised", 1e-7}, {"renormalisation", "Gram-Schmidt"},
                     {"renormOps", {{"mul", 16}, {"add", 6}, {"sqrt", 2}}}};
  const json drift = {{"steps", 10}, {"spaces", {{{"space", "S3"}, {"matrix", side}, {"motor", side}},
                                                 {{"space", "H3"}, {"matrix", side}, {"motor", side}}}}};
  json figures = json::object(), details = json::object();
  accuracy::putDriftFigures(drift, figures, details);
  const claims::Claim d = only(judgedOn("accuracy", figures), "curved_drift");
  EXPECT_EQ(d.verdict, claims::Verdict::Baseline) << d.verdictText;
  EXPECT_EQ(d.measuredValue.size(), 12u) << d.measuredValue.dump();
  EXPECT_NE(d.measured.find("H3 motor ops per renormalisation 24 ops"), std::string::npos) << d.measured;
}

// Every figure an accuracy row reads is one the accuracy room writes: the built-in run's figures
// (from hand-made measurements: the names do not depend on the values) and the skinned-file run's.
TEST(AccuracyRows, EveryReferenceIsAFigureTheRoomWrites) {
  json builtin = json::object(), files = json::object(), details = json::object();
  accuracy::putHandednessFigures({{"textured_box", 24, 8, 8, 8, 8, 1.3}}, builtin, details);
  accuracy::RingRadii r;
  r.measured = true, r.lbs = 0.5, r.motor = 1, r.times = 1;
  accuracy::putCandyWrapperFigures(r, builtin, details);
  const json side = {{"raw", 1}, {"renormalised", 1}, {"renormOps", json::object()}};
  accuracy::putDriftFigures({{"steps", 1}, {"spaces", {{{"space", "S3"}, {"matrix", side}, {"motor", side}},
                                                       {{"space", "H3"}, {"matrix", side}, {"motor", side}}}}},
                            builtin, details);
  accuracy::putSkinnedFileFigures({{"folder", "f"}, {"files", json::array()}, {"meshes", json::array()}}, files, details);
  accuracy::putBlendFigures({}, builtin, details);  // the names, not measured
  const std::map<std::string, const json*> sources = {{"accuracy", &builtin}, {"corpus_accuracy", &files}};
  for (const claims::ClaimRow& row : claims::accuracyRows())
    for (const claims::Evidence& e : row.evidence)
      for (const std::string& ref : {e.value, e.over}) {
        if (ref.empty()) continue;
        const std::string source = ref.substr(0, ref.find(':')), name = ref.substr(ref.find(':') + 1);
        ASSERT_TRUE(sources.count(source)) << row.id << ": " << ref;
        EXPECT_TRUE(sources.at(source)->contains(name)) << row.id << ": " << ref << " is no figure of " << source;
      }
}
