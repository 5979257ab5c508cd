// Determinism (DESIGN idea 6): the same frame rendered twice in one process,
// and by two separate `motorbench render` processes (one of them on a single llvmpipe thread),
// is bit-identical, for every built-in scene and registered pipeline, at rest and at an
// animation time. Goldens rely on this. The process pair renders every pipeline of a scene's
// space in one `render --pipelines all` each (a process start costs more than these frames).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/pipeline.h"
#include "pipelines/scene/curved_space.h"
#include "pipelines/scene/loader.h"
#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using namespace mb;

constexpr int kW = 160, kH = 120;

std::vector<char> bytesOf(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// "" when identical, else where the first difference is.
std::string firstDifference(const RgbaImage& a, const RgbaImage& b) {
  if (a.width != b.width || a.height != b.height) return "sizes differ";
  for (size_t i = 0; i < a.rgba.size(); ++i)
    if (a.rgba[i] != b.rgba[i]) {
      size_t px = i / 4;
      return "pixel (" + std::to_string(px % size_t(a.width)) + "," + std::to_string(px / size_t(a.width)) +
             ") channel " + std::to_string(i % 4) + ": " + std::to_string(a.rgba[i]) + " vs " +
             std::to_string(b.rgba[i]);
    }
  return "";
}

// Rest pose, and animation 0 at a time exactly representable in the decimal form passed to the
// command line (a multiple of 1/64), so both paths pose the same state.
std::vector<AnimState> determinismStates(const Scene& scene) {
  std::vector<AnimState> out = {AnimState{}};
  if (!scene.animations.empty()) {
    AnimState a;
    a.anim = 0;
    a.time = a.time2 = std::floor(0.4f * scene.animations[0].duration * 64.0f) / 64.0f;
    out.push_back(a);
  }
  return out;
}

RgbaImage renderSmallFrame(const Scene& scene, const std::string& pipeline, const AnimState& anim) {
  FrameSettings s;
  s.anim = anim;
  s.width = kW;
  s.height = kH;
  auto f = renderFrame(scene, pipeline, s);
  EXPECT_TRUE(f) << pipeline << ": " << f.error();
  return f ? f->image : RgbaImage{};
}

// Every scene the determinism tests cover: the glTF built-ins and the curved-space scenes.
std::vector<std::string> determinismScenes() {
  std::vector<std::string> out = builtinSceneNames();
  for (const std::string& c : curvedSceneNames()) out.push_back(c);
  return out;
}

// Every pipeline of `scene`'s space at every determinism state, in registry order.
using FramesByPipeline = std::map<std::string, std::vector<RgbaImage>>;
FramesByPipeline renderEveryPipeline(const Scene& scene) {
  FramesByPipeline out;
  for (const std::string& p : pipelineNames(scene.curved.space)) {
    if (!createPipeline(p)) continue;  // a placeholder pipeline draws nothing
    for (const AnimState& anim : determinismStates(scene)) out[p].push_back(renderSmallFrame(scene, p, anim));
  }
  return out;
}

// A scene's first in-process frames, rendered once per test process: both tests below compare
// with them (a second in-process round; the two render processes), so a process that runs both
// for a scene renders them once.
const FramesByPipeline& firstFrames(const std::string& name, const Scene& scene) {
  static std::map<std::string, FramesByPipeline> frames;
  auto it = frames.find(name);
  if (it == frames.end()) it = frames.emplace(name, renderEveryPipeline(scene)).first;
  return it->second;
}

class SceneDeterminism : public ::testing::TestWithParam<std::string> {
protected:
  void SetUp() override {
    auto s = loadScene(GetParam());
    ASSERT_TRUE(s) << s.error();
    scene_ = s.take();
  }
  Scene scene_;
};

// Each pipeline's frames drawn twice in one process with every other pipeline of the space drawn
// in between (all of them at every state: GL state one of them leaves behind must not leak into
// frames): one case per scene, each pipeline's first frame against its second.
TEST_P(SceneDeterminism, SameFrameTwiceInOneProcess) {
  const FramesByPipeline& first = firstFrames(GetParam(), scene_);
  const std::vector<AnimState> states = determinismStates(scene_);
  for (const std::string& p : pipelineNames(scene_.curved.space)) {
    if (!first.count(p)) continue;  // a placeholder pipeline
    for (size_t i = 0; i < states.size(); ++i) {
      ASSERT_FALSE(first.at(p)[i].rgba.empty()) << p;
      EXPECT_EQ(firstDifference(first.at(p)[i], renderSmallFrame(scene_, p, states[i])), "")
          << p << ": anim " << states[i].anim << " time " << states[i].time;
    }
  }
}

TEST_P(SceneDeterminism, SeparateProcessesMatchEachOtherAndThisProcess) {
  const fs::path dir = mb::cli_test::scratchDir("determinism");
  const std::vector<std::string> pipelines = pipelineNames(scene_.curved.space);
  ASSERT_FALSE(pipelines.empty());
  const FramesByPipeline& inProcess = firstFrames(GetParam(), scene_);
  const std::vector<AnimState> states = determinismStates(scene_);
  for (size_t i = 0; i < states.size(); ++i) {
    const AnimState& anim = states[i];
    char animArgs[96] = "";
    if (anim.anim >= 0) std::snprintf(animArgs, sizeof animArgs, " --anim %d --time %.6f", anim.anim, double(anim.time));
    // The second process rasterizes on one llvmpipe thread: goldens must not depend on the
    // number of cores of the machine that runs the check.
    const fs::path dirs[2] = {dir / "default", dir / "one_thread"};
    const char* env[2] = {"", "LP_NUM_THREADS=1 "};
    for (int k = 0; k < 2; ++k) {
      std::string out;
      int rc = mb::cli_test::runCommand(env[k] + mb::cli_test::motorbench() + "render " + GetParam() +
                                            " --pipelines all --size " + std::to_string(kW) + "x" + std::to_string(kH) +
                                            animArgs + " -o " + mb::cli_test::quoted(dirs[k]),
                                        &out);
      ASSERT_EQ(rc, 0) << out;
      // "all": one image per registered pipeline of the scene's space, nothing else.
      std::set<std::string> written, expected;
      for (const auto& e : fs::directory_iterator(dirs[k])) written.insert(e.path().filename().string());
      for (const std::string& p : pipelines) expected.insert(p + ".png");
      EXPECT_EQ(written, expected) << env[k] << animArgs;
    }
    for (const std::string& p : pipelines) {
      const fs::path files[2] = {dirs[0] / (p + ".png"), dirs[1] / (p + ".png")};
      EXPECT_EQ(bytesOf(files[0]), bytesOf(files[1])) << p << ": PNG files differ (default vs LP_NUM_THREADS=1)" << animArgs;
      auto a = readImage(files[0].string());
      auto b = readImage(files[1].string());
      EXPECT_TRUE(a && b) << p << ": an image did not decode" << animArgs;
      if (!a || !b) continue;
      ASSERT_TRUE(inProcess.count(p)) << p << ": no in-process frame (a placeholder pipeline)";
      EXPECT_EQ(firstDifference(*a, *b), "") << p << ": process vs process (default vs LP_NUM_THREADS=1)" << animArgs;
      EXPECT_EQ(firstDifference(*a, inProcess.at(p)[i]), "") << p << ": process vs in-process" << animArgs;
    }
    for (const fs::path& d : dirs) fs::remove_all(d);
  }
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(BuiltinScenes, SceneDeterminism, ::testing::ValuesIn(determinismScenes()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
