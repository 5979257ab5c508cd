#include "pipelines/gl/framebuffer.h"

#include <cstdio>
#include <cstring>
#include <string>

namespace mb::gl {

Result<std::unique_ptr<Framebuffer>> Framebuffer::create(int width, int height) {
  using R = Result<std::unique_ptr<Framebuffer>>;
  std::string size = std::to_string(width) + "x" + std::to_string(height);
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
  if (width <= 0 || height <= 0 || width > maxSize || height > maxSize)
    return R::fail("framebuffer " + size + ": size out of range (max " +
                   std::to_string(maxSize) + ")");
  std::unique_ptr<Framebuffer> fb(new Framebuffer());
  fb->width_ = width;
  fb->height_ = height;
  glGenTextures(1, &fb->color_);
  glBindTexture(GL_TEXTURE_2D, fb->color_);
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, width, height);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);
  glGenRenderbuffers(1, &fb->depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, fb->depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glGenFramebuffers(1, &fb->fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fb->fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, fb->color_, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, fb->depth_);
  GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04x", status);
    return R::fail("framebuffer " + size + ": incomplete (status " + hex + ")");
  }
  return fb;
}

Framebuffer::~Framebuffer() {
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  if (depth_) glDeleteRenderbuffers(1, &depth_);
  if (color_) glDeleteTextures(1, &color_);
}

// The framebuffer's draw and read buffer (its colour attachment 0), the colour mask and the
// clear depth (1) stay at GL's defaults: nothing sets them.
void Framebuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, width_, height_);
}

void Framebuffer::clear(float r, float g, float b, float a) const {
  bind();
  glDepthMask(GL_TRUE);
  glClearColor(r, g, b, a);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

std::vector<uint8_t> Framebuffer::readRgba() const {
  bind();
  glFinish();
  const size_t row = size_t(width_) * 4;
  std::vector<uint8_t> bottomUp(row * size_t(height_));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
  // GL rows start at the bottom; images are stored top row first.
  std::vector<uint8_t> topDown(bottomUp.size());
  for (int y = 0; y < height_; ++y)
    std::memcpy(&topDown[size_t(y) * row], &bottomUp[size_t(height_ - 1 - y) * row], row);
  return topDown;
}

}  // namespace mb::gl
