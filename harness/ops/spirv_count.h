// SPIR-V op counting: the cross-check of the counted (shim) ops per vertex (DESIGN.md, idea 4).
// A GLSL stage is compiled as glslangValidator compiles it (-G: OpenGL SPIR-V, --aml: automatic
// uniform locations, so plain `uniform mat4` compiles), optimised as spirv-opt optimises it (-O,
// which inlines every helper into main; or inlining alone), disassembled as spirv-dis does
// (all three through their libraries in this process, spirv_compile.h), and the arithmetic
// instructions of every function body are counted with vector and matrix instructions expanded
// to the scalar operations they stand for, by the same rules as mb::Counted:
//   OpFAdd/OpFSub vecN           N add           OpFMul vecN, OpVectorTimesScalar   N mul
//   OpFDiv vecN                  N div           OpFNegate, conversions, compares   free
//   OpDot vecN                   N mul, N-1 add  OpMatrixTimesScalar CxR            C*R mul
//   OpMatrixTimesVector CxR      C*R mul, (C-1)*R add  (mat4 * vec4: 16 mul, 12 add)
//   OpVectorTimesMatrix CxR      C*R mul, C*(R-1) add
//   OpMatrixTimesMatrix CxR*KxC  K*C*R mul, K*(C-1)*R add
//   GLSL.std.450 Fma vecN        N mul, N add    Sqrt vecN                          N sqrt
//   Normalize vecN               2N mul, N-1 add, 1 other (inversesqrt), as the shim expands it
//   Length vecN                  N mul, N-1 add, 1 sqrt      Cross  6 mul, 3 add
//   Distance vecN                N mul, 2N-1 add, 1 sqrt     FMix vecN  N mul, 2N add
//   InverseSqrt, Sin, Cos, FSign, FAbs, FMin, FMax, Floor, ... N other (FClamp 2N)
//   integer arithmetic (index computation) is kept apart in `intOps`.
// The count is static (every instruction once); after -O a vertex shader without loops is one
// block, so it is the per-vertex count. `histogram` keeps instructions per opcode name (and per
// GLSL.std.450 name) so differences between two counts can be listed.
#pragma once
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "pipelines/result.h"

namespace mb::spirv {

struct Counts {
  uint64_t mul = 0, add = 0, div = 0, sqrt = 0, other = 0, intOps = 0;
  std::map<std::string, uint64_t> histogram;       // instructions per opcode / ext name
  std::map<std::string, uint64_t> unknownExtInsts; // GLSL.std.450 calls without a rule

  Counts& operator+=(const Counts& o);
  bool sameArithmetic(const Counts& o) const {
    return mul == o.mul && add == o.add && div == o.div && sqrt == o.sqrt && other == o.other;
  }
};

// "49/36/0/0/0" (mul/add/div/sqrt/other).
std::string shortText(const Counts& c);
// Instruction-count differences of `b` against `a`, e.g. "+2 Normalize, +1 OpFDiv, -3 OpFMul"
// (arithmetic opcodes only; "" when the histograms agree).
std::string histogramDiff(const Counts& a, const Counts& b);

// Counts the function bodies of a spirv-dis disassembly. Fails on malformed text (an
// arithmetic instruction whose operand types are unknown).
Result<Counts> countDisassembly(const std::string& text);

// InlineOnly: helpers inlined, nothing else. NoFold: spirv-opt -O's pass list without
// simplify-instructions (inlining, SSA, common subexpressions, dead code; no instruction
// folding, which is where spirv-opt fuses a * b + c into Fma). Full: spirv-opt -O.
enum class Optimise { InlineOnly, NoFold, Full };

// A private temporary folder <tmp>/<prefix>-XXXXXX, removed with the object; `path` is empty
// when it could not be made.
struct TempDir {
  explicit TempDir(const std::string& prefix = "motorbench-spirv");
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::filesystem::path path;
};

// Compiles one GLSL stage (complete source text, #includes already expanded; `stage` is the
// glslang stage name: "vert", "frag") and returns the disassembly of the optimised module.
// Errors carry the compiler's log; `name` labels them.
Result<std::string> compileToDisassembly(const std::string& source, const std::string& stage,
                                         Optimise opt, const std::string& name);

// Compiles one GLSL stage with glslangValidator's `flags` (e.g. "-V -R --aml --amb": Vulkan
// SPIR-V with relaxed rules, for harness/isa) and returns the SPIR-V words, unoptimised.
Result<std::vector<uint32_t>> compileToBinary(const std::string& source, const std::string& stage,
                                              const std::string& flags, const std::string& name);

// compileToDisassembly + countDisassembly.
Result<Counts> countSource(const std::string& source, const std::string& stage, Optimise opt,
                           const std::string& name);

}  // namespace mb::spirv
