// What each printed figure is, on hand-made report.json pieces: the kernel table's ratios are
// time motor / matrix (the summary's convention) and say how each time was taken; a curved
// pipeline's op figures name their scope (the instance transform, the projection left out);
// the fragment stage's figures are the isa rows and kernels they name; hybrid's GPU side is
// qtangent's (the design-space plot marks it apart).
#include <gtest/gtest.h>

#include "harness/document/report_answer_figures.h"
#include "harness/document/report_figures.h"
#include "harness/document/report_layout_sections.h"
#include "harness/document/report_model.h"
#include "harness/figures/figure.h"

using json = nlohmann::json;
using namespace mb;

namespace {

json side(double itemsPerSecond, int repetitions) {
  return {{"items_per_second", itemsPerSecond}, {"repetitions", repetitions}};
}

// compose: the shim matrix at 2e8 items/s, the shim motor at 1e8 (twice the time per item); the
// fastest matrix (simd_affine) at 4e8, the fastest motor (simd_motor) at 8e8 (half the time).
json kernels() {
  json p = {{"pair", "compose"}, {"kernel", "compose"}, {"size", nullptr}, {"matrix", side(2e8, 3)},
            {"motor", side(1e8, 3)}, {"simd_affine", side(4e8, 3)}, {"simd_motor", side(8e8, 3)},
            {"ratio_motor_matrix", 0.5}, {"ratio_motor_fastest_matrix", 2.0}, {"fastest_motor", "simd_motor"},
            {"fastest_matrix", "simd_affine"}};
  return {{"pairs", json::array({p})}, {"probe", json::array()}, {"context", json::object()}, {"error", nullptr},
          {"source", "file"}, {"file", "bench.json"}};
}

std::string markdownOf(const document::Document& d) { return document::toMarkdown(d); }

}  // namespace

TEST(ReportScopes, KernelRatiosAreTimeMotorOverMatrixWithTheirRepetitions) {
  json r = {{"kernels", kernels()}, {"machine", json::object()}};
  r["figures"] = document::reportFigures(json::object(), json::object(), {}, json::object(), r["kernels"]);
  const auto shim = figures::figureNamed(r, "kernel_time.compose.shim_motor_over_shim_matrix");
  const auto fastest = figures::figureNamed(r, "kernel_time.compose.fastest_motor_over_fastest_matrix");
  ASSERT_TRUE(shim && fastest);
  EXPECT_DOUBLE_EQ(shim->value, 2.0);      // 2e8 / 1e8: the motor takes twice the time
  EXPECT_DOUBLE_EQ(fastest->value, 0.5);   // 4e8 / 8e8: half the time
  EXPECT_NE(shim->statistic.find("the median of 3 repetitions"), std::string::npos) << shim->statistic;
  document::Document d;
  document::kernelSection(d, r);
  const std::string md = markdownOf(d);
  EXPECT_NE(md.find("time motor / matrix (shim sources)"), std::string::npos) << md;
  EXPECT_NE(md.find("<span title=\"kernel_time.compose.shim_motor_over_shim_matrix\">2x</span>"), std::string::npos) << md;
  EXPECT_NE(md.find("<span title=\"kernel_time.compose.fastest_motor_over_fastest_matrix\">0.5x</span> (simd_motor / simd_affine)"),
            std::string::npos) << md;
  EXPECT_EQ(md.find("> 1 means faster"), std::string::npos) << md;  // no items/s convention left
  EXPECT_NE(md.find("median of 3 repetitions"), std::string::npos) << md;
}

TEST(ReportScopes, ABenchWithoutRepetitionsSaysSo) {
  json k = kernels();
  for (const char* s : {"matrix", "motor", "simd_affine", "simd_motor"}) k["pairs"][0][s].erase("repetitions");
  const json f = document::reportFigures(json::object(), json::object(), {}, json::object(), k);
  const auto shim = figures::figureNamed(f, "kernel_time.compose.shim_motor_over_shim_matrix");
  ASSERT_TRUE(shim);
  EXPECT_NE(shim->statistic.find("not recorded"), std::string::npos) << shim->statistic;
}

TEST(ReportScopes, ACurvedPipelinesOpsNameTheInstanceTransform) {
  const json counted = {{"mul", 64}, {"add", 48}, {"div", 0}, {"sqrt", 0}, {"other", 0}};
  const json row = {{"rigid", {{"counted", counted}, {"spirv", counted}}}, {"toClip", {{"counted", counted}, {"spirv", counted}}}};
  json ops = {{"perPipeline", json::array({json(row), json(row)})}};
  ops["perPipeline"][0]["pipeline"] = "s3_matrix";
  ops["perPipeline"][1]["pipeline"] = "matrix";
  const json f = document::reportFigures(json::object(), json::object(), {}, ops, json::object());
  const auto curved = figures::figureNamed(f, "ops_per_vertex.to_clip.counted.s3_matrix");
  const auto euclid = figures::figureNamed(f, "ops_per_vertex.to_clip.counted.matrix");
  ASSERT_TRUE(curved && euclid);
  EXPECT_DOUBLE_EQ(curved->value, 112);
  EXPECT_NE(curved->scope.find("projection left out"), std::string::npos) << curved->scope;
  EXPECT_EQ(euclid->scope, "rigid vertex with frame, object to clip");
  const auto probe = figures::figureNamed(f, "ops_per_vertex.rigid.spirv_probe.matrix");
  ASSERT_TRUE(probe);
  EXPECT_EQ(probe->device.rfind("SPIR-V probe", 0), 0u) << probe->device;
}

TEST(ReportScopes, FragmentFiguresAreTheirIsaRowsAndKernels) {
  json r = {{"settings", {{"pipelines", {"matrix", "motor_cf"}}}}, {"scenes", json::array()}};
  r["isa"]["families"] = {{{"id", "polaris10"}, {"generation", "GCN 4"}}};
  r["isa"]["shaders"] = {
      {{"stage", "vertex"}, {"pipeline", "motor_cf"}, {"labels", {"rigid"}}, {"familyId", "polaris10"},
       {"instructions", 139}, {"vgprs", 24}, {"varyingSlots", 5}, {"varyingComponents", 16}},
      {{"stage", "fragment"}, {"pipeline", "motor_cf"}, {"labels", {"rigid"}}, {"familyId", "polaris10"},
       {"instructions", 570}, {"vgprs", 36}}};
  r["opsPerVertex"]["kernels"] = {{{"function", "rotorShadingNormal"}, {"counted", {{"mul", 48}, {"add", 22}, {"other", 2}}}},
                                  {{"function", "tbnShadingNormal"}, {"counted", {{"mul", 51}, {"add", 22}, {"other", 3}}}}};
  document::addAnswerFigures(r);
  auto value = [&](const std::string& name) {
    const auto f = figures::figureNamed(r, name);
    return f ? f->value : -1.0;
  };
  EXPECT_EQ(value("isa.fragment_instructions.rigid.polaris10.motor_cf"), 570);
  EXPECT_EQ(value("isa.fragment_vgprs.rigid.polaris10.motor_cf"), 36);
  EXPECT_EQ(value("varyings.slots.motor_cf"), 5);
  EXPECT_EQ(value("varyings.components.motor_cf"), 16);
  EXPECT_EQ(value("ops_per_fragment.shading_normal.normal_mapped.motor_cf"), 48 + 22 + 2);  // the rotor's
  EXPECT_EQ(value("ops_per_fragment.shading_normal.normal_mapped.matrix"), 51 + 22 + 3);    // the TBN's
  const auto none = figures::figureNamed(r, "isa.fragment_instructions.rigid.polaris10.matrix");
  ASSERT_TRUE(none);  // no row for matrix: a figure that says so, no value
  EXPECT_EQ(none->n, 0);
}

TEST(ReportScopes, HybridDrawsWithQtangentsGpuSide) {
  EXPECT_EQ(document::gpuSideOf("hybrid"), "qtangent");
  for (const char* p : {"qtangent", "matrix", "affine", "motor", "motor_q", "matrix_c", "motor_c", "motor_cf", "s3_motor"})
    EXPECT_EQ(document::gpuSideOf(p), "") << p;
  json r = {{"settings", {{"pipelines", {"matrix", "qtangent", "hybrid"}}}}, {"scenes", json::array()}};
  document::addAnswerFigures(r);
  EXPECT_EQ(r["pipelineGpuSides"], json({{"hybrid", "qtangent"}}));
  EXPECT_EQ(r["pipelineFamilies"]["hybrid"], "motor");  // its CPU side: it poses with motors
}
