// Morph targets in every glTF pipeline, instanced draws included. The reference for a
// pipeline P is P itself drawing the same shape with the morph baked into the mesh on the CPU
// (each attribute plus its weighted deltas, in target order, as glTF 2.0 3.7.2.2 defines it):
// that image carries P's own quantisation of the shape and nothing of the morph path. Against
// matrix on the morphed scene, P may then cost what its own format costs on that shape (P baked
// vs matrix baked), plus at most 3 dB: the GPU morph adds float deltas to P's decoded vertex,
// where the baked mesh is quantised after the morph, two roundings of the same size, so the
// squared error may double (10 log10 2 = 3.01 dB), no more. Pipelines that draw the baked shape
// exactly as matrix does must draw the morph within 60 dB of matrix.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "pipelines/pipeline.h"
#include "pipelines/scene/animation.h"
#include "pipelines/scene/instancing.h"
#include "pipelines/scene/loader.h"
#include "tests/support/render_options.h"

using namespace mb;

namespace {

constexpr int kSize = 128;

// `s` with every node's sampled morph weights applied to its mesh on the CPU (the mesh must not
// be shared by nodes with other weights), the targets, weights and weights channels removed.
Scene baked(Scene s, const AnimState& st) {
  const std::vector<std::vector<float>> weights = sampleMorphWeights(s, st);
  for (size_t n = 0; n < s.nodes.size(); ++n) {
    if (s.nodes[n].mesh < 0 || weights[n].empty()) continue;
    for (Primitive& p : s.meshes[size_t(s.nodes[n].mesh)].primitives)
      for (size_t t = 0; t < p.targets.size(); ++t) {
        const float w = weights[n][t];
        const MorphTarget& d = p.targets[t];
        if (w == 0.0f) continue;
        for (size_t v = 0; v < p.positions.size(); ++v) {
          p.positions[v] += w * d.positions[v];
          if (!d.normals.empty()) p.normals[v] += w * d.normals[v];
          if (!d.tangents.empty() && !p.tangents.empty()) p.tangents[v] += glm::vec4(w * d.tangents[v], 0.0f);
        }
      }
  }
  for (Mesh& m : s.meshes) {
    m.weights.clear();
    for (Primitive& p : m.primitives) p.targets.clear();
  }
  for (Node& n : s.nodes) n.weights.clear();
  for (Animation& a : s.animations)
    std::erase_if(a.channels, [](const Channel& c) { return c.path == AnimPath::Weights; });
  return s;
}

Frame render(const Scene& scene, const std::string& pipeline, const AnimState& st) {
  return mbtest::renderWithOptions(scene, pipeline, {}, st, kSize);
}

double psnr(const Frame& a, const Frame& b) {
  auto m = compareImages(a.image, b.image);
  EXPECT_TRUE(m) << m.error();
  return m ? m->psnr : 0.0;
}

// Every pipeline draws `scene` at `st` morphed: at least matrix's morphing draws (more on
// motor_cf: 2 when a draw's unresolved triangles are drawn apart), within its own format's cost
// of matrix.
void expectEveryPipelineMorphs(const Scene& scene, const AnimState& st, const char* what) {
  const Scene flat = baked(scene, st);
  const Frame matrix = render(scene, "matrix", st), matrixBaked = render(flat, "matrix", st);
  ASSERT_GT(matrix.stats.morphDraws, 0) << what;
  // matrix against the glTF sum by hand: the same pixels.
  EXPECT_EQ(matrix.image.rgba, matrixBaked.image.rgba) << what << ": matrix vs the morph by hand";
  for (const std::string& p : pipelineNames()) {
    SCOPED_TRACE(std::string(what) + " " + p);
    const Frame morphed = render(scene, p, st), own = render(flat, p, st);
    EXPECT_GE(morphed.stats.morphDraws, matrix.stats.morphDraws);
    EXPECT_GT(morphed.stats.morphBytes, 0u);
    EXPECT_EQ(own.stats.morphDraws, 0);
    const double cost = psnr(own, matrixBaked), got = psnr(morphed, matrix);
    const double floor = std::isinf(cost) ? 60.0 : cost - 3.01;
    EXPECT_GE(got, floor) << "its format on the baked shape costs " << cost << " dB";
    std::printf("%s %-9s vs matrix %6.1f dB (baked shape: %6.1f dB; vs its own baked %6.1f dB)\n", what,
                p.c_str(), got, cost, psnr(morphed, own));
  }
}

}  // namespace

// morph_torus at t 1.4 s: weights (1, 0.4), both targets with normal and tangent deltas.
TEST(MorphEveryPipeline, MorphTorusAnimated) {
  auto torus = loadScene("morph_torus");
  ASSERT_TRUE(torus) << torus.error();
  expectEveryPipelineMorphs(*torus, AnimState{0, 1.4f}, "morph_torus t 1.4");
  expectEveryPipelineMorphs(*torus, AnimState{0, 2.5f}, "morph_torus t 2.5");
}

// The same torus drawn as a grid of 4 instances (EXT_mesh_gpu_instancing): every instance
// morphed by its node's weights.
TEST(MorphEveryPipeline, InstancedMorphTorus) {
  auto torus = loadScene("morph_torus");
  ASSERT_TRUE(torus) << torus.error();
  ASSERT_EQ(addGridInstances(*torus, 4), 0);
  expectEveryPipelineMorphs(*torus, AnimState{0, 1.4f}, "instanced morph_torus t 1.4");
}
