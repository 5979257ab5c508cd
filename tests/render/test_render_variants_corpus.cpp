// Every registered pipeline against matrix on every glTF file of ../shared/corpus at the rest
// pose: PSNR >= 45 dB, the bound of the quantized-frame pipelines (qtangent,
// motor_q, hybrid), which the float pipelines clear too. barrel.glb is normal-mapped with
// authored tangents, the case where an int16 frame could show.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "pipelines/scene/loader.h"

namespace fs = std::filesystem;
using namespace mb;

TEST(CorpusVariants, EveryPipelineWithin45DbOfMatrixAtRest) {
  const fs::path dir = fs::path(MB_SOURCE_DIR) / ".." / "shared" / "corpus";
  if (!fs::is_directory(dir)) GTEST_SKIP() << "no corpus at " << dir;
  int compared = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string ext = e.path().extension().string();
    if (ext != ".gltf" && ext != ".glb") continue;
    auto scene = loadScene(e.path().string());
    ASSERT_TRUE(scene) << scene.error();
    FrameSettings s;
    s.width = s.height = 128;
    auto reference = renderFrame(*scene, "matrix", s);
    ASSERT_TRUE(reference) << reference.error();
    for (const std::string& p : pipelineNames()) {
      if (p == "matrix" || !createPipeline(p)) continue;
      auto frame = renderFrame(*scene, p, s);
      ASSERT_TRUE(frame) << p << ": " << frame.error();
      auto m = compareImages(reference->image, frame->image);
      ASSERT_TRUE(m) << m.error();
      std::printf("[ corpus ] %-22s %-9s PSNR %.2f dB\n", e.path().filename().c_str(), p.c_str(), m->psnr);
      EXPECT_GE(m->psnr, 45.0) << e.path().filename() << " " << p;
      ++compared;
    }
  }
  EXPECT_GT(compared, 0);
}
