// An offscreen render target: RGBA8 colour and 24-bit depth renderbuffers, one sample,
// fixed size. Every pipeline draws into one of these; readRgba() returns the image top-down.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "pipelines/gl/gl_api.h"
#include "pipelines/result.h"

namespace mb::gl {

class Framebuffer {
public:
  // Needs a current context. Fails (naming the size and the GL status) when incomplete.
  static Result<std::unique_ptr<Framebuffer>> create(int width, int height);
  ~Framebuffer();
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  // Binds it as the draw and read framebuffer and sets the viewport to its size.
  void bind() const;
  // Binds, then clears colour to `rgba` (linear values written as-is) and depth to 1.
  void clear(float r, float g, float b, float a) const;
  // glFinish, then reads the colour buffer as RGBA8, rows top-down (row 0 = top of image).
  std::vector<uint8_t> readRgba() const;

private:
  Framebuffer() = default;
  int width_ = 0, height_ = 0;
  GLuint fbo_ = 0, buffers_[2] = {};  // colour, depth
};

}  // namespace mb::gl
