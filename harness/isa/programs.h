// The programs `motorbench isa` compiles: every real vertex-shader variant of
// harness/ops/ops_vertex.h's shaderVariants() (the table the SPIR-V op count uses: the same files
// and #defines the pipelines load), once per pipeline and set of defines, each with the fragment
// shader its pipeline links it with; and their GLSL made into Vulkan SPIR-V.
#pragma once
#include <string>
#include <vector>

#include "harness/isa/pipeline_stats.h"
#include "pipelines/gl/shader_source.h"
#include "pipelines/result.h"

namespace mb::isa {

struct Program {
  std::string pipeline;       // "matrix"
  std::string program;        // "rigid", "skinned", "rigid_no_tangent", "patch", "curved", ...
  std::string variant;        // the label of shaderVariants(): "skinned, reference", ...
  std::vector<std::string> labels;  // every label of shaderVariants() this program stands for
  std::string vertexFile, fragmentFile;  // relative to the shader folder
  gl::Defines defines;        // given to both stages, as gl::Program::fromFiles does
  // The varyings (the fragment shader's inputs, from its SPIR-V; set by runIsa): locations
  // (vec4 slots) and their 32-bit components.
  int varyingSlots = 0, varyingComponents = 0;
};

// In table order; a (pipeline, file, defines) listed twice under two labels comes once, under
// its first label.
std::vector<Program> allPrograms();

// "S3 instance" -> "curved", "bezier patch, scaled fallback" -> "patch_scaled_fallback",
// "skinned+scaled" -> "skinned_scaled".
std::string programId(const std::string& label);

struct CompiledProgram {
  StageModule vertex, fragment;
};

// Expands each stage's #includes and #defines (pipelines/gl/shader_source.h) and compiles it
// with glslangValidator -V -R --aml --amb (Vulkan SPIR-V, relaxed rules: loose uniforms go to a
// default uniform block; automatic locations and bindings). The fragment stage's resources go
// to descriptor set 1 (--rsb 1) so the two stages' automatic bindings cannot collide.
Result<CompiledProgram> compileProgram(const Program& p);

// "SKINNED MB_WORLD_PALETTE" style list for JSON: {"SKINNED", "MB_KAPPA=1"}.
std::vector<std::string> defineList(const gl::Defines& d);

}  // namespace mb::isa
