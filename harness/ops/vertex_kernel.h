// One per-vertex kernel of a pipeline: a GLSL function run once on mb::Counted through the shim,
// and a probe vertex shader calling the same function (harness/ops/spirv_count.h counts it).
#pragma once
#include <functional>
#include <string>

#include "shaders/shim/counted.h"

namespace mb::opsv {

// One per-vertex kernel: a GLSL function of a pipeline, run once on mb::Counted, and a probe
// vertex shader that calls the same function with per-vertex inputs and per-draw uniforms.
struct VertexKernel {
  std::string pipeline;  // "matrix", "motor", "matrix-affine" (extra baseline)
  std::string kernel;    // "rigid vertex with frame", "skinned vertex (4 joints)", ...
  std::string function;  // the GLSL function measured
  std::function<void()> run;  // executes the function once on mb::Counted
  std::string probe;     // GLSL body of the probe's main() (declarations in probeDecls)
  std::string probeDecls;
  std::string note;      // known reason a count differs, "" when none
};

// The counted ops of one kernel.
inline OpCounts countVertexKernel(const VertexKernel& k) { return countOps(k.run); }

}  // namespace mb::opsv
