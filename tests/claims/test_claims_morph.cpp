// The morph rows of claims on hand-made report.json "morph" figures: each row quotes
// its figure, the 50 dB rule decides the image rows, and without morph figures every row says
// why it is not measurable.
#include <gtest/gtest.h>

#include "harness/claims/claims_morph.h"
#include "harness/figures/figure.h"

using json = nlohmann::json;
using namespace mb;

namespace {

void putFigure(json& morph, const std::string& name, double value, const std::string& unit) {
  figures::Figure f;
  f.name = name;
  f.value = value;
  f.unit = unit;
  figures::put(morph["figures"], f);
}

const claims::Claim& rowOf(const std::vector<claims::Claim>& rows, const std::string& id) {
  for (const claims::Claim& c : rows)
    if (c.id == id) return c;
  ADD_FAILURE() << "no row " << id;
  return rows.front();
}

}  // namespace

TEST(ClaimsMorph, RowsQuoteTheReportsMorphFigures) {
  json morph = {{"schema", "motorbench-morph/1"}};
  putFigure(morph, "morph.bytes_per_vertex.matrix", 48, "bytes");
  putFigure(morph, "morph.bytes_per_vertex.motor_frame", 36, "bytes");
  putFigure(morph, "morph.bytes_per_target_vertex.matrix", 36, "bytes");
  putFigure(morph, "morph.bytes_per_target_vertex.motor_frame", 36, "bytes");
  putFigure(morph, "morph.bytes_per_target_vertex.motor_rotor", 28, "bytes");
  putFigure(morph, "morph.worst_psnr.rigid.motor_frame", 56.7, "dB");
  putFigure(morph, "morph.worst_psnr.rigid.motor_rotor", 29.9, "dB");
  morph["worst"]["morph.worst_psnr.rigid.motor_rotor"] = {{"scene", "morphing.gltf"}, {"anim", -1}, {"time", 0}};
  const auto rows = claims::morphClaims(json{{"morph", morph}}, "r.json");
  ASSERT_EQ(rows.size(), 4u);
  const claims::Claim& vertex = rowOf(rows, "morph_vertex_bytes");
  EXPECT_EQ(vertex.measuredValue["motor"], 36);  // 9 floats
  EXPECT_EQ(vertex.measuredValue["matrix"], 48);
  const claims::Claim& target = rowOf(rows, "morph_target_bytes");
  EXPECT_NE(target.verdictText.find("8 bytes fewer"), std::string::npos) << target.verdictText;  // 36 - 28
  const claims::Claim& frame = rowOf(rows, "morph_frame_image");
  EXPECT_EQ(frame.verdict, claims::Verdict::Reproduced);
  EXPECT_DOUBLE_EQ(frame.measuredValue.get<double>(), 56.7);
  const claims::Claim& rotor = rowOf(rows, "morph_rotor_image");
  EXPECT_EQ(rotor.verdict, claims::Verdict::Differs);  // 29.9 < 50
  EXPECT_NE(rotor.method.find("morphing.gltf"), std::string::npos) << rotor.method;
  for (const claims::Claim& c : rows) EXPECT_EQ(c.section, "Morph targets");
}

TEST(ClaimsMorph, WithoutMorphFiguresEveryRowSaysWhy) {
  for (const claims::Claim& c : claims::morphClaims(json{{"scenes", json::array()}}, "r.json")) {
    EXPECT_EQ(c.verdict, claims::Verdict::NotMeasurable) << c.id;
    EXPECT_NE(c.verdictText.find("--morph-json"), std::string::npos) << c.verdictText;
  }
}
