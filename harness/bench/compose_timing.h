// Composition of two transforms, timed side by side in one process (the claims' `composition`
// row): the motor product gp_mm, the 4x4 product (matrix_transform.glsl's matrixCompose) and
// the affine mat4x3 product (harness/bench/affine_compose.h), each the shader source compiled
// through the shim with float, plus GLM's own mat4 and affine (mat3 + vec3) products and a plain
// 12-float affine product. Rounds interleave the sides in rotating order, so drift and other
// processes fall on all alike; each side's figure is the median over rounds, each ratio the
// median of the per-round ratios.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace mb::bench {

struct ComposeTiming {
  std::vector<std::string> sides;              // in timing order, "motor" first
  std::map<std::string, double> nsPerCompose;  // median over rounds
  std::map<std::string, double> ratioToMotor;  // median over rounds of side time / motor time
  int rounds = 0, pairs = 0, repeats = 0;      // repeats: passes over the pairs per block
};

// Side names: "motor" (gp_mm), "mat4" (matrixCompose), "affine" (affineCompose), "glm_mat4",
// "glm_affine", "affine_plain" (the affine product on 12 plain floats, hand-written C++). `rounds` >= 1; each block lasts at least about `blockMs` milliseconds.
ComposeTiming timeCompositions(int rounds = 15, double blockMs = 2.0);

}  // namespace mb::bench
