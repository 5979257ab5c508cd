// The report's morph section on a hand-made report.json: every cell is the figure,
// ops row or ISA row it names, the per-target ops are the delta floats (bytes / 4), the default
// is marked, and a report without `morph` says how to get one.
#include <gtest/gtest.h>

#include "harness/document/report_morph.h"
#include "harness/figures/figure.h"

using json = nlohmann::json;
using namespace mb;

namespace {

json figureJson(const std::string& name, double value, const std::string& unit) {
  figures::Figure f;
  f.name = name;
  f.value = value;
  f.unit = unit;
  f.statistic = "minimum over frames";
  f.n = 3;
  return figures::toJson(f);
}

json isaShader(const std::string& pipeline, const std::string& label, const std::string& family, int instr, int vgprs) {
  return {{"stage", "vertex"}, {"pipeline", pipeline}, {"variant", label}, {"labels", {label}},
          {"familyId", family}, {"instructions", instr}, {"vgprs", vgprs}};
}

json ops(int mul, int add) { return {{"mul", mul}, {"add", add}, {"div", 0}, {"sqrt", 0}, {"other", 0}}; }

json handReport() {
  json morph = {{"schema", "motorbench-morph/1"}, {"size", 64}, {"motorDefault", "motor_frame"}};
  morph["methods"] = {{{"id", "matrix"}, {"pipeline", "matrix"}, {"method", "deltas"}, {"program", "rigid, morph"}},
                      {{"id", "motor_frame"}, {"pipeline", "motor"}, {"method", "(a)"}, {"program", "rigid, morph frame (a)"}},
                      {{"id", "motor_rotor"}, {"pipeline", "motor"}, {"method", "(b)"}, {"program", "rigid, morph rotor (b)"}}};
  morph["scenes"] = {{{"scene", "a.glb"}, {"frames", json::array({json::object(), json::object()})}}};
  json& f = morph["figures"];
  f["morph.bytes_per_vertex.matrix"] = figureJson("morph.bytes_per_vertex.matrix", 48, "bytes");
  f["morph.bytes_per_target_vertex.matrix"] = figureJson("morph.bytes_per_target_vertex.matrix", 36, "bytes");
  f["morph.bytes_per_target_vertex.motor_rotor"] = figureJson("morph.bytes_per_target_vertex.motor_rotor", 28, "bytes");
  f["morph.worst_psnr.rigid.motor_rotor"] = figureJson("morph.worst_psnr.rigid.motor_rotor", 29.9, "dB");
  morph["worst"]["morph.worst_psnr.rigid.motor_rotor"] = {{"scene", "/x/morphing.gltf"}, {"anim", 2}, {"time", 0.5}};
  json r = {{"morph", morph}};
  r["opsPerVertex"]["kernels"] = {{{"function", "morphRotorBlend"}, {"counted", ops(9, 7)}}};
  r["opsPerVertex"]["variants"] = {{{"pipeline", "motor"}, {"label", "rigid, morph rotor (b)"}, {"spirv", ops(90, 70)}},
                                   {{"pipeline", "motor"}, {"label", "rigid"}, {"spirv", ops(74, 56)}}};
  r["isa"]["families"] = {{{"id", "tahiti"}}, {{"id", "navi10"}}, {{"id", "gfx1100"}}};
  r["isa"]["shaders"] = {isaShader("motor", "rigid, morph rotor (b)", "tahiti", 260, 28),
                         isaShader("motor", "rigid", "tahiti", 122, 24),
                         isaShader("motor", "rigid, morph rotor (b)", "gfx1100", 303, 36)};
  return r;
}

}  // namespace

TEST(ReportMorph, CellsQuoteTheirFiguresAndRows) {
  const json r = handReport();
  EXPECT_EQ(document::morphIsaFamilies(r), (std::vector<std::string>{"tahiti", "gfx1100"}));
  const auto rows = document::morphTable(r);
  ASSERT_EQ(rows.size(), 4u);  // header + three methods
  const auto& header = rows[0];
  auto col = [&](const std::string& name) {
    for (size_t i = 0; i < header.size(); ++i)
      if (header[i].rfind(name, 0) == 0) return i;
    ADD_FAILURE() << "no column " << name;
    return size_t(0);
  };
  const auto& matrix = rows[1];
  const auto& frame = rows[2];
  const auto& rotor = rows[3];
  EXPECT_EQ(matrix[col("bytes per vertex")], "48 bytes");
  EXPECT_EQ(matrix[col("bytes per target")], "36 bytes");
  EXPECT_EQ(frame[col("bytes per vertex")], "-");  // no figure: not invented
  EXPECT_NE(frame[0].find("(motor default)"), std::string::npos);
  EXPECT_EQ(rotor[0].find("(motor default)"), std::string::npos);
  // 28 bytes per target vertex = 7 delta floats, each one mul and one add per target.
  const std::string rotorOps = rotor[col("counted ops")];
  EXPECT_EQ(rotorOps.rfind("9 mul / 7 add", 0), 0u) << rotorOps;
  EXPECT_NE(rotorOps.find("+ 7 mul + 7 add per target"), std::string::npos) << rotorOps;
  EXPECT_NE(matrix[col("counted ops")].find("+ 9 mul + 9 add per target"), std::string::npos);
  EXPECT_EQ(rotor[col("SPIR-V")], "90 mul / 70 add (74 mul / 56 add)");
  EXPECT_EQ(rotor[col("ISA tahiti")], "260 / 28 (rigid 122 / 24)");
  EXPECT_EQ(rotor[col("ISA gfx1100")], "303 / 36");  // no rigid row for that family
  EXPECT_EQ(frame[col("ISA tahiti")], "-");
  EXPECT_EQ(rotor[col("worst PSNR vs matrix")], "29.9 dB");
  EXPECT_EQ(rotor[col("worst frame")], "morphing.gltf anim 2 t 0.5");
  EXPECT_EQ(matrix[col("worst PSNR vs matrix")], "baseline");
}

// The default method's sentence says what its figures say (worst PSNR and max error against
// matrix over n frames), not that it is exact.
TEST(ReportMorph, TheDefaultMethodIsDescribedByItsFigures) {
  json r = handReport();
  json& f = r["morph"]["figures"];
  f["morph.worst_psnr.rigid.motor_frame"] = figureJson("morph.worst_psnr.rigid.motor_frame", 56.7, "dB");
  f["morph.max_error.rigid.motor_frame"] = figureJson("morph.max_error.rigid.motor_frame", 0.129, "of 1");
  document::Document d;
  document::morphSection(d, r);
  std::string text;
  for (const auto& b : d.blocks) text += b.text + "\n";
  EXPECT_EQ(text.find("exact where matrix is"), std::string::npos) << text;
  EXPECT_NE(text.find("56.7 dB"), std::string::npos) << text;
  EXPECT_NE(text.find("0.129 of 1"), std::string::npos) << text;
  EXPECT_NE(text.find("over 3 frames"), std::string::npos) << text;  // the figures' n
  const auto rows = document::morphTable(r);
  EXPECT_EQ(rows[2].back().rfind("exact", 0), std::string::npos) << rows[2].back();
}

TEST(ReportMorph, WithoutMorphJsonTheSectionSaysHowToMeasure) {
  document::Document d;
  document::morphSection(d, json{{"opsPerVertex", json::object()}});
  bool told = false;
  for (const auto& b : d.blocks) told = told || b.text.find("motorbench report --morph-json") != std::string::npos;
  EXPECT_TRUE(told);
  EXPECT_EQ(document::morphTable(json::object()).size(), 1u);  // the header only
}
