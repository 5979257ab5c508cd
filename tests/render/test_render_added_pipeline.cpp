// Adding a pipeline takes its registry entry and nothing else: a copy of matrix under another
// name, registered with one entry, is drawn by render (the same bytes as matrix: compare finds
// them identical), counted by ops (its declared variants, the same figures as matrix), compiled
// by isa (the same programs), in the pipelines check and report run by default, and priced by the
// report's per-scene ops; once its registration ends it is gone from every list.
#include <gtest/gtest.h>

#include <algorithm>

#include "harness/isa/programs.h"
#include "harness/ops/pipeline_ops.h"
#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "harness/report/report_ops.h"
#include "harness/report/report_run.h"
#include "pipelines/matrix/matrix_pipeline.h"
#include "pipelines/registry.h"
#include "pipelines/scene/loader.h"

namespace {

using namespace mb;

const char* const kTwin = "matrix_twin";

// matrix under another name: every call goes to a matrix pipeline.
class MatrixTwin final : public Pipeline {
public:
  std::string name() const override { return kTwin; }
  void configure(const PipelineOptions& o) override { matrix_->configure(o); }
  SkinSpace skinSpace() const override { return matrix_->skinSpace(); }
  Status prepare(const Scene& scene) override { return matrix_->prepare(scene); }
  void update(const AnimState& state) override { matrix_->update(state); }
  void timeUpdatePhases(bool on) override { matrix_->timeUpdatePhases(on); }
  void render(const View& view) override { matrix_->render(view); }
  PipelineStats stats() const override { return matrix_->stats(); }

private:
  std::unique_ptr<Pipeline> matrix_ = makeMatrixPipeline();
};

PipelineEntry twinEntry() {
  PipelineEntry e = matrixEntry();
  e.name = kTwin;
  e.make = []() -> std::unique_ptr<Pipeline> { return std::make_unique<MatrixTwin>(); };
  return e;
}

bool listed(const std::vector<std::string>& names) {
  return std::find(names.begin(), names.end(), kTwin) != names.end();
}

TEST(AddedPipeline, OneRegistryEntryReachesEveryCommand) {
  {
    ScopedRegistration twin(twinEntry());
    ASSERT_TRUE(twin.added());
    EXPECT_FALSE(ScopedRegistration(matrixEntry()).added());  // a taken name is refused

    // check and report draw every registered pipeline unless told; render and compare accept it.
    EXPECT_TRUE(listed(allPipelineNames()));
    EXPECT_TRUE(listed(pipelineNames(Space::Euclidean)));
    EXPECT_TRUE(listed(report::runPipelines(report::Options{})));
    EXPECT_EQ(skinMethodOf(kTwin), SkinMethod::LinearBlend);

    // render + compare: the same image as matrix.
    auto scene = loadScene("textured_box");
    ASSERT_TRUE(scene) << scene.error();
    FrameSettings s;
    s.width = s.height = 48;
    auto a = renderFrame(*scene, "matrix", s);
    auto b = renderFrame(*scene, kTwin, s);
    ASSERT_TRUE(a) << a.error();
    ASSERT_TRUE(b) << b.error();
    EXPECT_GT(b->stats.draws, 0);
    auto m = compareImages(a->image, b->image);
    ASSERT_TRUE(m) << m.error();
    EXPECT_EQ(m->maxError, 0.0);
    EXPECT_EQ(a->image.rgba, b->image.rgba);

    // ops: its declared variants, every kernel resolved, matrix's figures.
    const opsv::VertexOps ops = opsv::measureVertexOps(opsv::SpirvDepth::None);
    size_t variants = 0;
    for (const opsv::VariantRow& v : ops.variants) {
      if (v.variant.pipeline != kTwin) continue;
      ++variants;
      EXPECT_TRUE(v.kernelsResolved) << v.variant.label << ": " << v.error;
    }
    EXPECT_EQ(variants, matrixEntry().variants.size());
    const auto rows = opsv::pipelineOps(ops);
    auto row = [&](const std::string& p) {
      return std::find_if(rows.begin(), rows.end(), [&](const opsv::PipelineOps& r) { return r.pipeline == p; });
    };
    ASSERT_NE(row(kTwin), rows.end());
    EXPECT_EQ(row(kTwin)->problem, "");
    EXPECT_EQ(opsv::readmeOpsCell(*row(kTwin)), opsv::readmeOpsCell(*row("matrix")));

    // isa: the same programs as matrix (files and defines), under its name.
    std::vector<std::string> twinPrograms, matrixPrograms;
    for (const isa::Program& p : isa::allPrograms()) {
      const std::string what = p.vertexFile + " " + p.fragmentFile + " " + p.program;
      if (p.pipeline == kTwin) twinPrograms.push_back(what);
      if (p.pipeline == "matrix") matrixPrograms.push_back(what);
    }
    EXPECT_FALSE(twinPrograms.empty());
    EXPECT_EQ(twinPrograms, matrixPrograms);

    // report: the per-scene ops of a rigid scene price it as matrix.
    nlohmann::json flat = {{"variants", nlohmann::json::array()}};
    for (const opsv::VariantRow& v : ops.variants)
      flat["variants"].push_back({{"pipeline", v.variant.pipeline}, {"label", v.variant.label},
                                  {"counted", {{"mul", v.counted.mul}, {"add", v.counted.add}}}, {"spirv", nullptr}});
    const nlohmann::json priced = report::sceneOpsPerVertex(flat, {{"rigid", 100.0}});
    ASSERT_TRUE(priced.contains(kTwin)) << priced.dump();
    EXPECT_EQ(priced[kTwin], priced["matrix"]);
  }
  EXPECT_FALSE(listed(allPipelineNames()));
  EXPECT_EQ(createPipeline(kTwin), nullptr);
}

}  // namespace
