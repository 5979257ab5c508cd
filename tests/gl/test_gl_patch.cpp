// Bezier patches on the GPU: the real patch vertex shaders (matrix_patch.vs, motor_patch.vs)
// run over the teapot with transform feedback, their positions compared with an independent
// CPU evaluation (de Casteljau in double) within 1e-5 relative, their normals finite on every
// vertex including the degenerate lid-apex and bottom-centre edges, shared patch edges
// checked for cracks, and rendered frames of both pipelines checked for black (NaN) pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>

#include "harness/render/render_frame.h"
#include "tests/support/patch_test_support.h"
#include "pipelines/gl/context.h"
#include "pipelines/gl/framebuffer.h"
#include "pipelines/gl/patch_geometry.h"
#include "pipelines/gl/shader_source.h"
#include "pipelines/scene/loader.h"

namespace {

constexpr int kLevel = 8;

struct Captured {
  std::vector<float> position, normal;  // 3 floats per captured vertex
};

// Compiles `vs` with transform feedback of v_worldPosition and v_worldNormal, draws every patch
// of `scene` with the identity transform, and returns what the vertex shader wrote: per
// instance (patch), per pattern triangle, 3 vertices.
Captured capture(const mb::Scene& scene, const std::string& vs, bool motor) {
  Captured out;
  auto src = mb::gl::expandShaderFile(vs);
  EXPECT_TRUE(src) << src.error();
  if (!src) return out;
  GLuint shader = glCreateShader(GL_VERTEX_SHADER);
  const char* text = src->text.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  EXPECT_TRUE(ok) << vs << " did not compile";
  GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  const char* varyings[] = {"v_worldPosition", "v_worldNormal"};
  glTransformFeedbackVaryings(program, 2, varyings, GL_SEPARATE_ATTRIBS);
  glLinkProgram(program);
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  EXPECT_TRUE(ok) << vs << " did not link";
  glUseProgram(program);
  const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  if (motor) {
    const float unit[8] = {1, 0, 0, 0, 0, 0, 0, 0};
    glUniform4fv(glGetUniformLocation(program, "u_World"), 2, unit);
    glUniform4fv(glGetUniformLocation(program, "u_Camera"), 2, unit);
    glUniform1f(glGetUniformLocation(program, "u_Scale"), 1.0f);
  } else {
    for (const char* u : {"u_ModelMatrix", "u_NormalMatrix", "u_ViewProjectionMatrix"})
      glUniformMatrix4fv(glGetUniformLocation(program, u), 1, GL_FALSE, identity);
  }
  mb::PipelineStats stats;
  mb::gl::PatchGeometry patches;
  mb::Status up = patches.upload(scene, stats);
  EXPECT_TRUE(up) << up.error();
  const size_t vertices = scene.meshes[0].primitives[0].patchPoints.size() / 16 * 6 * kLevel * kLevel;
  GLuint buffers[2];
  glGenBuffers(2, buffers);
  for (int i = 0; i < 2; ++i) {
    glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, buffers[i]);
    glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, GLsizeiptr(vertices * 3 * sizeof(float)), nullptr, GL_STATIC_READ);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, GLuint(i), buffers[i]);
  }
  auto fb = mb::gl::Framebuffer::create(4, 4);  // drawing needs a complete framebuffer bound
  EXPECT_TRUE(fb) << fb.error();
  if (fb) (*fb)->bind();
  glEnable(GL_RASTERIZER_DISCARD);
  glBeginTransformFeedback(GL_TRIANGLES);
  patches.draw({0, 0, 0});
  glEndTransformFeedback();
  glDisable(GL_RASTERIZER_DISCARD);
  glFinish();
  out.position.resize(vertices * 3);
  out.normal.resize(vertices * 3);
  for (int i = 0; i < 2; ++i) {
    glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, buffers[i]);
    glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, GLsizeiptr(vertices * 3 * sizeof(float)),
                       (i ? out.normal : out.position).data());
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glDeleteBuffers(2, buffers);
  patches.release();
  glDeleteProgram(program);
  glDeleteShader(shader);
  return out;
}

class GpuPatches : public ::testing::TestWithParam<std::string> {
protected:
  void SetUp() override {
    auto ctx = mb::gl::sharedContext();
    ASSERT_TRUE(ctx) << ctx.error();
    points_ = mbtest::teapotPoints();
    ASSERT_EQ(points_.size(), 512u);
    scene_ = mb::sceneFromPatches(points_, "teapot.bpt");
    scene_.patchLevel = kLevel;
    pattern_ = mb::gl::refinementPattern(kLevel);
    got_ = capture(scene_, GetParam(), GetParam().rfind("motor", 0) == 0);
    ASSERT_EQ(got_.position.size(), 32u * pattern_.indices.size() * 3);
  }
  // uv of captured vertex k.
  glm::vec2 uvOf(size_t k) const { return pattern_.uv[pattern_.indices[k % pattern_.indices.size()]]; }
  size_t patchOf(size_t k) const { return k / pattern_.indices.size(); }
  glm::vec3 at(const std::vector<float>& v, size_t k) const { return {v[3 * k], v[3 * k + 1], v[3 * k + 2]}; }

  std::vector<glm::vec3> points_;
  mb::Scene scene_;
  mb::gl::RefinementPattern pattern_;
  Captured got_;
};

TEST_P(GpuPatches, PositionsMatchCpuEvaluation) {
  double worst = 0.0;
  for (size_t k = 0; k < got_.position.size() / 3; ++k) {
    glm::vec2 uv = uvOf(k);
    glm::dvec3 ref = mbtest::referencePoint(points_, patchOf(k), uv.x, uv.y);
    glm::dvec3 gpu(at(got_.position, k));
    worst = std::max(worst, glm::length(gpu - ref) / std::max(1.0, glm::length(ref)));
  }
  std::printf("%s: worst relative position error vs de Casteljau (double): %.3g\n", GetParam().c_str(), worst);
  EXPECT_LE(worst, 1e-5);
}

TEST_P(GpuPatches, NormalsAreFiniteEverywhereIncludingDegenerateEdges) {
  int degenerate = 0;
  for (size_t k = 0; k < got_.normal.size() / 3; ++k) {
    glm::vec3 n = at(got_.normal, k);
    ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z)) << "patch " << patchOf(k) + 1;
    ASSERT_GT(glm::length(n), 0.0f) << "patch " << patchOf(k) + 1;
    size_t p = patchOf(k);
    if (uvOf(k).y == 0.0f && ((p >= 20 && p <= 23) || p >= 28)) {
      // The collapsed first row: the lid apex and the bottom centre, on the z axis.
      EXPECT_GT(std::fabs(glm::normalize(n).z), 0.999f) << "patch " << p + 1 << " u=" << uvOf(k).x;
      ++degenerate;
    }
  }
  // 8 patches x (kLevel + 1) edge vertices, each captured once per triangle using it.
  EXPECT_GE(degenerate, 8 * (kLevel + 1));
}

TEST_P(GpuPatches, SharedEdgesHaveNoCracks) {
  // Every captured vertex position by (patch, uv): vertices on shared edges must coincide.
  std::map<std::pair<size_t, std::pair<float, float>>, glm::vec3> byUv;
  for (size_t k = 0; k < got_.position.size() / 3; ++k) byUv[{patchOf(k), {uvOf(k).x, uvOf(k).y}}] = at(got_.position, k);
  // Group GPU edge positions by the CPU's exact (bit-identical across patches) edge position.
  std::map<std::tuple<float, float, float>, glm::vec3> first;
  float worst = 0.0f;
  int shared = 0;
  for (const auto& [key, gpu] : byUv) {
    glm::vec2 uv(key.second.first, key.second.second);
    if (uv.x != 0 && uv.x != 1 && uv.y != 0 && uv.y != 1) continue;
    auto cpu = mbtest::evaluate<float>(points_, key.first, uv.x, uv.y)[0];
    auto [it, inserted] = first.insert({{cpu.x, cpu.y, cpu.z}, gpu});
    if (inserted) continue;
    ASSERT_EQ(it->second, it->second) << "NaN";
    ++shared;
    worst = std::max(worst, glm::length(gpu - it->second));
  }
  std::printf("%s: %d edge vertices shared with another patch, largest GPU gap %.3g\n", GetParam().c_str(), shared, worst);
  EXPECT_GT(shared, 100);
  EXPECT_EQ(worst, 0.0f) << "shared edge vertices must be bit-identical (a gap is a crack)";
}

INSTANTIATE_TEST_SUITE_P(Shaders, GpuPatches, ::testing::Values("matrix_patch.vs", "motor_patch.vs"),
                         [](const auto& info) { return info.param.substr(0, info.param.find('_')); });

// Rendered frames: no black pixel anywhere (the background is grey; a NaN normal shades
// black), at rest and with the lid lifted, in both pipelines.
TEST(GpuPatchFrames, NoBlackPixelsInEitherPipeline) {
  auto scene = mb::loadScene("teapot");
  ASSERT_TRUE(scene) << scene.error();
  for (const char* pipeline : {"matrix", "motor"})
    for (float t : {0.0f, 4.0f / 3.0f}) {
      mb::FrameSettings s;
      s.anim.anim = 0;
      s.anim.time = t;
      s.width = 256, s.height = 192;
      auto f = mb::renderFrame(*scene, pipeline, s);
      ASSERT_TRUE(f) << f.error();
      int black = 0, teapot = 0;
      for (size_t i = 0; i < f->image.rgba.size(); i += 4) {
        const uint8_t* p = &f->image.rgba[i];
        black += p[0] == 0 && p[1] == 0 && p[2] == 0;
        teapot += p[0] > p[2] + 20;  // the orange glaze, not the grey background
      }
      EXPECT_EQ(black, 0) << pipeline << " t=" << t;
      EXPECT_GT(teapot, 256 * 192 / 20) << pipeline << " t=" << t << ": the teapot covers the frame";
    }
}

}  // namespace
