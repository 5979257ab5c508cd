// The in-process SPIR-V toolchain (harness/ops/spirv_compile.h) against the commands it stands
// for: glslangValidator, spirv-opt and spirv-dis (Debian's glslang-tools and spirv-tools, built
// from the same sources as the libraries). Real shader variants of three pipelines, both flag
// sets motorbench uses (-G for op counts, -V -R for the AMD ISA), and spirv-opt -O: the same
// bytes and the same text. Skipped where the commands are not installed (setup.sh installs them).
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "harness/ops/shader_variants.h"
#include "harness/ops/spirv_compile.h"
#include "pipelines/gl/shader_source.h"
#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::quoted;
using mb::cli_test::readText;

bool commandRuns(const std::string& cmd) {
  std::string output;
  return mb::cli_test::runCommand(cmd, &output) == 0;
}

std::vector<uint32_t> readWords(const fs::path& p) {
  const std::string bytes = readText(p);
  std::vector<uint32_t> w(bytes.size() / 4);
  std::memcpy(w.data(), bytes.data(), w.size() * 4);
  return w;
}

class SpirvCompile : public ::testing::Test {
protected:
  void SetUp() override {
    if (!commandRuns("glslangValidator --version") || !commandRuns("spirv-opt --version") ||
        !commandRuns("spirv-dis --version"))
      GTEST_SKIP() << "glslangValidator, spirv-opt or spirv-dis not installed (the reference commands)";
    dir_ = mb::cli_test::scratchDir("spirv_compile");
  }
  void TearDown() override { fs::remove_all(dir_); }

  // glslangValidator <flags> -S <stage> -o cli.spv shader.<stage>: the module it writes.
  std::vector<uint32_t> glslangValidator(const std::string& source, const std::string& stage,
                                         const std::string& flags) {
    const fs::path src = dir_ / ("shader." + stage), spv = dir_ / "cli.spv";
    std::ofstream(src, std::ios::binary) << source;
    EXPECT_TRUE(commandRuns("glslangValidator " + flags + " -S " + stage + " -o " + quoted(spv) + " " + quoted(src)));
    return readWords(spv);
  }
  std::vector<std::pair<std::string, std::string>> sources() const {  // (label, vertex text)
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& v : mb::opsv::shaderVariants()) {
      if (v.pipeline != "matrix" && v.pipeline != "motor" && v.pipeline != "qtangent") continue;
      if (v.label != "rigid" && v.label != "skinned") continue;
      auto e = mb::gl::expandShaderFile(v.file, v.defines);
      EXPECT_TRUE(e.ok()) << e.error();
      if (e.ok()) out.push_back({v.pipeline + " " + v.label, e->text});
    }
    return out;
  }
  fs::path dir_;
};

TEST_F(SpirvCompile, ModulesAreGlslangValidatorsBytes) {
  const auto vertices = sources();
  ASSERT_EQ(vertices.size(), 6u);
  auto fragment = mb::gl::expandShaderFile("forward.fs", {});
  ASSERT_TRUE(fragment.ok()) << fragment.error();
  for (const auto& [label, text] : vertices)
    for (const char* flags : {"-G --aml", "-V -R --aml --amb"}) {
      auto ours = mb::spirv::compileGlsl(text, "vert", flags, label);
      ASSERT_TRUE(ours.ok()) << ours.error();
      EXPECT_EQ(*ours, glslangValidator(text, "vert", flags)) << label << ", " << flags;
    }
  const char* fragmentFlags = "-V -R --aml --amb --rsb 1";
  auto ours = mb::spirv::compileGlsl(fragment->text, "frag", fragmentFlags, "forward.fs");
  ASSERT_TRUE(ours.ok()) << ours.error();
  EXPECT_EQ(*ours, glslangValidator(fragment->text, "frag", fragmentFlags));
}

TEST_F(SpirvCompile, OptimisedTextIsSpirvOptAndSpirvDisOutput) {
  for (const auto& [label, text] : sources()) {
    auto module = mb::spirv::compileGlsl(text, "vert", "-G --aml", label);
    ASSERT_TRUE(module.ok()) << module.error();
    auto optimised = mb::spirv::optimiseSpirv(*module, "-O", label);
    ASSERT_TRUE(optimised.ok()) << optimised.error();
    auto ours = mb::spirv::disassembleSpirv(*optimised, label);
    ASSERT_TRUE(ours.ok()) << ours.error();

    const fs::path in = dir_ / "in.spv", opt = dir_ / "opt.spv", dis = dir_ / "opt.spvasm";
    std::ofstream(in, std::ios::binary).write(reinterpret_cast<const char*>(module->data()), module->size() * 4);
    ASSERT_TRUE(commandRuns("spirv-opt -O " + quoted(in) + " -o " + quoted(opt)));
    EXPECT_EQ(*optimised, readWords(opt)) << label;
    ASSERT_TRUE(commandRuns("spirv-dis --no-color -o " + quoted(dis) + " " + quoted(opt)));
    EXPECT_EQ(*ours, readText(dis)) << label;
    EXPECT_NE(ours->find("OpEntryPoint Vertex"), std::string::npos);
  }
}

TEST(SpirvCompileErrors, BadFlagsStagesAndSourcesAreNamed) {
  const std::string ok = "#version 450\nvoid main() { gl_Position = vec4(0.0); }\n";
  auto flag = mb::spirv::compileGlsl(ok, "vert", "-G --aml -Os", "probe.vs");
  ASSERT_FALSE(flag.ok());
  EXPECT_NE(flag.error().find("probe.vs"), std::string::npos) << flag.error();
  EXPECT_NE(flag.error().find("'-Os'"), std::string::npos) << flag.error();
  EXPECT_FALSE(mb::spirv::compileGlsl(ok, "vert", "--aml", "probe.vs").ok());  // neither -G nor -V
  EXPECT_FALSE(mb::spirv::compileGlsl(ok, "comp", "-G", "probe.vs").ok());
  auto syntax = mb::spirv::compileGlsl("#version 450\nvoid main() { gl_Position = vec4(0.0) }\n", "vert", "-G", "broken.vs");
  ASSERT_FALSE(syntax.ok());
  EXPECT_NE(syntax.error().find("broken.vs: glslang failed"), std::string::npos) << syntax.error();
  EXPECT_NE(syntax.error().find("ERROR"), std::string::npos) << syntax.error();
  auto passes = mb::spirv::optimiseSpirv({0x07230203u}, "--no-such-pass", "x");
  EXPECT_FALSE(passes.ok());
  EXPECT_FALSE(mb::spirv::disassembleSpirv({1, 2, 3}, "x").ok());
}

}  // namespace
