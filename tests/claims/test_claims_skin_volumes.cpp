// The real-file skinning row judged on a kept measurement (claims --skin-volumes): hand-made
// measurements against the printed rule (motor within 5 % and LBS not: reproduced; motor
// outside: differs; neither: inconclusive), the per-file text, the file named in the method.
// (Measured on the corpus and read back: ClaimsSkinning.RealFileRowSkipsCleanlyOrMeasuresRiggedSimple.)
#include <gtest/gtest.h>

#include "harness/claims/claims_sources.h"
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

json measurement(const json& meshes) {
  return {{"schema", claims::kSkinVolumesSchema}, {"folder", "some/corpus"}, {"files", {"a.glb", "b.gltf"}},
          {"meshes", meshes}};
}

claims::Claim judged(const json& meshes) {
  return only(claims::skinnedFileVolumeClaimsFrom(measurement(meshes), "kept/volumes.json"), "skinning_volume_file");
}

}  // namespace

TEST(ClaimsSkinVolumes, KeptMeasurementJudgedByThePrintedRule) {
  // a.glb: a closed mesh where LBS loses 10 % and the motor 1 %; b.gltf: two open meshes.
  const claims::Claim c = judged(json::array({mesh("a.glb", "body", true, 0.90, 1.0, 0.99, 1.0),
                                              mesh("b.gltf", "arm", false, 0.98, 1.01, 0.999, 1.001),
                                              mesh("b.gltf", "leg", false, 0.97, 1.0, 0.998, 1.002)}));
  EXPECT_EQ(c.verdict, claims::Verdict::Reproduced) << c.verdictText;
  EXPECT_EQ(c.verdictText, "reproduced: motor 0.990..1.002, LBS 0.900..1.010 of the rest volume");
  EXPECT_EQ(c.measured, "volume posed / rest over every time: a.glb (1 closed mesh(es): enclosed volume) LBS 0.900..1.000, "
                        "motor 0.990..1.000; b.gltf (2 open mesh(es): local volume) LBS 0.970..1.010, motor 0.998..1.002");
  EXPECT_EQ(c.measuredValue["meshes"]["b.gltf/leg"]["motor"]["max"], 1.002);
  EXPECT_FALSE(c.measuredValue["meshes"]["b.gltf/leg"].contains("file"));  // the row's shape as measured now
  EXPECT_NE(c.method.find("directly in some/corpus (its figures kept in kept/volumes.json)"), std::string::npos) << c.method;
  // The motor leaving 5 % differs; neither leaving it is inconclusive.
  EXPECT_EQ(judged(json::array({mesh("a.glb", "body", true, 0.90, 1.0, 0.94, 1.0)})).verdict, claims::Verdict::Differs);
  EXPECT_EQ(judged(json::array({mesh("a.glb", "body", true, 0.96, 1.0, 0.99, 1.0)})).verdict, claims::Verdict::Inconclusive);
  const claims::Claim none = judged(json::array());
  EXPECT_EQ(none.verdict, claims::Verdict::NotMeasurable);
  EXPECT_EQ(none.verdictText, "not measurable here: no animated skinned mesh in some/corpus");
}
