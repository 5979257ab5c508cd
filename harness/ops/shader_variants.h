// Which kernels each registered pipeline draws: every real vertex-shader variant of every
// pipeline (rigid, skinned, normal-mapped or not, scaled fallback, Bezier patch, curved
// instance) with the counted kernels its main() calls, as each pipeline declares them in its
// registry entry (pipelines/registry.h). The one table every ops figure is derived from
// (pipeline_ops.h: report, `motorbench ops`, claims, the README's table) and the programs
// `motorbench isa` compiles.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace mb::opsv {

struct ShaderVariant {
  std::string pipeline;  // a registered pipeline name (pipelines/registry.cpp)
  std::string file;      // relative to the shader folder
  std::vector<std::pair<std::string, std::string>> defines;
  std::string label;     // "rigid", "skinned", ...
  std::vector<std::string> kernels;  // VertexKernel::function names the variant's main() calls
  std::string note = "";             // what main() does besides those kernels, "" when nothing
  std::string fragment = "forward.fs";  // the fragment shader the pipeline links it with
};

// Labels: "rigid", "skinned", "scaled fallback", "bezier patch" are what each pipeline draws by
// default (the report weights them by its vertex mix); "linear fallback" and "skinned, linear
// fallback" what the motor family's exact fallback draws (weighted by the vertices it drew). The
// skinned configurations are counted side by side for matrix and motor: "skinned, reference" (as
// the references do: the node's transform after the blend) and "skinned, world palette" (neither
// reference); the matrix default "skinned" is the former, the motor default the latter.
// "..., no tangent": the float-frame matrix forms (matrix, affine) on primitives without TANGENT
// or normal map.
//
// In registry order, each pipeline's variants in the order it declares them.
std::vector<ShaderVariant> shaderVariants();

}  // namespace mb::opsv
