// Ops of the motor family's two morph methods (shaders/motor_transform.glsl),
// counted through the shim, against hand-derived counts (the shim's rules: dot(vec4) 4 mul +
// 3 add, normalize(vec3) 6 mul + 2 add + 1 inversesqrt, cross 6 / 3, comparisons free).
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "harness/ops/ops_vertex.h"

using namespace mb;

namespace {

OpCounts counted(const std::string& function) {
  for (const opsv::VertexKernel& k : opsv::vertexKernels())
    if (k.function == function) return opsv::countVertexKernel(k);
  ADD_FAILURE() << "no kernel " << function;
  return {};
}

// mul, add, div, other (no sqrt: inversesqrt counts as other).
void expectOps(const OpCounts& c, std::array<uint64_t, 4> want, const std::string& what) {
  const std::array<uint64_t, 5> got{c.mul, c.add, c.div, c.sqrt, c.other};
  EXPECT_EQ(got, (std::array<uint64_t, 5>{want[0], want[1], want[2], 0, want[3]})) << what;
}

}  // namespace

TEST(MorphOps, RotorMethodIsAnAddAndARenormalisation) {
  // rotor + delta 0/4; handedness sign(1/x) 1 div + 1 other; dot 4/3, inversesqrt, flip * s 1/0,
  // rotor * s 4/0.
  expectOps(counted("morphRotorBlend"), {9, 7, 1, 2}, "rotor method");
}

TEST(MorphOps, FrameMethodDecodesAndReformsTheRotor) {
  // rotorFrame: extractNormalTangent 9/8 + doubling 6/0; deltas 0/6; handedness 1 div 1 other;
  // rotorFromFrame: normalize 6/2, dot 3/2, n * d 3/0, subtract 0/3, normalize 6/2, cross 6/3,
  // trace 0/2, the fourth branch (the probe's frame has its largest diagonal on n.z) 0/6,
  // renormaliseRotor 9/3 + inversesqrt; three inversesqrt in all.
  expectOps(counted("morphRotorFrame"),
            {15 + 6 + 3 + 3 + 6 + 6 + 9, 8 + 6 + 2 + 2 + 3 + 2 + 3 + 2 + 6 + 3, 1, 4}, "frame method");
}

// The SPIR-V side (glslang + spirv-opt -O of each kernel's probe), printed beside the counted
// ops for the table; both kernels compile.
TEST(MorphOps, SpirvProbesCompile) {
  const opsv::VertexOps ops = opsv::measureVertexOps(opsv::SpirvDepth::Probes);
  if (!ops.toolsProblem.empty()) GTEST_SKIP() << ops.toolsProblem;
  int found = 0;
  for (const opsv::KernelRow& row : ops.kernels) {
    if (row.kernel.function != "morphRotorFrame" && row.kernel.function != "morphRotorBlend") continue;
    ++found;
    ASSERT_TRUE(row.optimised) << row.kernel.function << ": " << row.error;
    std::printf("[ morph ops ] %s counted %llu mul %llu add %llu div %llu other; SPIR-V -O %s\n",
                row.kernel.function.c_str(), (unsigned long long)row.counted.mul, (unsigned long long)row.counted.add,
                (unsigned long long)row.counted.div, (unsigned long long)row.counted.other,
                spirv::shortText(*row.optimised).c_str());
  }
  EXPECT_EQ(found, 2);
}
