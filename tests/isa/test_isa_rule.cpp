// The occupancy rule (harness/isa/families.h) on hand-derived cases, the program list against
// the pipelines' shader table, and the SPIR-V interface reader on a real compiled shader.
#include <gtest/gtest.h>

#include <set>

#include "harness/isa/families.h"
#include "harness/isa/programs.h"
#include "harness/isa/spirv_interface.h"
#include "harness/ops/ops_vertex.h"

#define VK_NO_PROTOTYPES
#include <vulkan/vulkan_core.h>

namespace {

using namespace mb::isa;

const Family& family(const std::string& id) {
  for (const Family& f : allFamilies())
    if (f.id() == id) return f;
  throw std::runtime_error("no family " + id);
}

Registers regs(int v, int s, int wave) {
  Registers r;
  r.vgprs = v, r.sgprs = s, r.waveSize = wave;
  return r;
}

TEST(IsaRule, GcnVgprGranuleAndCap) {
  // 28 VGPRs: 256 / 28 = 9 waves; 56 SGPRs on GCN 1: 512 / 56 = 9.
  EXPECT_EQ(wavesPerSimd(family("tahiti"), regs(28, 56, 64)), 9);
  // 25 VGPRs round up to 28 (granule 4).
  EXPECT_EQ(wavesPerSimd(family("vega10"), regs(25, 16, 64)), 9);
  // Few registers: the cap, 10 waves (8 on Polaris).
  EXPECT_EQ(wavesPerSimd(family("vega10"), regs(8, 16, 64)), 10);
  EXPECT_EQ(wavesPerSimd(family("polaris10"), regs(8, 16, 64)), 8);
  // SGPR-bound on GCN 1: 104 SGPRs -> 512 / 104 = 4, while 24 VGPRs would allow 10.
  EXPECT_EQ(wavesPerSimd(family("tahiti"), regs(24, 104, 64)), 4);
  // GCN 5: 800 SGPRs in granules of 16: 100 -> 112 -> 7.
  EXPECT_EQ(wavesPerSimd(family("vega10"), regs(24, 100, 64)), 7);
}

TEST(IsaRule, RdnaVgprsAndUnits) {
  // RDNA 1 wave64: 512 registers / 28 = 18 (cap 20); RADV counts 32-lane units: 36.
  EXPECT_EQ(wavesPerSimd(family("navi10"), regs(28, 128, 64)), 18);
  EXPECT_EQ(radvSubgroupsPerSimd(family("navi10"), 18, 64), 36);
  // RDNA 2 wave64: 30 VGPRs -> hardware granule 8 -> 32 -> 512 / 32 = 16 (cap 16).
  EXPECT_EQ(wavesPerSimd(family("navi21-ngg"), regs(30, 128, 64)), 16);
  // RDNA 2 wave32: 1024 registers, granule 16: 40 -> 48 -> 21 -> cap 16.
  EXPECT_EQ(wavesPerSimd(family("navi21-nonggc"), regs(40, 128, 32)), 16);
  // 100 VGPRs wave32 -> 112 -> 1024 / 112 = 9.
  EXPECT_EQ(wavesPerSimd(family("navi21-nonggc"), regs(100, 128, 32)), 9);
  // gfx1100 wave64: 768 registers, granule 12: 40 -> 48 -> 16.
  EXPECT_EQ(wavesPerSimd(family("gfx1100"), regs(40, 128, 64)), 16);
  // 100 -> 108 -> 768 / 108 = 7.
  EXPECT_EQ(wavesPerSimd(family("gfx1100"), regs(100, 128, 64)), 7);
  EXPECT_EQ(radvSubgroupsPerSimd(family("tahiti"), 7, 64), 7);
}

TEST(IsaPrograms, EveryShaderVariantOnceWithItsFragmentShader) {
  const auto programs = allPrograms();
  std::set<std::string> keys;
  for (const Program& p : programs) {
    std::string k = p.pipeline + "|" + p.vertexFile;
    for (const auto& d : defineList(p.defines)) k += "|" + d;
    EXPECT_TRUE(keys.insert(k).second) << "listed twice: " << k;
    EXPECT_EQ(p.fragmentFile, p.vertexFile.rfind("curved_", 0) == 0 ? "curved.fs" : "forward.fs");
  }
  // Every (pipeline, file, defines) of the ops table is here.
  for (const auto& v : mb::opsv::shaderVariants()) {
    std::string k = v.pipeline + "|" + v.file;
    for (const auto& d : defineList(v.defines)) k += "|" + d;
    EXPECT_TRUE(keys.count(k)) << k;
  }
  EXPECT_EQ(programId("S3 instance"), "curved");
  EXPECT_EQ(programId("bezier patch, scaled fallback"), "patch_scaled_fallback");
  EXPECT_EQ(programId("skinned+scaled"), "skinned_scaled");
  EXPECT_EQ(programId("rigid, no tangent"), "rigid_no_tangent");
}

TEST(IsaPrograms, SpirvInterfaceOfTheSkinnedMatrixProgram) {
  Program skinned;
  for (const Program& p : allPrograms())
    if (p.pipeline == "matrix" && p.program == "skinned") skinned = p;
  ASSERT_EQ(skinned.vertexFile, "matrix.vs");
  auto c = compileProgram(skinned);
  ASSERT_TRUE(c) << c.error();
  // matrix.vs: a_position 0 (vec3), a_normal 1, a_tangent 2 (vec4), a_uv0 3, a_uv1 4, a_color 5,
  // a_joints 6 (uvec4), a_weights 7.
  const auto& in = c->vertex.interface.inputs;
  ASSERT_EQ(in.size(), 8u);
  for (uint32_t i = 0; i < 8; ++i) EXPECT_EQ(in[i].location, i);
  EXPECT_EQ(in[0].components, 3u);
  EXPECT_EQ(in[2].components, 4u);
  EXPECT_EQ(in[6].kind, VertexInput::Uint);
  EXPECT_EQ(in[7].kind, VertexInput::Float);
  // Vertex: the default uniform block and the JointPalette storage buffer (binding 0 in the
  // source), both in set 0; fragment: five samplers (bindings 0-4) and its uniform block, set 1.
  std::set<int> vertexTypes;
  for (const Descriptor& d : c->vertex.interface.descriptors) {
    EXPECT_EQ(d.set, 0u);
    vertexTypes.insert(d.type);
  }
  EXPECT_EQ(vertexTypes, (std::set<int>{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}));
  int samplers = 0;
  for (const Descriptor& d : c->fragment.interface.descriptors) {
    EXPECT_EQ(d.set, 1u);
    samplers += d.type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  }
  EXPECT_EQ(samplers, 5);
  // The six varyings of forward.fs are the fragment inputs.
  EXPECT_EQ(c->fragment.interface.inputs.size(), 6u);
}

TEST(IsaPrograms, RejectsWhatIsNotSpirv) {
  auto r = readInterface({1, 2, 3, 4, 5, 6}, "junk.spv");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error(), "junk.spv: not a SPIR-V module");
  auto t = readInterface({0x07230203, 0x10000, 0, 10, 0, (9u << 16) | 59}, "cut.spv");
  ASSERT_FALSE(t);
  EXPECT_EQ(t.error(), "cut.spv: truncated SPIR-V instruction");
}

}  // namespace
