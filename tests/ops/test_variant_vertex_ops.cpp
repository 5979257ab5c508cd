// Ops per vertex of the issue-16 kernels, counted through the shim, against hand-derived
// counts: a mat4x3 * point is 9 mul / 9 add, a mat3 * vector 9 / 6, a cross product 6 / 3,
// the blend of four mat4x3 48 / 36, the quaternion's two columns 12 / 8 (+ sign), and the
// motor world to clip with per-frame constants the sandwich plus 3 mul / 1 add.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "harness/ops/ops_vertex.h"

using namespace mb;

namespace {

std::map<std::string, OpCounts> counted() {
  std::map<std::string, OpCounts> out;
  for (const opsv::VertexKernel& k : opsv::vertexKernels()) out[k.function] = opsv::countVertexKernel(k);
  return out;
}

void expectCounts(const OpCounts& c, uint64_t mul, uint64_t add, uint64_t other, const std::string& what) {
  EXPECT_EQ(c.mul, mul) << what;
  EXPECT_EQ(c.add, add) << what;
  EXPECT_EQ(c.div, 0u) << what;
  EXPECT_EQ(c.sqrt, 0u) << what;
  EXPECT_EQ(c.other, other) << what;
}

}  // namespace

TEST(VariantVertexOps, AffineKernelsMatchHandDerivedCounts) {
  auto c = counted();
  expectCounts(c["matrixAffineVertex"], 28, 21, 0, "position 9/9 + normal 9/6 + tangent 9/6 + w 1/0");
  expectCounts(c["affineBlendJoints"], 48, 36, 0, "4 x 12 mul, 3 x 12 add");
  expectCounts(c["affineAdjugateVertex"], 28 + 18, 21 + 9, 0, "cofactor (3 cross) + affine vertex");
  expectCounts(c["affineSkinnedVertex"], 48 + 18 + 28, 36 + 9 + 21, 0, "blend + cofactor + affine");
  expectCounts(c["affineSkinnedNormalsVertex"], 48 + 36 + 28, 36 + 27 + 21, 0,
               "blend + mat3 blend + affine");
  expectCounts(c["qtangentFrame"], 12, 8, 1, "q.xyz * 2, nine products, two columns, sign(w)");
  expectCounts(c["qtangentRigidVertex"], 12 + 28, 8 + 21, 1, "decode + affine vertex");
  expectCounts(c["qtangentSkinnedVertex"], 12 + 94, 8 + 66, 1, "decode + skinned affine");
  // The 8-float vertex without tangent, as matrix.vs's MB_NO_TANGENT.
  expectCounts(c["affineVertexNoTangent"], 9 + 9, 9 + 6, 0, "position 9/9 + normal 9/6");
  expectCounts(c["affineSkinnedVertexNoTangent"], 48 + 18 + 18, 36 + 9 + 15, 0, "blend + cofactor + position, normal");
}

TEST(VariantVertexOps, WorldToClipWithConstantsIsTheSandwichPlusThreeMul) {
  auto c = counted();
  const OpCounts& k = c["motorWorldToClipConstants"];
  const OpCounts& paper = c["motorWorldToClip"];
  // The paper's form: the same sandwich, plus project()'s constants recomputed per vertex.
  EXPECT_EQ(k.mul, 21u + 3u);
  EXPECT_EQ(k.add, 18u + 1u);
  EXPECT_EQ(k.div + k.sqrt + k.other, 0u);
  EXPECT_GT(paper.mul, k.mul);
  EXPECT_GT(paper.div, 0u);
}
