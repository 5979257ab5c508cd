// The "figures" object of ops.json: every count `motorbench ops` makes, as named figures
// (harness/figures/figure.h) that claims and documents read by name instead of counting again.
//   kernel.<name>.<col>       every kernel of op_kernels.h (the "kernels" table), and the pieces
//                             of op_kernels_pieces.h (conversion, affine composition, the vertex
//                             frame by the paper's pieces, the uniform scale's overhead)
//   listing.<name>.<col>      the paper's printed listings (op_kernels_listings.h)
//   vertex.<function>.<col>   every counted per-vertex function (ops_vertex.h); a function counted
//                             for several pipelines (curved space) is vertex.<function>.<pipeline>;
//                             vertex.<...>.spirv.<col>: its probe shader in optimised SPIR-V
//   variant.<pipeline>.<label>.counted|spirv.<col>
//                             every vertex-shader variant: the sum of its counted kernels, and
//                             the whole shader (main() included) in optimised SPIR-V
// <col> is mul, add, div, sqrt, other or total (their sum). Labels and pipeline lists are
// written with '_' for every run of other characters ("skinned, world palette" ->
// skinned_world_palette). Per pipeline and kind (rigid, skinned, to clip) the report's
// ops_per_vertex.* figures hold the same counts.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/ops/op_count.h"
#include "harness/ops/ops_vertex.h"

namespace mb::ops {

// `kernels`: the measured rows of the "kernels" table (measureAll(allKernels())); `perVertex`
// as `motorbench ops` measured it (a run without SPIR-V gives NaN SPIR-V figures that say
// why). The listings and pieces are counted here.
nlohmann::json opsFigures(const std::vector<Row>& kernels, const opsv::VertexOps& perVertex);

// "skinned, world palette" -> "skinned_world_palette", "rigid, morph frame (a)" -> "rigid_morph_frame_a".
std::string figureLabel(const std::string& label);

// The listing lines ops.txt prints after the kernel table: each listing counted beside its
// claim, and for every kernel that disagrees with the paper while the listing agrees, why.
std::string formatListings(const std::vector<Row>& kernels);

}  // namespace mb::ops
