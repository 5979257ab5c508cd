// Counted ops per vertex (harness/ops/ops_vertex.h) against hand-derived values: the pipelines'
// per-vertex GLSL functions executed on mb::Counted through the shim. The motor side is also
// checked to be exactly the sum of the toolbox kernels it is composed of.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "harness/ops/ops_vertex.h"

namespace {

using mb::Counted;
using mb::OpCounts;
using mb::countOps;

struct Expect {
  uint64_t mul, add, div = 0, sqrt = 0, other = 0;
};

void expectCounts(const OpCounts& c, const Expect& e, const std::string& what) {
  EXPECT_EQ(c.mul, e.mul) << what;
  EXPECT_EQ(c.add, e.add) << what;
  EXPECT_EQ(c.div, e.div) << what;
  EXPECT_EQ(c.sqrt, e.sqrt) << what;
  EXPECT_EQ(c.other, e.other) << what;
}

std::map<std::string, OpCounts> countedByFunction() {
  std::map<std::string, OpCounts> m;
  for (const auto& k : mb::opsv::vertexKernels()) m[k.function] = mb::opsv::countVertexKernel(k);
  return m;
}

OpCounts sum(std::initializer_list<OpCounts> parts) {
  OpCounts s;
  for (const OpCounts& p : parts) {
    s.mul += p.mul, s.add += p.add, s.div += p.div, s.sqrt += p.sqrt, s.other += p.other;
    for (size_t i = 0; i < s.fn.size(); ++i) s.fn[i] += p.fn[i];
  }
  return s;
}

TEST(VertexOps, MatrixKernelsMatchHandDerivedCounts) {
  auto c = countedByFunction();
  // mat4 * vec4 = 16 mul, 12 add; the Sample Viewer does three per vertex (48/36) and its
  // mirrored-node handedness fix multiplies the tangent's w once.
  expectCounts(c["matrixRigidVertex"], {49, 36}, "matrix rigid vertex with frame");
  // Two palettes blended (4 x 16 mul, 3 x 16 add each), two sets of three products, handedness.
  expectCounts(c["matrixSkinnedVertex"], {2 * 64 + 2 * 48 + 1, 2 * 48 + 2 * 36}, "matrix skinned");
  expectCounts(c["matrixBlendJoints"], {64, 48}, "matrix joint blend");
  expectCounts(c["matrixWorldToClip"], {16, 12}, "matrix world to clip");
  // Affine: 3x3 * p + t (9/9), mat3 * n (9/6), 3x3 * t (9/6), handedness (1/0).
  expectCounts(c["matrixAffineVertex"], {28, 21}, "matrix affine rigid vertex");

  mb::MatrixShader<Counted> M;
  const auto& in = mb::opsv::detail::inputs();
  OpCounts frame = countOps([&] {
    M.matrixTransformFrame(in.model, in.normal, in.world, in.world, in.world);
  });
  expectCounts(frame, {48, 36}, "the paper's matrix baseline: three mat4 * vec4");
}

TEST(VertexOps, MotorRigidVertexIsTheSumOfItsKernels) {
  auto c = countedByFunction();
  mb::MotorShader<Counted> P;
  const auto& in = mb::opsv::detail::inputs();
  const OpCounts swmp = countOps([&] { P.sw_mp(in.toWorld, in.position); });
  const OpCounts gprr = countOps([&] { P.gp_rr(in.toWorld, in.toWorld); });
  const OpCounts ent = countOps([&] { P.extractNormalTangent(in.toWorld); });
  const OpCounts hand = countOps([&] { P.motorHandedness(in.rotor); });
  const OpCounts scale = countOps([&] { (void)(in.position * Counted(2.0)); });
  expectCounts(swmp, {21, 18}, "sw_mp (paper 21/18)");
  expectCounts(gprr, {16, 12}, "gp_rr (paper 16/12)");
  expectCounts(ent, {9, 8}, "extractNormalTangent (paper 9/8)");
  expectCounts(hand, {0, 0, 1, 0, 1}, "handedness sign(1/x)");
  expectCounts(scale, {3, 0}, "uniform scale of the position");
  const OpCounts composed = sum({swmp, gprr, ent, hand, scale});
  EXPECT_EQ(c["motorRigidVertex"], composed);
  // The paper's 47 mul / 38 add has no position scale (3 mul) and counts the handedness as 1
  // mul where the shader divides and takes a sign: 49 mul, 38 add, 1 div, 1 sign.
  expectCounts(c["motorRigidVertex"], {49, 38, 1, 0, 1}, "motor rigid vertex with frame");
}

TEST(VertexOps, MotorSkinnedVertexIsBlendPlusRigid) {
  auto c = countedByFunction();
  mb::MotorShader<Counted> P;
  const auto& in = mb::opsv::detail::inputs();
  const OpCounts norm = countOps([&] { P.normalize_m(in.joints[1]); });
  expectCounts(norm, {22, 10, 0, 0, 1}, "normalize_m");
  // Blend: 3 shortest-arc dots (4 mul, 3 add each), 4 motors x weight (8 mul each), 3 motor
  // sums (8 add each), then normalize_m.
  expectCounts(c["motorBlendJoints"], {3 * 4 + 4 * 8 + 22, 3 * 3 + 3 * 8 + 10, 0, 0, 1},
               "motor joint blend");
  EXPECT_EQ(c["motorSkinnedVertex"], sum({c["motorBlendJoints"], c["motorRigidVertex"]}));
}

TEST(VertexOps, MotorWorldToClipIsSandwichPlusProject) {
  auto c = countedByFunction();
  mb::MotorShader<Counted> P;
  const OpCounts proj = countOps([&] {
    P.project(0.05, 100.0, 0.8, 1.5, mb::MotorShader<Counted>::vec3(1.0, 2.0, 3.0));
  });
  // project(): cot(fov/2) = cos(0.5 f)/sin(0.5 f) (2 mul, 1 div), fa = 2 f n / (n - f) (2 mul,
  // 1 add, 1 div), fb = (n + f)/(n - f) (2 add, 1 div), fit = cthf * (-1/aspect, 1) (2 mul,
  // 1 div), per vertex xy * fit (2 mul) and fa - fb z (1 mul, 1 add).
  expectCounts(proj, {9, 4, 4, 0, 2}, "project");
  expectCounts(c["motorWorldToClip"], {21 + 9, 18 + 4, 4, 0, 2}, "motor world to clip");
}

TEST(VertexOps, EveryVariantNamesCountedKernels) {
  auto c = countedByFunction();
  for (const auto& v : mb::opsv::shaderVariants())
    for (const std::string& fn : v.kernels) EXPECT_TRUE(c.count(fn)) << v.file << " " << fn;
}

}  // namespace

namespace {

// Symmetric skinning: the skinned vertex in both configurations for both pipelines, and the matrix
// vertex without a tangent, from hand-derived counts (mat4 * vec4 = 16/12, blend = 64/48).
TEST(VertexOps, SymmetricSkinningAndNoTangentVariants) {
  auto c = countedByFunction();
  // Without tangent: position and normal products only.
  expectCounts(c["matrixRigidVertexNoTangent"], {2 * 16, 2 * 12}, "matrix rigid, no tangent");
  expectCounts(c["matrixSkinnedVertexNoTangent"], {2 * 64 + 4 * 16, 2 * 48 + 4 * 12},
               "matrix skinned (reference), no tangent");
  // World-space palette: the blends and one set of three products (+ handedness).
  expectCounts(c["matrixSkinnedVertexWorld"], {2 * 64 + 3 * 16 + 1, 2 * 48 + 3 * 12},
               "matrix skinned, world palette");
  expectCounts(c["matrixSkinnedVertexWorldNoTangent"], {2 * 64 + 2 * 16, 2 * 48 + 2 * 12},
               "matrix skinned, world palette, no tangent");
  // The reference configuration adds the model matrix's three products (48/36) to the
  // matrix vertex and gp_mm (48/40) to the motor vertex.
  mb::MotorShader<Counted> P;
  const auto& in = mb::opsv::detail::inputs();
  const OpCounts gpmm = countOps([&] { P.gp_mm(in.toWorld, in.toWorld); });
  expectCounts(gpmm, {48, 40}, "gp_mm");
  EXPECT_EQ(c["motorSkinnedVertexReference"], sum({c["motorSkinnedVertex"], gpmm}));
  const OpCounts m = c["matrixSkinnedVertex"], w = c["matrixSkinnedVertexWorld"];
  EXPECT_EQ(m.mul - w.mul, 48u);
  EXPECT_EQ(m.add - w.add, 36u);
}

TEST(VertexOps, BothSkinnedConfigurationsAreVariantsOfBothPipelines) {
  for (const char* pipeline : {"matrix", "motor"})
    for (const char* label : {"skinned, reference", "skinned, world palette"}) {
      bool found = false;
      for (const auto& v : mb::opsv::shaderVariants())
        found = found || (v.pipeline == pipeline && v.label == label);
      EXPECT_TRUE(found) << pipeline << " " << label;
    }
}

// Bezier patches: the shared evaluation and each pipeline's frame, by hand.
TEST(VertexOps, PatchKernelsMatchHandDerivedCounts) {
  auto c = countedByFunction();
  // Bases 2 x (8/1) + 2 x (6/1); four rows 4 x (21/24); P and dP/du 2 x (12/9); dP/dv 9/15;
  // two squared lengths 6/4; the relative degenerate test 2 mul (an interior vertex).
  expectCounts(c["bezierPatch"], {153, 137}, "bezierPatch");
  // cross 6/3 + three mat4 * vec4 48/36 + handedness 1/0.
  expectCounts(c["matrixPatchVertex"], {55, 39}, "matrixPatchVertex");
  // affine_patch.vs: cross 6/3 + mat4x3 point 9/9, mat3 normal 9/6, tangent 9/6, w 1/0.
  expectCounts(c["affinePatchVertex"], {6 + 28, 3 + 21}, "affinePatchVertex");
  // (a): sw_mp 21/18 after the scale 3/0, two sw_md 2 x (18/12), cross 6/3.
  expectCounts(c["motorPatchVertex"], {66, 45}, "motorPatchVertex");
  // (a) scaled: three scalings 9/0, sw_mp 21/18, two sw_md 36/24, cross 6/3, mirror = sign of
  // a product 2/0 + 1 other, mirror * normal 3/0.
  expectCounts(c["motorScaledPatchVertex"], {77, 45, 0, 0, 1}, "motorScaledPatchVertex");
  // (b) at these inputs (frame trace > 0): normalize(dP/du) 6/2 + 1 inversesqrt; cross 6/3
  // and its normalize 6/2 + 1 inversesqrt; frameRotor: bitangent cross 6/3, trace 0/2,
  // 0.5 inversesqrt(trace + 1) 1/1 + 1 inversesqrt, three differences times s 3/3, 0.25 / s
  // 1 div; gp_rr 16/12; extractNormalTangent 9/8; sw_mp 21/18 after the scale 3/0.
  const OpCounts b = c["motorPatchVertexRotor"];
  expectCounts(b, {77, 54, 1, 0, 3}, "motorPatchVertexRotor (b)");
  EXPECT_GT(b.mul + b.add, 66u + 45u) << "(a) is the cheaper frame, the one drawn";
}

}  // namespace
