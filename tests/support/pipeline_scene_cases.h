// Parameterised tests over (registered pipeline, built-in scene). The cases come from
// pipelineNames(), so a new pipeline is covered by its registry line alone; placeholder
// pipelines (factory returns nullptr) are skipped, and the scene is loaded once per test.
#pragma once
#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "pipelines/pipeline.h"
#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/loader.h"

namespace mb {

struct PipelineScene {
  std::string pipeline, scene;
};
// How gtest shows a case (instead of its bytes).
inline void PrintTo(const PipelineScene& c, std::ostream* os) { *os << c.pipeline << " on " << c.scene; }

// Every registered pipeline (but `except`) x every built-in scene.
inline std::vector<PipelineScene> pipelineSceneCases(const std::string& except = "") {
  std::vector<PipelineScene> out;
  for (const std::string& p : pipelineNames())
    if (p != except)
      for (const std::string& s : builtinSceneNames()) out.push_back({p, s});
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
