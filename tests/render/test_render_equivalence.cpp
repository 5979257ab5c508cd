// Every registered pipeline vs the matrix baseline of its space (matrix; s3_matrix / h3_matrix for
// the curved scenes): on every rigid built-in scene and on the skinned scenes in their bind pose,
// PSNR >= 50 dB and at most 0.1 % of the pixels differ by more than 2/255. The cases come from
// pipelineNames(), so a new pipeline is covered by its registry line; placeholder pipelines are
// skipped. On a failure both images and a diff heat map are written to a temporary folder named in
// the message, to see where the images part.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "tests/support/pipeline_scene_cases.h"

using namespace mb;

namespace {

class Equivalence : public PipelineSceneTest {
protected:
  // The baseline's frame of this scene at `label`'s state, rendered once per test process for
  // every pipeline compared with it (a failed render is not kept: each case then fails).
  const RgbaImage* baselineFrame(const std::string& baseline, const std::string& label, const FrameSettings& s) {
    static std::map<std::string, RgbaImage> frames;
    const std::string key = GetParam().scene + "/" + label;
    if (auto it = frames.find(key); it != frames.end()) return &it->second;
    auto a = renderFrame(scene_, baseline, s);
    EXPECT_TRUE(a) << baseline << ": " << a.error();
    if (!a) return nullptr;
    return &frames.emplace(key, std::move(a->image)).first->second;
  }

  // Renders matrix and the pipeline under test; metrics, and the images kept for a report.
  ImageMetrics compareAt(const AnimState& anim, const std::string& label) {
    FrameSettings s;
    s.anim = anim;
    s.width = s.height = 128;
    const std::string baseline = pipelineNames(scene_.curved.space).front();
    const RgbaImage* a = baselineFrame(baseline, label, s);
    auto b = renderFrame(scene_, GetParam().pipeline, s);
    EXPECT_TRUE(b) << b.error();
    if (!a || !b) return {};
    auto m = compareImages(*a, b->image);
    EXPECT_TRUE(m) << m.error();
    if (!m) return {};
    std::printf("[ equiv    ] %s vs matrix, %s %s: PSNR %.2f dB, >2/255 %.4f%%, max %.0f/255 at (%d,%d)\n",
                GetParam().pipeline.c_str(), GetParam().scene.c_str(), label.c_str(), m->psnr,
                100 * m->fractionOver2, std::round(m->maxError * 255), m->maxX, m->maxY);
    a_ = *a;
    b_ = b->image;
    return *m;
  }

  // Where to look when the bound is missed.
  std::string saveImages(const std::string& label) {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / ("motorbench_equivalence_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::string stem = (dir / (GetParam().scene + "." + label + ".")).string();
    writeImage(stem + "matrix.png", a_);
    writeImage(stem + GetParam().pipeline + ".png", b_);
    writeImage(stem + "diff.png", diffHeatmap(a_, b_));
    return "images: " + stem + "{matrix," + GetParam().pipeline + ",diff}.png";
  }

  void expectEquivalent(const ImageMetrics& m, const std::string& label) {
    bool ok = m.psnr >= 50.0 && m.fractionOver2 <= 0.001;
    EXPECT_GE(m.psnr, 50.0) << label;
    EXPECT_LE(m.fractionOver2, 0.001) << label << ", max error at (" << m.maxX << "," << m.maxY << ")";
    if (!ok) ADD_FAILURE() << saveImages(label);
  }

  RgbaImage a_, b_;
};

TEST_P(Equivalence, MatchesMatrixAtRestPose) {
  // Rest pose: rigid scenes as authored, skinned ones in their bind pose.
  expectEquivalent(compareAt(AnimState{}, "rest"), "rest");
}

TEST_P(Equivalence, AnimatedFramesStayClose) {
  // Animated poses differ by design on skinned meshes (linear blend vs motor skinning), so only
  // rigid animation is held to the tight bound; skinned poses must still render comparably.
  if (scene_.animations.empty()) GTEST_SKIP() << "no animation";
  AnimState anim{0, 0.4f * scene_.animations[0].duration};
  ImageMetrics m = compareAt(anim, "anim0");
  if (scene_.skins.empty()) expectEquivalent(m, "anim0");
  else EXPECT_GE(m.psnr, 20.0);
}

INSTANTIATE_TEST_SUITE_P(VsMatrix, Equivalence, ::testing::ValuesIn(pipelineSceneCases(false)), caseName);

}  // namespace
