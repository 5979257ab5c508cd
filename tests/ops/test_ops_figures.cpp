// ops.json's "figures" (harness/ops/ops_figures.h): the counts claims reads by name, checked
// against values derived by hand, and each figure stating what it is.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "harness/figures/figure.h"
#include "harness/ops/op_kernels.h"
#include "harness/ops/ops_figures.h"

namespace {

using nlohmann::json;

// Counted only (no SPIR-V compile): well under a second.
const json& countedFigures() {
  static const json f = mb::ops::opsFigures(mb::ops::measureAll(mb::ops::allKernels()),
                                            mb::opsv::measureVertexOps(mb::opsv::SpirvDepth::None));
  return f;
}

double value(const std::string& name) {
  const auto f = mb::figures::figureNamed(countedFigures(), name);
  EXPECT_TRUE(f.has_value()) << name;
  return f ? f->value : std::nan("");
}

struct Cols { double mul, add, div, sqrt, other; };

void expectColumns(const std::string& prefix, Cols want) {
  EXPECT_EQ(value(prefix + ".mul"), want.mul) << prefix;
  EXPECT_EQ(value(prefix + ".add"), want.add) << prefix;
  EXPECT_EQ(value(prefix + ".div"), want.div) << prefix;
  EXPECT_EQ(value(prefix + ".sqrt"), want.sqrt) << prefix;
  EXPECT_EQ(value(prefix + ".other"), want.other) << prefix;
  EXPECT_EQ(value(prefix + ".total"), want.mul + want.add + want.div + want.sqrt + want.other) << prefix;
}

}  // namespace

TEST(OpsFigures, KernelsMatchHandDerivedCounts) {
  expectColumns("kernel.gp_mm", {48, 40, 0, 0, 0});
  // A 4x4 matrix times a vector: 4 rows of 4 products and 3 sums.
  expectColumns("kernel.mat4*vec4", {16, 12, 0, 0, 0});
  // The affine product: mat3 * mat3 (27 mul, 18 add), mat3 * vec3 (9, 6), + translation (3 add).
  expectColumns("kernel.mat4x3*mat4x3", {36, 27, 0, 0, 0});
  // Names with '*' and ':' stay as the table prints them.
  expectColumns("kernel.E:gp_mm_k", {48, 40, 0, 0, 0});
}

TEST(OpsFigures, PrintedListingAsRecountedByHand) {
  // paper_normalize_m recounted from the printed listing: 24 mul, 10 add, 1 div, 1 sqrt.
  expectColumns("listing.normalize_m", {24, 10, 1, 1, 0});
  // paper_log_m: the listing's own comment, 14 mul, 5 add, 1 div, 1 sqrt, 1 acos.
  expectColumns("listing.log_m", {14, 5, 1, 1, 1});
}

TEST(OpsFigures, PiecesClaimsQuote) {
  // (x, y, z, w) -> [w, -x, -y, -z]: three sign changes, free.
  expectColumns("kernel.quat_to_rotor", {0, 0, 0, 0, 0});
  // sw_mp 21/18 + gp_rr 16/12 + extractNormalTangent 9/8 + sign(1/x) (1 div, 1 sign).
  expectColumns("kernel.motor_vertex_frame", {46, 38, 1, 0, 1});
  expectColumns("kernel.three_mat4*vec4", {48, 36, 0, 0, 0});
  // The uniform scale: position * scale, a vec3 times a float.
  expectColumns("kernel.uniform_scale_overhead", {3, 0, 0, 0, 0});
  // The Sample Viewer's vertex: three mat4 * vec4 + w * sign(det) for the handedness.
  expectColumns("vertex.matrixRigidVertex", {49, 36, 0, 0, 0});
  expectColumns("vertex.motorRigidVertex", {49, 38, 1, 0, 1});
}

TEST(OpsFigures, EachFigureSaysWhatItIs) {
  const auto f = mb::figures::figureNamed(countedFigures(), "kernel.gp_mm.mul");
  ASSERT_TRUE(f);
  EXPECT_EQ(f->statistic, "counted once on the op-counting scalar");
  EXPECT_EQ(f->unit, "ops");
  EXPECT_EQ(f->n, 1);
  EXPECT_EQ(f->device, "op-counting scalar (mb::Counted through the GLSL shim)");
  EXPECT_NE(f->definition.find("motor * motor"), std::string::npos) << f->definition;
  // Every kernel of the table has its six figures.
  for (const mb::ops::Kernel& k : mb::ops::allKernels())
    for (const char* col : {"mul", "add", "div", "sqrt", "other", "total"})
      EXPECT_TRUE(mb::figures::figureNamed(countedFigures(), "kernel." + k.name + "." + col)) << k.name << " " << col;
}

TEST(OpsFigures, MissingSpirvIsNamedNotZero) {
  // This run compiled no SPIR-V: the figure is there, not measured, and says why.
  const auto f = mb::figures::figureNamed(countedFigures(), "variant.matrix.rigid.spirv.total");
  ASSERT_TRUE(f);
  EXPECT_TRUE(std::isnan(f->value));
  EXPECT_FALSE(f->why.empty());
  EXPECT_EQ(value("variant.matrix.rigid.counted.total"), value("vertex.matrixRigidVertex.total") +
                                                              value("vertex.matrixWorldToClip.total"));
}

TEST(OpsFigures, FunctionsCountedForSeveralPipelinesAreNamedByPipeline) {
  EXPECT_FALSE(mb::figures::figureNamed(countedFigures(), "vertex.curvedMatrixVertex.total"));
  EXPECT_TRUE(mb::figures::figureNamed(countedFigures(), "vertex.curvedMatrixVertex.s3_matrix.total"));
  EXPECT_TRUE(mb::figures::figureNamed(countedFigures(), "vertex.curvedMatrixVertex.h3_matrix.total"));
  EXPECT_EQ(mb::ops::figureLabel("skinned, world palette"), "skinned_world_palette");
  EXPECT_EQ(mb::ops::figureLabel("rigid, morph frame (a)"), "rigid_morph_frame_a");
}

TEST(OpsFigures, ListingLinesExplainEveryDisagreement) {
  const std::string text = mb::ops::formatListings(mb::ops::measureAll(mb::ops::allKernels()));
  EXPECT_NE(text.find("log_m: ours 14/6, the paper 14/5, its printed listing 14/5 (= the paper): ours rewrites"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("normalize_m: ours 22/10, the paper 21/5, its printed listing 24/10 (not the paper's figure"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("exp_b: ours"), std::string::npos) << "exp_b agrees: no line";
}
