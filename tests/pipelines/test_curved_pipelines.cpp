// The curved-space scenes and pipelines: the scenes are what they claim (group
// sizes, isometries of the right space, points on the quadric), matrix and motor images of
// each space agree (PSNR >= 50 dB) and fill the view, uploads are 16 vs 8 floats per
// instance, and each kind of pipeline refuses the other kind of scene by name.
#include <cmath>
#include <cstdlib>
#include <set>

#include <gtest/gtest.h>

#include "harness/render/image_metrics.h"
#include "pipelines/curved/curved_motor.h"
#include "pipelines/gl/context.h"
#include "pipelines/gl/framebuffer.h"
#include "pipelines/pipeline.h"
#include "pipelines/scene/curved_space.h"
#include "pipelines/scene/loader.h"

namespace {

double form(int k, const glm::dvec4& a, const glm::dvec4& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z + k * a.w * b.w;
}

// max |M^T eta M - eta| over the entries.
double isometryError(int k, const glm::dmat4& m) {
  double worst = 0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      const double want = c == r ? (c == 3 ? double(k) : 1.0) : 0.0;
      worst = std::max(worst, std::abs(form(k, m[c], m[r]) - want));
    }
  return worst;
}

struct Rendered {
  mb::RgbaImage image;
  mb::PipelineStats stats;
};

mb::Result<Rendered> render(const mb::Scene& scene, const std::string& pipeline, float time,
                            int w = 256, int h = 192) {
  using R = mb::Result<Rendered>;
  auto ctx = mb::gl::sharedContext();
  if (!ctx) return R::fail(ctx.error());
  auto fb = mb::gl::Framebuffer::create(w, h);
  if (!fb) return R::fail(fb.error());
  auto p = mb::createPipeline(pipeline);
  if (!p) return R::fail("no pipeline " + pipeline);
  if (mb::Status s = p->prepare(scene); !s) return R::fail(s.error());
  p->update(mb::AnimState{0, time});
  mb::View view;
  view.aspect = float(w) / float(h);
  (*fb)->clear(0.2f, 0.2f, 0.22f, 1.0f);
  p->render(view);
  Rendered r;
  r.image = {w, h, (*fb)->readRgba()};
  r.stats = p->stats();
  return r;
}

// Fraction of pixels that differ from the clear colour.
double covered(const mb::RgbaImage& im) {
  size_t n = 0;
  for (size_t i = 0; i < im.rgba.size(); i += 4)
    n += im.rgba[i] != 51 || im.rgba[i + 1] != 51 || im.rgba[i + 2] != 56;
  return double(n) / double(im.width * im.height);
}

}  // namespace

TEST(CurvedScenes, S3TilingIsTheReferenceGroupTiling) {
  auto s = mb::loadScene("s3_tiling");
  ASSERT_TRUE(s) << s.error();
  const mb::CurvedScene& c = s->curved;
  EXPECT_EQ(c.space, mb::Space::Spherical);
  ASSERT_EQ(c.instances.size(), 14400u);  // 120 x 120 pairs
  ASSERT_EQ(c.positions.size(), 3u);
  double worst = 0;
  std::set<std::vector<long long>> distinct;
  for (const glm::dmat4& m : c.instances) {
    worst = std::max(worst, isometryError(1, m));
    EXPECT_GT(glm::determinant(m), 0.0);
    std::vector<long long> key;
    for (int k = 0; k < 16; ++k) key.push_back(std::llround(m[k / 4][k % 4] * 1e6));
    distinct.insert(key);
  }
  EXPECT_LT(worst, 1e-12);
  // (q1, q2) and (-q1, -q2) are the same map: 7,200 distinct isometries.
  EXPECT_EQ(distinct.size(), 7200u);
  for (size_t v = 0; v < 3; ++v) {
    const glm::dvec4 p(c.positions[v]), n(c.normals[v]);
    EXPECT_NEAR(form(1, p, p), 1.0, 1e-6);
    EXPECT_NEAR(form(1, n, n), 1.0, 1e-6);
    EXPECT_NEAR(form(1, p, n), 0.0, 1e-6);
  }
  ASSERT_EQ(s->animations.size(), 1u);
  EXPECT_GT(s->animations[0].duration, 0.0f);
}

TEST(CurvedScenes, H3TilingCellsAreDistinctCubesOfTheHoneycomb) {
  auto s = mb::loadScene("h3_tiling");
  ASSERT_TRUE(s) << s.error();
  const mb::CurvedScene& c = s->curved;
  EXPECT_EQ(c.space, mb::Space::Hyperbolic);
  ASSERT_GE(c.instances.size(), 10000u);
  // Cell centres: on the hyperboloid, and no two closer than the cube's face-to-face distance
  // 2a (sinh^2 a = cos 72deg), checked on a sample against all.
  const double twoA = 2.0 * std::asinh(std::sqrt(std::cos(2.0 * M_PI / 5.0)));
  std::vector<glm::dvec4> centres;
  double worst = 0;
  for (const glm::dmat4& m : c.instances) {
    worst = std::max(worst, isometryError(-1, m) / (1.0 + m[3][3] * m[3][3]));
    centres.push_back(m[3]);
  }
  EXPECT_LT(worst, 1e-12);
  for (size_t i = 0; i < centres.size(); i += 97)
    for (size_t j = 0; j < centres.size(); ++j) {
      if (i == j) continue;
      const double d = std::acosh(std::max(1.0, -form(-1, centres[i], centres[j])));
      ASSERT_GT(d, twoA - 1e-6) << i << " " << j;
    }
  ASSERT_EQ(c.positions.size(), 9u);
  for (size_t v = 0; v < 9; ++v) {
    const glm::dvec4 p(c.positions[v]), n(c.normals[v]);
    EXPECT_NEAR(form(-1, p, p), -1.0, 1e-6);
    EXPECT_NEAR(form(-1, n, n), 1.0, 1e-6);
    EXPECT_NEAR(form(-1, p, n), 0.0, 1e-6);
  }
}

// Every instance of both scenes converts to a motor whose matrix is the instance's.
TEST(CurvedScenes, MotorsOfAllInstancesReproduceTheirMatrices) {
  for (const char* name : {"s3_tiling", "h3_tiling"}) {
    auto s = mb::loadScene(name);
    ASSERT_TRUE(s) << s.error();
    const int k = mb::kappaOf(s->curved.space);
    double worst = 0;
    for (const glm::dmat4& m : s->curved.instances) {
      auto mo = mb::curved::motorOfMatrix(k, m);
      ASSERT_TRUE(mo) << name << ": " << mo.error();
      const glm::dmat4 back = mb::curved::matrixOfMotor(k, *mo);
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) worst = std::max(worst, std::abs(back[c][r] - m[c][r]) / (1 + std::abs(m[c][r])));
    }
    EXPECT_LT(worst, 1e-9) << name;
  }
  // Not an isometry: refused with the reason.
  auto bad = mb::curved::motorOfMatrix(1, glm::dmat4(2.0));
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("not an orientation-preserving isometry"), std::string::npos);
}

// The camera: the matrix side's view and the motor side's view motor are the same isometry.
TEST(CurvedScenes, ViewMotorEqualsViewMatrix) {
  for (const char* name : {"s3_tiling", "h3_tiling"}) {
    auto s = mb::loadScene(name);
    ASSERT_TRUE(s) << s.error();
    const int k = mb::kappaOf(s->curved.space);
    for (double t : {0.0, 1.3, 5.0}) {
      const glm::dmat4 v = glm::inverse(mb::cameraToWorld(s->curved, t));
      const glm::dmat4 m = mb::curved::matrixOfMotor(k, mb::curved::viewMotor(s->curved, t));
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(m[c][r], v[c][r], 1e-9) << name << " t " << t;
    }
  }
}

TEST(CurvedPipelines, MatrixAndMotorImagesAgreeAndFillTheView) {
  for (const char* name : {"s3_tiling", "h3_tiling"}) {
    auto s = mb::loadScene(name);
    ASSERT_TRUE(s) << s.error();
    const std::vector<std::string> pipes = mb::pipelineNames(s->curved.space);
    ASSERT_EQ(pipes.size(), 2u);
    for (float t : {0.0f, 2.7f, 5.3f}) {
      auto a = render(*s, pipes[0], t), b = render(*s, pipes[1], t);
      ASSERT_TRUE(a) << a.error();
      ASSERT_TRUE(b) << b.error();
      auto m = mb::compareImages(a->image, b->image);
      ASSERT_TRUE(m) << m.error();
      const double psnr = m->rmse == 0 ? 1e9 : m->psnr;
      EXPECT_GE(psnr, 50.0) << name << " t " << t;
      EXPECT_GT(covered(a->image), 0.5) << name << " t " << t;
      if (const char* dir = std::getenv("MB_CURVED_IMAGES")) {  // for looking at them
        mb::writeImage(std::string(dir) + "/" + name + "." + pipes[0] + ".t" + std::to_string(int(t * 10)) + ".png", a->image);
        mb::writeImage(std::string(dir) + "/" + name + "." + pipes[1] + ".t" + std::to_string(int(t * 10)) + ".png", b->image);
      }
      std::printf("%s t=%.1f: %s vs %s PSNR %.2f dB, covered %.3f\n", name, t, pipes[0].c_str(),
                  pipes[1].c_str(), psnr, covered(a->image));
    }
  }
}

TEST(CurvedPipelines, FloatsPerInstanceFromTheUploads) {
  for (const char* name : {"s3_tiling", "h3_tiling"}) {
    auto s = mb::loadScene(name);
    ASSERT_TRUE(s) << s.error();
    const std::vector<std::string> pipes = mb::pipelineNames(s->curved.space);
    auto a = render(*s, pipes[0], 0.0f, 32, 32), b = render(*s, pipes[1], 0.0f, 32, 32);
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->stats.floatsPerTransform, 16.0);
    EXPECT_EQ(b->stats.floatsPerTransform, 8.0);
    EXPECT_EQ(a->stats.extraVertexBytes, 64u * s->curved.instances.size());
    EXPECT_EQ(b->stats.extraVertexBytes, 32u * s->curved.instances.size());
    EXPECT_EQ(a->stats.floatsPerVertex, 8.0);
    EXPECT_EQ(b->stats.floatsPerVertex, 8.0);
  }
}

TEST(CurvedPipelines, EachKindRefusesTheOtherKindOfScene) {
  auto gltf = mb::loadScene("textured_box");
  auto s3 = mb::loadScene("s3_tiling");
  ASSERT_TRUE(gltf && s3);
  auto r1 = render(*gltf, "s3_motor", 0.0f, 16, 16);
  ASSERT_FALSE(r1);
  EXPECT_NE(r1.error().find("Euclidean glTF scene"), std::string::npos) << r1.error();
  auto r2 = render(*s3, "motor", 0.0f, 16, 16);
  ASSERT_FALSE(r2);
  EXPECT_NE(r2.error().find("use s3_matrix or s3_motor"), std::string::npos) << r2.error();
  auto r3 = render(*s3, "h3_matrix", 0.0f, 16, 16);
  ASSERT_FALSE(r3);
  EXPECT_NE(r3.error().find("spherical (S3)"), std::string::npos) << r3.error();
}

// Every glTF pipeline (pipelineNames(), the shared draw path's guard) refuses a scene of each
// curved space with the one message: the scene, the pipeline, the space and who draws it.
TEST(CurvedPipelines, EveryGltfPipelineRefusesCurvedScenesWithOneMessage) {
  auto ctx = mb::gl::sharedContext();
  ASSERT_TRUE(ctx) << ctx.error();
  const std::pair<const char*, const char*> spaces[] = {
      {"s3_tiling", "this is a spherical (S3) scene: use s3_matrix or s3_motor"},
      {"h3_tiling", "this is a hyperbolic (H3) scene: use h3_matrix or h3_motor"}};
  for (const auto& [sceneName, space] : spaces) {
    auto scene = mb::loadScene(sceneName);
    ASSERT_TRUE(scene) << scene.error();
    for (const std::string& name : mb::pipelineNames()) {
      auto p = mb::createPipeline(name);
      ASSERT_TRUE(p) << name;
      const mb::Status s = p->prepare(*scene);
      ASSERT_FALSE(s) << name << " drew " << sceneName;
      EXPECT_EQ(s.error(), std::string(scene->source) + ": pipeline " + name +
                               " draws Euclidean glTF scenes; " + space)
          << name;
    }
  }
}
