// The traits each pipeline declares in its registry entry (pipelines/registry.h), which the
// report's and claims' tables read instead of pipeline names, against what the pipeline does:
// the vertex bytes against the bytes its uploads count on the normal-mapped torus, the frame
// decoder against the kernels harness/ops counts, the per-fragment rotor against the defines
// of its variants, the family against its skinning method, and the report's family of each.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "harness/document/report_answer_figures.h"
#include "harness/ops/vertex_kernels.h"
#include "harness/render/render_frame.h"
#include "pipelines/registry.h"
#include "pipelines/scene/loader.h"

namespace {

using namespace mb;

bool definesAny(const PipelineEntry& e, const std::string& define) {
  for (const ShaderVariant& v : e.variants)
    for (const auto& [name, value] : v.defines)
      if (name == define) return true;
  return false;
}

TEST(PipelineTraits, VertexBytesAreWhatTheUploadsCount) {
  auto scene = loadScene("normal_torus");
  ASSERT_TRUE(scene) << scene.error();
  FrameSettings s;
  s.width = s.height = 32;
  for (const PipelineEntry& e : registeredPipelines()) {
    if (e.space != Space::Euclidean) continue;
    auto f = renderFrame(*scene, e.name, s);
    ASSERT_TRUE(f) << e.name << ": " << f.error();
    ASSERT_GT(f->stats.normalMappedVertices, 0u) << e.name;
    EXPECT_EQ(f->stats.normalMappedVertexBytes, uint64_t(e.vertexBytes) * f->stats.normalMappedVertices) << e.name;
  }
}

TEST(PipelineTraits, FrameDecodersAreCountedKernelsAndTheRotorPassesWhereDeclared) {
  std::vector<std::string> counted;
  for (const opsv::VertexKernel& k : opsv::vertexKernels()) counted.push_back(k.function);
  int perFragment = 0;
  for (const PipelineEntry& e : registeredPipelines()) {
    if (e.space != Space::Euclidean) continue;
    if (e.frame.decodeKernel.empty())
      EXPECT_FALSE(e.frame.fetched.empty()) << e.name << ": neither a decoder nor what the fetch reads";
    else
      EXPECT_NE(std::find(counted.begin(), counted.end(), e.frame.decodeKernel), counted.end())
          << e.name << ": " << e.frame.decodeKernel;
    EXPECT_EQ(e.frame.perFragment, definesAny(e, "MB_FRAGMENT_ROTOR")) << e.name;
    perFragment += e.frame.perFragment;
    // Blending motors is the motor side's; hybrid poses with motors and blends matrices.
    if (e.skin == SkinMethod::MotorBlend) {
      EXPECT_EQ(e.family, PipelineFamily::Motor) << e.name;
    }
    if (e.family == PipelineFamily::Matrix) {
      EXPECT_EQ(e.skin, SkinMethod::LinearBlend) << e.name;
    }
  }
  EXPECT_EQ(perFragment, 1);  // motor_cf
}

// The report groups pipelines by the family they declare: matrices on the CPU or motors.
TEST(PipelineTraits, TheReportsFamilyIsTheDeclaredOne) {
  const std::set<std::string> matrices = {"matrix", "affine", "qtangent", "matrix_c", "s3_matrix", "h3_matrix"};
  for (const PipelineEntry& e : registeredPipelines())
    EXPECT_EQ(document::pipelineFamily(e.name), matrices.count(e.name) ? "matrix" : "motor") << e.name;
}

}  // namespace
