// Parameterised tests over (registered pipeline, built-in scene of its space). The cases come
// from the registry, so a new pipeline is covered by its registry line alone: glTF pipelines x
// the glTF built-ins, curved ones x the curved scenes of their space (s3_tiling, h3_tiling);
// placeholder pipelines (factory returns nullptr) are skipped, and the scene is loaded once
// per test.
#pragma once
#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "pipelines/pipeline.h"
#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/curved_space.h"
#include "pipelines/scene/loader.h"

namespace mb {

struct PipelineScene {
  std::string pipeline, scene;
};
// How gtest shows a case (instead of its bytes).
inline void PrintTo(const PipelineScene& c, std::ostream* os) { *os << c.pipeline << " on " << c.scene; }

// Every registered pipeline x every built-in scene of its space; `withBaselines` false leaves
// out each space's baseline (matrix, s3_matrix, h3_matrix), for tests that compare with it.
inline std::vector<PipelineScene> pipelineSceneCases(bool withBaselines = true) {
  std::vector<PipelineScene> out;
  for (Space space : {Space::Euclidean, Space::Spherical, Space::Hyperbolic}) {
    const std::vector<std::string> pipes = pipelineNames(space);
    std::vector<std::string> scenes;
    if (space == Space::Euclidean) scenes = builtinSceneNames();
    for (const std::string& c : curvedSceneNames())
      if (space != Space::Euclidean && curvedSceneSpace(c) == space) scenes.push_back(c);
    for (size_t i = withBaselines ? 0 : 1; i < pipes.size(); ++i)
      for (const std::string& s : scenes) out.push_back({pipes[i], s});
  }
  return out;
}

inline std::string caseName(const ::testing::TestParamInfo<PipelineScene>& info) {
  return info.param.pipeline + "_" + info.param.scene;
}

class PipelineSceneTest : public ::testing::TestWithParam<PipelineScene> {
protected:
  void SetUp() override {
    if (!createPipeline(GetParam().pipeline)) GTEST_SKIP() << "placeholder pipeline";
    auto s = loadScene(GetParam().scene);
    ASSERT_TRUE(s) << s.error();
    scene_ = s.take();
  }
  Scene scene_;
};

}  // namespace mb
