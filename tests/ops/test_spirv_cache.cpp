// The SPIR-V cache (harness/ops/spirv_cache.h) for compileToBinary: a module is stored once and
// read back instead of running glslangValidator again, next to the disassembly entries and never
// confused with them; an entry that cannot be a module is compiled again.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "harness/ops/spirv_count.h"

namespace {

namespace fs = std::filesystem;

const char* kShader = "#version 450 core\nlayout(location = 0) in vec4 a_p;\nvoid main() { gl_Position = a_p * 2.0; }\n";
const char* kFlags = "-V -R --aml --amb";

class SpirvCache : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mb_spirv_cache_test_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    const char* old = std::getenv("MB_CACHE_DIR");
    if (old) oldValue_ = old;
    hadOld_ = old != nullptr;
    setenv("MB_CACHE_DIR", dir_.c_str(), 1);
  }
  void TearDown() override {
    if (hadOld_) setenv("MB_CACHE_DIR", oldValue_.c_str(), 1);
    else unsetenv("MB_CACHE_DIR");
    fs::remove_all(dir_);
  }
  std::vector<uint32_t> compile() {
    auto words = mb::spirv::compileToBinary(kShader, "vert", kFlags, "cache test");
    EXPECT_TRUE(words.ok()) << words.error();
    return words.ok() ? *words : std::vector<uint32_t>{};
  }
  std::vector<fs::path> entries() const {
    std::vector<fs::path> out;
    if (fs::exists(dir_ / "spirv"))
      for (const auto& e : fs::directory_iterator(dir_ / "spirv")) out.push_back(e.path());
    return out;
  }
  fs::path dir_;
  std::string oldValue_;
  bool hadOld_ = false;
};

TEST_F(SpirvCache, ModuleStoredOnceAndReadBack) {
  const std::vector<uint32_t> first = compile();
  ASSERT_FALSE(first.empty());
  EXPECT_EQ(first[0], 0x07230203u);  // the SPIR-V magic number
  ASSERT_EQ(entries().size(), 1u);
  EXPECT_EQ(compile(), first);
  EXPECT_EQ(entries().size(), 1u);

  // The entry is what is returned: one word appended to it comes back (glslang is not run).
  const fs::path entry = entries()[0];
  { std::ofstream(entry, std::ios::binary | std::ios::app).write("\x01\x02\x03\x04", 4); }
  std::vector<uint32_t> fromCache = compile();
  ASSERT_EQ(fromCache.size(), first.size() + 1);
  EXPECT_EQ(fromCache.back(), 0x04030201u);
  fromCache.pop_back();
  EXPECT_EQ(fromCache, first);

  // Bytes that cannot be a module (not whole words): compiled again and stored again.
  { std::ofstream(entry, std::ios::binary | std::ios::app).write("\x05", 1); }
  EXPECT_EQ(compile(), first);
  EXPECT_EQ(compile(), first);
}

TEST_F(SpirvCache, DisassemblyOfTheSameTextIsAnotherEntry) {
  const std::vector<uint32_t> module = compile();
  ASSERT_FALSE(module.empty());
  auto text = mb::spirv::compileToDisassembly(kShader, "vert", mb::spirv::Optimise::Full, "cache test");
  ASSERT_TRUE(text.ok()) << text.error();
  EXPECT_NE(text->find("OpEntryPoint Vertex"), std::string::npos) << *text;  // text, not the module
  EXPECT_EQ(entries().size(), 2u);
  EXPECT_EQ(compile(), module);
}

}  // namespace
