// The counted per-vertex kernels of every pipeline, one file per family: matrix forms
// (vertex_kernels_matrix.cpp), motor forms (vertex_kernels_motor.cpp), Bezier patches
// (vertex_kernels_patch.cpp), curved space (vertex_kernels_curved.cpp), and forward.fs's
// per-fragment frame (vertex_kernels_fragment.cpp). Which pipeline draws
// which kernel is shader_variants.h's table.
#pragma once
#include <vector>

#include "harness/ops/vertex_kernel.h"

namespace mb::opsv {

namespace detail {
std::vector<VertexKernel> matrixKernels();
std::vector<VertexKernel> motorKernels();
std::vector<VertexKernel> patchKernels();
std::vector<VertexKernel> curvedKernels();
std::vector<VertexKernel> fragmentKernels();  // forward.fs's shading normal
}  // namespace detail

// Every kernel, in report order.
inline std::vector<VertexKernel> vertexKernels() {
  std::vector<VertexKernel> all;
  for (auto family : {detail::matrixKernels, detail::motorKernels, detail::patchKernels, detail::curvedKernels,
                      detail::fragmentKernels})
    for (VertexKernel& k : family()) all.push_back(std::move(k));
  return all;
}

}  // namespace mb::opsv
