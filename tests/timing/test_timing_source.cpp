// Where the frame-time figure comes from (harness/timing/frame_timing.h): the rule as a pure
// function, and the GL_TIME_ELAPSED path itself, forced on llvmpipe (where it is never the
// figure) so that it runs without a GPU.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "harness/document/report_format.h"
#include "harness/render/render_frame.h"
#include "harness/timing/frame_timing.h"
#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/loader.h"

namespace {

using mb::timing::FrameTimeSource;

TEST(FrameTimeSource, GpuTimerOnlyOnARealGpuWithATimer) {
  EXPECT_EQ(mb::timing::chooseFrameTimeSource(true, 64), FrameTimeSource::GpuTimer);
  EXPECT_EQ(mb::timing::chooseFrameTimeSource(false, 64), FrameTimeSource::WallClock);
  EXPECT_EQ(mb::timing::chooseFrameTimeSource(true, 0), FrameTimeSource::WallClock);  // no counter bits
  EXPECT_EQ(mb::timing::chooseFrameTimeSource(false, 64, true), FrameTimeSource::GpuTimer);
  EXPECT_EQ(mb::timing::chooseFrameTimeSource(false, 0, true), FrameTimeSource::WallClock);
  EXPECT_STREQ(mb::timing::toString(FrameTimeSource::GpuTimer), "gpu-timer");
  EXPECT_STREQ(mb::timing::toString(FrameTimeSource::WallClock), "wall-clock");
}

mb::timing::Settings quick() {
  mb::timing::Settings s;
  s.frames = 4, s.warmup = 1, s.bestOf = 1;
  s.width = s.height = 64;
  return s;
}

TEST(FrameTiming, LlvmpipeTimesByTheWallClock) {
  auto scene = mb::loadScene("normal_torus");
  ASSERT_TRUE(scene) << scene.error();
  auto t = mb::timing::timeScene(*scene, "normal_torus", quick());
  ASSERT_TRUE(t) << t.error();
  EXPECT_EQ(t->source, FrameTimeSource::WallClock);
  for (const auto& p : t->pipelines) {
    ASSERT_TRUE(p.error.empty()) << p.pipeline << ": " << p.error;
    EXPECT_TRUE(p.gpuMs.empty()) << p.pipeline;
    EXPECT_EQ(p.frameMs, p.wallMs) << p.pipeline;  // the figure is the wall clock
  }
  EXPECT_EQ(mb::timing::toJson(*t)["frameTimeSource"], "wall-clock");
}

// Forced: one query per render, read after glFinish. Every sample is positive, no longer than
// the wall clock around the same render (which also waits for glFinish) plus a millisecond of
// clock granularity, and becomes the frame-time figure. dense_torus at 64x64 is vertex-bound:
// the printed medians show how much of the frame llvmpipe's query leaves out (README.md).
TEST(FrameTiming, ForcedTimerQueriesGiveSaneValuesOnLlvmpipe) {
  auto scene = mb::loadScene("dense_torus");
  ASSERT_TRUE(scene) << scene.error();
  mb::timing::Settings s = quick();
  s.forceTimerQueries = true;
  auto t = mb::timing::timeScene(*scene, "dense_torus", s);
  ASSERT_TRUE(t) << t.error();
  ASSERT_EQ(t->source, FrameTimeSource::GpuTimer);
  for (const auto& p : t->pipelines) {
    ASSERT_TRUE(p.error.empty()) << p.pipeline << ": " << p.error;
    ASSERT_EQ(p.gpuMs.size(), size_t(s.frames)) << p.pipeline;
    ASSERT_EQ(p.wallMs.size(), size_t(s.frames)) << p.pipeline;
    EXPECT_EQ(p.frameMs, p.gpuMs) << p.pipeline;
    for (size_t i = 0; i < p.gpuMs.size(); ++i) {
      EXPECT_GT(p.gpuMs[i], 0.0) << p.pipeline << " frame " << i;
      EXPECT_LT(p.gpuMs[i], p.wallMs[i] + 1.0) << p.pipeline << " frame " << i;
    }
    std::printf("%-9s timer query median %.3f ms, wall clock median %.3f ms\n", p.pipeline.c_str(), p.gpu.median,
                p.wall.median);
  }
  const nlohmann::json j = mb::timing::toJson(*t);
  EXPECT_EQ(j["frameTimeSource"], "gpu-timer");
  EXPECT_TRUE(j["pipelines"]["matrix"]["gpu_ms"].is_object());
  EXPECT_TRUE(j["pipelines"]["matrix"]["wall_ms"].is_object());
}

// The report's timing tables name their device from the record report.json keeps.
TEST(FrameTimeDevice, TablesNameTheDeviceAndItsClock) {
  mb::gl::ContextInfo h100;
  h100.backend = "egl-device 1", h100.renderer = "NVIDIA H100 80GB HBM3/PCIe/SSE2";
  h100.deviceIndex = 1, h100.deviceSoftware = false, h100.drm = "/dev/dri/renderD128";
  const nlohmann::json gpu = mb::toJson(h100);
  EXPECT_EQ(gpu["kind"], "gpu");
  EXPECT_EQ(gpu["device"]["drm"], "/dev/dri/renderD128");
  EXPECT_EQ(mb::document::frameTimeOn(gpu), "Frame time on NVIDIA H100 80GB HBM3/PCIe/SSE2 (GPU timer queries)");
  mb::gl::ContextInfo llvm;
  llvm.backend = "egl-surfaceless", llvm.renderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
  const nlohmann::json cpu = mb::toJson(llvm);
  EXPECT_EQ(cpu["kind"], "cpu-rasterizer");
  EXPECT_TRUE(cpu["device"]["index"].is_null());
  EXPECT_EQ(mb::document::frameTimeOn(cpu),
            "Frame time on llvmpipe (LLVM 15.0.6, 256 bits) \u2014 a CPU rasterizer (wall clock)");
  EXPECT_EQ(mb::document::frameTimeOn(nlohmann::json{{"error", "no context"}}), "Frame time (device not recorded)");
}

}  // namespace
