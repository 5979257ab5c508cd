// The headless GL layer: context creation (EGL surfaceless, OSMesa fallback), framebuffer
// clear and top-down readback.
#include <gtest/gtest.h>

#include <cstdlib>

#include "pipelines/gl/context.h"
#include "pipelines/gl/framebuffer.h"
#include "pipelines/gl/gl_api.h"

namespace {

void expectClearColor(int w, int h) {
  auto fb = mb::gl::Framebuffer::create(w, h);
  ASSERT_TRUE(fb) << fb.error();
  (*fb)->clear(1.0f, 0.5f, 0.0f, 1.0f);
  std::vector<uint8_t> px = (*fb)->readRgba();
  ASSERT_EQ(px.size(), size_t(w) * h * 4);
  for (size_t i = 0; i < px.size(); i += 4) {
    ASSERT_EQ(px[i], 255);
    ASSERT_NEAR(px[i + 1], 128, 1);
    ASSERT_EQ(px[i + 2], 0);
    ASSERT_EQ(px[i + 3], 255);
  }
}

}  // namespace

TEST(GlContext, SharedContextIsGl45Core) {
  auto ctx = mb::gl::sharedContext();
  ASSERT_TRUE(ctx) << ctx.error();
  const mb::gl::ContextInfo& info = (*ctx)->info();
  EXPECT_FALSE(info.renderer.empty());
  EXPECT_FALSE(info.version.empty());
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_GE(major * 10 + minor, 45) << info.version;
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  std::printf("backend %s, GL_RENDERER %s, GL_VERSION %s\n", info.backend.c_str(),
              info.renderer.c_str(), info.version.c_str());
}

TEST(GlContext, FramebufferClearAndReadback) {
  ASSERT_TRUE(mb::gl::sharedContext());
  expectClearColor(7, 5);  // odd sizes: no row padding in readback
}

TEST(GlContext, FramebufferRejectsBadSize) {
  ASSERT_TRUE(mb::gl::sharedContext());
  auto fb = mb::gl::Framebuffer::create(0, 16);
  ASSERT_FALSE(fb);
  EXPECT_NE(fb.error().find("0x16"), std::string::npos) << fb.error();
}

TEST(GlContext, OsmesaFallbackWorksAndSharedContextSurvivesIt) {
  setenv("MB_GL_BACKEND", "osmesa", 1);
  auto os = mb::gl::Context::create();
  unsetenv("MB_GL_BACKEND");
  if (!os) GTEST_SKIP() << "OSMesa not available: " << os.error();
  EXPECT_EQ((*os)->info().backend, "osmesa");
  expectClearColor(4, 3);
  os->reset();
  // Back to the shared (EGL) context: the GL pointers must be reloaded for it.
  auto ctx = mb::gl::sharedContext();
  ASSERT_TRUE(ctx) << ctx.error();
  expectClearColor(3, 3);
}

TEST(GlContext, UnknownBackendIsAnError) {
  setenv("MB_GL_BACKEND", "vulkan", 1);
  auto bad = mb::gl::Context::create();
  unsetenv("MB_GL_BACKEND");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("MB_GL_BACKEND"), std::string::npos);
  ASSERT_TRUE(mb::gl::sharedContext());
}
