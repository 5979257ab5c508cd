// The SPIR-V op counter (harness/ops/spirv_count.h) on tiny hand-written shaders whose counts are
// derived by hand, and on hand-written disassembly for the instructions glslang rarely emits.
#include <gtest/gtest.h>

#include <string>

#include "harness/ops/spirv_count.h"

namespace {

using mb::spirv::Counts;
using mb::spirv::Optimise;

// Wraps a body in a vertex shader with a few inputs of every shape.
std::string vertexShader(const std::string& decls, const std::string& body) {
  return "#version 450 core\n" + decls + "\nvoid main() {\n" + body + "\n}\n";
}

Counts count(const std::string& source, Optimise opt = Optimise::Full) {
  auto c = mb::spirv::countSource(source, "vert", opt, "test shader");
  EXPECT_TRUE(c.ok()) << c.error();
  return c.ok() ? *c : Counts{};
}

class SpirvTools : public ::testing::Test {};  // glslang and SPIRV-Tools are linked in: never skipped

TEST_F(SpirvTools, Mat4TimesVec4Is16Mul12Add) {
  Counts c = count(vertexShader("uniform mat4 u_m; layout(location = 0) in vec4 a_p;",
                                "gl_Position = u_m * a_p;"));
  EXPECT_EQ(c.mul, 16u);
  EXPECT_EQ(c.add, 12u);
  EXPECT_EQ(c.div + c.sqrt + c.other, 0u);
  EXPECT_EQ(c.histogram["OpMatrixTimesVector"], 1u);
}

TEST_F(SpirvTools, VectorMulAddDivAndFreeNegation) {
  // vec3: a * b (3 mul) + c (3 add); / d (3 div); negation free; vec4 * scalar 4 mul.
  Counts c = count(vertexShader(
      "layout(location = 0) in vec3 a; layout(location = 1) in vec3 b; "
      "layout(location = 2) in vec3 cc; layout(location = 3) in vec3 d; "
      "layout(location = 4) in float s; layout(location = 0) out vec3 o; "
      "layout(location = 1) out vec4 o2;",
      "o = -((a * b + cc) / d); o2 = vec4(a, 1.0) * s;"));
  EXPECT_EQ(c.mul, 7u);
  EXPECT_EQ(c.add, 3u);
  EXPECT_EQ(c.div, 3u);
  EXPECT_EQ(c.other, 0u);
}

TEST_F(SpirvTools, DotCrossNormalizeLengthSqrt) {
  // dot(vec4) 4/3; cross 6/3; normalize(vec3) 6 mul 2 add 1 inversesqrt; length(vec2) 2 mul
  // 1 add 1 sqrt; sqrt(float) 1 sqrt.
  Counts c = count(vertexShader(
      "layout(location = 0) in vec4 a; layout(location = 1) in vec4 b; "
      "layout(location = 2) in vec3 u; layout(location = 3) in vec3 v; "
      "layout(location = 4) in vec2 w; layout(location = 5) in float f; "
      "layout(location = 0) out float o1; layout(location = 1) out vec3 o2; "
      "layout(location = 2) out vec3 o3; layout(location = 3) out float o4; "
      "layout(location = 4) out float o5;",
      "o1 = dot(a, b); o2 = cross(u, v); o3 = normalize(u); o4 = length(w); o5 = sqrt(f);"));
  EXPECT_EQ(c.mul, 4u + 6u + 6u + 2u);
  EXPECT_EQ(c.add, 3u + 3u + 2u + 1u);
  EXPECT_EQ(c.sqrt, 2u);
  EXPECT_EQ(c.other, 1u);
}

TEST_F(SpirvTools, HelpersAreInlinedAndCountedOnce) {
  // A helper called twice: 2 x (3 mul + 3 add), with and without the full optimiser.
  const std::string src = vertexShader(
      "layout(location = 0) in vec3 a; layout(location = 1) in vec3 b; "
      "layout(location = 0) out vec3 o; layout(location = 1) out vec3 o2;\n"
      "vec3 madd(vec3 x, vec3 y) { return x * y + y; }",
      "o = madd(a, b); o2 = madd(b, a);");
  for (Optimise opt : {Optimise::InlineOnly, Optimise::Full}) {
    Counts c = count(src, opt);
    EXPECT_EQ(c.mul, 6u);
    EXPECT_EQ(c.add, 6u);
  }
}

TEST_F(SpirvTools, IntegerIndexMathIsKeptApart) {
  // 2u * j + 1u: one integer multiply (or shift) and one add, not float ops.
  Counts c = count(vertexShader(
      "uniform vec4 u_v[8]; layout(location = 0) in uint j;",
      "gl_Position = u_v[2u * j + 1u];"));
  EXPECT_EQ(c.mul + c.add + c.div + c.sqrt + c.other, 0u);
  EXPECT_EQ(c.intOps, 2u);
}

TEST(SpirvDisassembly, MatrixAndFmaRules) {
  // Hand-written module: mat3x4 (3 columns of vec4) times vec3 = 12 mul 8 add; vec4 times
  // mat3x4 (row vector) = 12 mul 9 add; mat4 * mat4 = 64 mul 48 add; Fma vec2 = 2 mul 2 add;
  // mat2 * scalar = 4 mul; FNegate free; FClamp vec3 = 6 other; Distance vec3 = 3 mul 5 add
  // 1 sqrt.
  const std::string dis = R"(
          %1 = OpExtInstImport "GLSL.std.450"
      %float = OpTypeFloat 32
    %v2float = OpTypeVector %float 2
    %v3float = OpTypeVector %float 3
    %v4float = OpTypeVector %float 4
%mat3v4float = OpTypeMatrix %v4float 3
%mat4v4float = OpTypeMatrix %v4float 4
%mat2v2float = OpTypeMatrix %v2float 2
         %m3 = OpUndef %mat3v4float
         %m4 = OpUndef %mat4v4float
         %m2 = OpUndef %mat2v2float
          %v = OpUndef %v3float
          %w = OpUndef %v4float
          %x = OpUndef %v2float
          %s = OpUndef %float
       %main = OpFunction %void None %3
          %5 = OpLabel
         %10 = OpMatrixTimesVector %v4float %m3 %v
         %11 = OpVectorTimesMatrix %v3float %w %m3
         %12 = OpMatrixTimesMatrix %mat4v4float %m4 %m4
         %13 = OpExtInst %v2float %1 Fma %x %x %x
         %14 = OpMatrixTimesScalar %mat2v2float %m2 %s
         %15 = OpFNegate %v4float %w
         %16 = OpExtInst %v3float %1 FClamp %v %v %v
         %17 = OpExtInst %float %1 Distance %v %v
               OpReturn
               OpFunctionEnd
)";
  auto c = mb::spirv::countDisassembly(dis);
  ASSERT_TRUE(c.ok()) << c.error();
  EXPECT_EQ(c->mul, 12u + 12u + 64u + 2u + 4u + 3u);
  EXPECT_EQ(c->add, 8u + 9u + 48u + 2u + 5u);
  EXPECT_EQ(c->other, 6u);
  EXPECT_EQ(c->sqrt, 1u);
  EXPECT_EQ(c->histogram.count("OpFNegate"), 0u);
}

TEST(SpirvDisassembly, UnknownOperandIsAnError) {
  const std::string dis = R"(
      %float = OpTypeFloat 32
       %main = OpFunction %void None %3
         %10 = OpDot %float %nope %nope
               OpFunctionEnd
)";
  EXPECT_FALSE(mb::spirv::countDisassembly(dis).ok());
}

TEST(SpirvDisassembly, HistogramDiffListsChangedOpcodes) {
  Counts a, b;
  a.histogram = {{"OpFMul", 3}, {"Normalize", 1}};
  b.histogram = {{"OpFMul", 1}, {"Normalize", 3}, {"OpFDiv", 1}};
  EXPECT_EQ(mb::spirv::histogramDiff(a, b), "+2 Normalize, +1 OpFDiv, -2 OpFMul");
  EXPECT_EQ(mb::spirv::histogramDiff(a, a), "");
}

}  // namespace
