// renderFrame with PipelineOptions (e.g. the motor family's morph method, issue 37): create,
// configure, prepare, update, render and read back as harness/render/render_frame.cpp does,
// framed automatically at `anim`.
#pragma once
#include <gtest/gtest.h>

#include <string>

#include "harness/render/render_frame.h"
#include "pipelines/gl/context.h"
#include "pipelines/gl/framebuffer.h"
#include "pipelines/pipeline.h"

namespace mbtest {

inline mb::Frame renderWithOptions(const mb::Scene& scene, const std::string& pipeline,
                                   const mb::PipelineOptions& options, const mb::AnimState& anim, int size) {
  mb::Frame f;
  auto ctx = mb::gl::sharedContext();
  auto fb = mb::gl::Framebuffer::create(size, size);
  std::unique_ptr<mb::Pipeline> p = mb::createPipeline(pipeline);
  if (!ctx || !fb || !p) {
    ADD_FAILURE() << "no context, framebuffer or pipeline " << pipeline;
    return f;
  }
  p->configure(options);
  mb::Status prepared = p->prepare(scene);
  EXPECT_TRUE(prepared) << prepared.error();
  p->update(anim);
  (*fb)->clear(mb::kBackground[0], mb::kBackground[1], mb::kBackground[2], mb::kBackground[3]);
  p->render(mb::frameScene(scene, anim, 1.0f));
  f.image = {size, size, (*fb)->readRgba()};
  f.stats = p->stats();
  return f;
}

}  // namespace mbtest
