// The affine mat4x3 product the bench and the ops table count (harness/bench/affine_compose.h)
// equals GLM's 4x4 product of the same two matrices.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "harness/bench/affine_compose.h"

using namespace mb;

TEST(AffineCompose, EqualsGlmsProduct) {
  using M = MatrixShader<double>;
  M::mat4x3 a, b;
  glm::dmat4 ga(1.0), gb(1.0);
  for (int col = 0; col < 4; ++col)
    for (int r = 0; r < 3; ++r) {
      a[col][r] = ga[col][r] = 0.3 + 0.4 * col - 0.25 * r * r;
      b[col][r] = gb[col][r] = -0.2 + 0.3 * col * r + 0.15 * r;
    }
  const M::mat4x3 x = bench::affineCompose<double>(a, b);
  const glm::dmat4 g = ga * gb;
  for (int col = 0; col < 4; ++col)
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(x[col][r], g[col][r], 1e-12) << col << "," << r;
}
