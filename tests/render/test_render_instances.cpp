// Instanced draws (EXT_mesh_gpu_instancing, `--instances N`): the bytes every pipeline streams
// per instance against the per-draw transform each one documents (hand-derived: matrix 2 mat4
// = 128 bytes, affine family mat4x3 + mat3 + mirror = 22 floats = 88 bytes, motor family
// motor + scale = 9 floats = 36 bytes, 11 floats = 44 bytes on the scale fallback), drawn
// vertices multiplied by the instances, and a grid of instances that changes the image.
#include <gtest/gtest.h>

#include <map>

#include "harness/render/render_frame.h"
#include "pipelines/scene/instancing.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"

using namespace mb;

namespace {

// matrix_c, motor_c and motor_cf compact the vertex, not the instance: as affine and
// motor (their dequantisation is a per-draw uniform).
const std::map<std::string, uint64_t> kBytesPerInstance = {{"matrix", 128}, {"affine", 88}, {"qtangent", 88},
                                                           {"hybrid", 88},  {"matrix_c", 88}, {"motor", 36},
                                                           {"motor_q", 36}, {"motor_c", 36},
                                                           {"motor_cf", 36}};

Scene load(const std::string& name) {
  auto s = loadScene(name);
  EXPECT_TRUE(s) << s.error();
  return s ? s.take() : Scene{};
}

Frame render(const Scene& scene, const std::string& pipeline) {
  FrameSettings settings;
  settings.width = settings.height = 64;
  auto f = renderFrame(scene, pipeline, settings);
  EXPECT_TRUE(f) << f.error();
  return f ? *f : Frame{};
}

// Pixels that are not the clear colour.
int covered(const RgbaImage& image) {
  int n = 0;
  for (size_t i = 0; i + 3 < image.rgba.size(); i += 4)
    n += image.rgba[i] != uint8_t(kBackground[0] * 255.0f + 0.5f) || image.rgba[i + 1] != uint8_t(kBackground[1] * 255.0f + 0.5f);
  return n;
}

TEST(Instances, GridOfFourDrawsFourTimesTheVerticesInEveryPipeline) {
  const Scene one = load("normal_torus");
  Scene four = one;
  EXPECT_EQ(addGridInstances(four, 4), 0);
  ASSERT_EQ(four.nodes[0].instances.size(), 4u);
  for (const std::string& p : pipelineNames()) {
    SCOPED_TRACE(p);
    const Frame a = render(one, p), b = render(four, p);
    EXPECT_EQ(a.stats.instances, 0u);
    EXPECT_EQ(a.stats.instanceBytes, 0u);
    EXPECT_EQ(a.stats.drawnVertices, a.stats.vertices) << "one node, drawn once";
    EXPECT_EQ(b.stats.drawnVertices, 4 * a.stats.drawnVertices);
    EXPECT_EQ(b.stats.vertices, a.stats.vertices) << "instancing uploads no vertex twice";
    EXPECT_EQ(b.stats.instances, 4u);
    EXPECT_EQ(b.stats.instanceBytes, 4 * kBytesPerInstance.at(p));
    EXPECT_NE(a.image.rgba, b.image.rgba);
    EXPECT_GT(covered(b.image), 64 * 64 / 50) << "the grid is drawn, not a blank image";
  }
}

TEST(Instances, InstancedGridStreamsEachPipelinesTransformPerInstance) {
  const Scene scene = load("instanced_grid");
  const FileStats f = computeFileStats(scene);
  EXPECT_EQ(f.instancedNodes, 1);
  EXPECT_EQ(f.instances, 256);
  for (const std::string& p : pipelineNames()) {
    SCOPED_TRACE(p);
    const Frame frame = render(scene, p);
    EXPECT_EQ(frame.stats.instances, 256u);
    EXPECT_EQ(frame.stats.drawnVertices, uint64_t(f.drawnVertices));
    const bool motorFamily = p == "motor" || p == "motor_q" || p == "motor_c" || p == "motor_cf";
    // Instance 17 (non-uniform) and 40 (mirrored) take the motor scale fallback: vec3 scale.
    EXPECT_EQ(frame.stats.instanceBytes, motorFamily ? 254 * 36 + 2 * 44 : 256 * kBytesPerInstance.at(p));
    EXPECT_EQ(frame.stats.scaleFallbackInstances, motorFamily ? 2 : 0);
    // Draws: one per primitive and group (plain, mirrored; motor: plain, fallback, mirrored fallback).
    EXPECT_EQ(frame.stats.draws, motorFamily ? 3 : 2);
  }
}

TEST(Instances, SkinnedNodesStayDrawnOnce) {
  Scene crowd = load("crowd");
  const int meshNodes = computeFileStats(crowd).meshNodes;
  EXPECT_EQ(addGridInstances(crowd, 3), meshNodes) << "every crowd member is skinned";
  EXPECT_EQ(computeFileStats(crowd).instances, 0);
}

TEST(Instances, OneInstanceChangesNothing) {
  Scene scene = load("textured_box");
  EXPECT_EQ(addGridInstances(scene, 1), 0);
  EXPECT_TRUE(scene.nodes[0].instances.empty());
}

}  // namespace
