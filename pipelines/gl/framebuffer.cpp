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
  glGenFramebuffers(1, &fb->fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fb->fbo_);
  glGenRenderbuffers(2, fb->buffers_);
  const GLenum formats[2] = {GL_RGBA8, GL_DEPTH_COMPONENT24};
  const GLenum attachments[2] = {GL_COLOR_ATTACHMENT0, GL_DEPTH_ATTACHMENT};
  for (int i = 0; i < 2; ++i) {
    glBindRenderbuffer(GL_RENDERBUFFER, fb->buffers_[i]);
    glRenderbufferStorage(GL_RENDERBUFFER, formats[i], width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, attachments[i], GL_RENDERBUFFER, fb->buffers_[i]);
  }
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04x", status);
    return R::fail("framebuffer " + size + ": incomplete (status " + hex + ")");
  }
  return fb;
}

Framebuffer::~Framebuffer() {  // create() generated both
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(2, buffers_);
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
