// Every glTF file of ../shared/corpus renders with the matrix pipeline without error, at the
// rest pose and at several times of every animation, and draws something.
#include <gtest/gtest.h>

#include <filesystem>

#include "harness/render/render_frame.h"
#include "pipelines/scene/loader.h"

namespace fs = std::filesystem;
using namespace mb;

namespace {

fs::path corpusDir() { return fs::path(MB_SOURCE_DIR) / ".." / "shared" / "corpus"; }

bool drewSomething(const RgbaImage& img) {
  for (size_t p = 0; p < img.rgba.size(); p += 4)
    for (int c = 0; c < 3; ++c)
      if (std::abs(int(img.rgba[p + c]) - int(kBackground[c] * 255.0f + 0.5f)) > 1) return true;
  return false;
}

}  // namespace

TEST(CorpusRender, EveryFileAtSeveralTimes) {
  if (!fs::is_directory(corpusDir())) GTEST_SKIP() << "no corpus at " << corpusDir();
  int rendered = 0;
  for (const auto& e : fs::directory_iterator(corpusDir())) {
    std::string ext = e.path().extension().string();
    if (ext != ".gltf" && ext != ".glb") continue;
    auto scene = loadScene(e.path().string());
    ASSERT_TRUE(scene) << scene.error();
    std::vector<AnimState> states = {AnimState{}};
    for (size_t a = 0; a < scene->animations.size(); ++a)
      for (float f : {0.0f, 0.37f, 1.0f})
        states.push_back({int(a), f * scene->animations[a].duration});
    if (scene->animations.size() >= 2) states.push_back({0, 0.2f, 1, 0.4f, 0.5f});
    for (const AnimState& s : states) {
      FrameSettings settings;
      settings.anim = s;
      settings.width = settings.height = 64;
      auto frame = renderFrame(*scene, "matrix", settings);
      ASSERT_TRUE(frame) << frame.error();
      EXPECT_TRUE(drewSomething(frame->image))
          << e.path().filename() << " anim " << s.anim << " t " << s.time << ": empty image";
      ++rendered;
    }
  }
  EXPECT_GT(rendered, 0);
}
