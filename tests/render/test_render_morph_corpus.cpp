// The morph-target files of ../shared/corpus-wide (MANIFEST.tsv features "morph-targets")
// through matrix and the motor family's two morph methods, weights animated: every
// animation at a quarter, half and three quarters of its duration, plus the rest pose. Prints
// per method the worst PSNR vs matrix, its largest channel error and the frame where it
// occurs; the frame method must reach 50 dB on every frame of the unskinned files (the skinned
// ones add motor skinning's own difference, measured by the skinning tests). Skipped without
// the folder.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "pipelines/pipeline.h"
#include "pipelines/scene/loader.h"
#include "tests/support/render_options.h"

namespace fs = std::filesystem;
using namespace mb;

namespace {

constexpr int kSize = 128;

struct Worst {
  double psnr = std::numeric_limits<double>::infinity(), maxError = 0;
  std::string frame = "none";
};

std::vector<std::string> morphFiles(const fs::path& dir) {
  std::vector<std::string> out;
  std::ifstream in(dir / "MANIFEST.tsv");
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cols;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, '\t');) cols.push_back(c);
    if (cols.size() > 8 && cols[8].find("morph-targets") != std::string::npos) out.push_back(cols[0]);
  }
  return out;
}

}  // namespace

TEST(MorphCorpus, MotorMethodsAgainstMatrixWithAnimatedWeights) {
  const fs::path dir = fs::path(MB_SOURCE_DIR) / ".." / "shared" / "corpus-wide";
  if (!fs::is_regular_file(dir / "MANIFEST.tsv")) GTEST_SKIP() << "no corpus-wide at " << dir;
  const std::vector<std::string> files = morphFiles(dir);
  ASSERT_FALSE(files.empty());
  const std::pair<const char*, MorphMethod> methods[] = {{"frame", MorphMethod::Frame}, {"rotor", MorphMethod::Rotor}};
  Worst worst[2], worstRigid[2];
  int frames = 0, morphedFrames = 0;
  for (const std::string& file : files) {
    auto scene = loadScene((dir / file).string());
    ASSERT_TRUE(scene) << scene.error();
    bool skinned = false;
    for (const Node& n : scene->nodes) skinned |= n.skin >= 0 && n.mesh >= 0;
    std::vector<AnimState> states{AnimState{}};
    for (size_t a = 0; a < scene->animations.size(); ++a)
      for (float f : {0.25f, 0.5f, 0.75f}) states.push_back({int(a), f * scene->animations[a].duration});
    // Each pipeline and method prepared once per file, every state drawn through it.
    const std::vector<Frame> matrix = mbtest::renderStatesWithOptions(*scene, "matrix", {}, states, kSize);
    std::vector<Frame> motor[2];
    for (int m = 0; m < 2; ++m)
      motor[m] = mbtest::renderStatesWithOptions(*scene, "motor", {SkinSpace::PipelineDefault, methods[m].second}, states, kSize);
    for (size_t i = 0; i < states.size(); ++i) {
      const AnimState& st = states[i];
      ++frames;
      morphedFrames += matrix[i].stats.morphDraws > 0;
      const std::string where = fs::path(file).filename().string() + " anim " + std::to_string(st.anim) + " t " +
                                std::to_string(st.time).substr(0, 5);
      for (int m = 0; m < 2; ++m) {
        const Frame& f = motor[m][i];
        EXPECT_EQ(f.stats.morphDraws, matrix[i].stats.morphDraws) << where;
        auto metrics = compareImages(matrix[i].image, f.image);
        ASSERT_TRUE(metrics) << metrics.error();
        for (Worst* w : {&worst[m], skinned ? nullptr : &worstRigid[m]})
          if (w && metrics->psnr < w->psnr) *w = {metrics->psnr, metrics->maxError, where};
        if (!skinned && methods[m].second == MorphMethod::Frame) EXPECT_GE(metrics->psnr, 50.0) << where;
      }
    }
  }
  std::printf("[ morph corpus ] %zu files, %d frames (%d with a morphing draw), %d px\n", files.size(), frames,
              morphedFrames, kSize);
  for (int m = 0; m < 2; ++m)
    std::printf("[ morph corpus ] motor %-5s worst PSNR %.2f dB (max error %.4f) at %s; unskinned files %.2f dB at %s\n",
                methods[m].first, worst[m].psnr, worst[m].maxError, worst[m].frame.c_str(), worstRigid[m].psnr,
                worstRigid[m].frame.c_str());
  EXPECT_GT(morphedFrames, 0);
}

// Every pipeline draws the morph files as matrix does: on every frame it morphs the
// draws matrix morphs (at least as many: motor_cf may split one) and counts no node drawn in its
// base shape. Prints each pipeline's worst PSNR vs matrix over the frames where matrix morphs.
TEST(MorphCorpus, EveryPipelineMorphsWhatMatrixMorphs) {
  const fs::path dir = fs::path(MB_SOURCE_DIR) / ".." / "shared" / "corpus-wide";
  if (!fs::is_regular_file(dir / "MANIFEST.tsv")) GTEST_SKIP() << "no corpus-wide at " << dir;
  const std::vector<std::string> files = morphFiles(dir);
  ASSERT_FALSE(files.empty());
  std::map<std::string, Worst> worst;
  for (const std::string& file : files) {
    auto scene = loadScene((dir / file).string());
    ASSERT_TRUE(scene) << scene.error();
    std::vector<AnimState> states{AnimState{}};  // the rest pose (default weights), then the animations
    for (size_t a = 0; a < scene->animations.size(); ++a)
      for (float f : {0.25f, 0.5f, 0.75f}) states.push_back({int(a), f * scene->animations[a].duration});
    // The states where matrix morphs; each pipeline prepared once per file and drawn at each.
    const std::vector<Frame> all = mbtest::renderStatesWithOptions(*scene, "matrix", {}, states, kSize);
    std::vector<AnimState> morphing;
    std::vector<Frame> matrix;
    for (size_t i = 0; i < states.size(); ++i)
      if (all[i].stats.morphDraws > 0) morphing.push_back(states[i]), matrix.push_back(all[i]);
    if (morphing.empty()) continue;
    for (const std::string& p : pipelineNames()) {
      const std::vector<Frame> frames = mbtest::renderStatesWithOptions(*scene, p, {}, morphing, kSize);
      for (size_t i = 0; i < morphing.size(); ++i) {
        const std::string where = fs::path(file).filename().string() + " anim " + std::to_string(morphing[i].anim) +
                                  " t " + std::to_string(morphing[i].time).substr(0, 5);
        EXPECT_GE(frames[i].stats.morphDraws, matrix[i].stats.morphDraws) << p << " " << where;
        EXPECT_EQ(frames[i].stats.morphNotDrawnNodes, 0) << p << " " << where;
        auto metrics = compareImages(matrix[i].image, frames[i].image);
        ASSERT_TRUE(metrics) << metrics.error();
        if (metrics->psnr < worst[p].psnr) worst[p] = {metrics->psnr, metrics->maxError, where};
      }
    }
  }
  for (const auto& [p, w] : worst)
    std::printf("[ morph corpus ] %-9s worst PSNR vs matrix %.2f dB (max error %.4f) at %s\n", p.c_str(), w.psnr,
                w.maxError, w.frame.c_str());
  EXPECT_EQ(worst.size(), pipelineNames().size()) << "some frame morphed";
}
