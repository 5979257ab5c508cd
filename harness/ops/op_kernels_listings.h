// harness/ops/op_kernels_listings.h: the paper's printed listings (shaders/paper_listings.glsl,
// transcribed expression for expression) counted on mb::Counted exactly as the kernels of
// op_kernels.h, each with the paper's table figure as its claim. Where our kernel and the
// paper's table disagree, the listing says whether the paper's own code reaches its table.
// Header-only, like op_kernels.h.
#pragma once
#include <string>
#include <vector>

#include "harness/ops/op_count.h"
#include "shaders/shim/counted.h"
#include "shaders/shim/paper_listings.h"

namespace mb::ops {

// Generic inputs: a non-unit motor (normalize_m's input), a unit motor with scalar part != 1
// (log_m's closed form), a bivector with a non-zero Euclidean part (exp_b's closed form).
inline std::vector<Kernel> listingKernels() {
  using PL = PaperListings<Counted>;
  static PL L;
  static const PL::motor m(0.9, 0.2, -0.3, 0.1, 0.4, -0.2, 0.3, 0.05);
  static const PL::motor unit = L.normalize_m(m);
  static const PL::line b(Counted(0.3), Counted(-0.2), Counted(0.5), Counted(0.1), Counted(0.4), Counted(-0.6));
  const auto paper = [](int mul, int add) { return Claim{mul, add, "paper"}; };
  return {
      {"listing", "normalize_m", "the paper's printed normalize_m listing: M / |M| (Study number)", paper(21, 5),
       [] { L.paper_normalize_m(m); }},
      {"listing", "sqrt_m", "the paper's printed sqrt_m listing: normalize(1 + M)", paper(21, 6),
       [] { L.paper_sqrt_m(unit); }},
      {"listing", "exp_b", "the paper's printed exp_b listing: exp(line) -> motor", paper(17, 8),
       [] { L.paper_exp_b(b); }},
      {"listing", "log_m", "the paper's printed log_m listing: log(motor) -> line", paper(14, 5),
       [] { L.paper_log_m(unit); }},
  };
}

// Why our kernel of the same name counts otherwise than the printed listing ("" when it
// does not).
inline std::string oursAgainstListing(const std::string& name) {
  if (name == "normalize_m") return "ours takes one inversesqrt and scales the dual correction once";
  if (name == "sqrt_m") return "ours is our normalize_m + 1 add";
  if (name == "log_m")
    return "ours rewrites 1 - s^2 as (1 - s)(1 + s), exact near s = 1 (small rotations) in float, for one addition";
  return "";
}

}  // namespace mb::ops
