// renderFrame with PipelineOptions (e.g. the motor family's morph method): create,
// configure, prepare, update, render and read back as harness/render/render_frame.cpp does,
// framed automatically at `anim`; several states through one prepared pipeline.
#pragma once
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "harness/render/render_frame.h"
#include "pipelines/gl/context.h"
#include "pipelines/gl/framebuffer.h"
#include "pipelines/pipeline.h"

namespace mbtest {

// renderWithOptions for several animation states through one prepared pipeline: update, render
// and read back per state, as an animation plays (the shaders, uploads and framebuffer once per
// scene instead of once per frame). Each frame's stats count the morphed nodes left in their base
// shape as renderFrame does (PipelineStats::morphNotDrawnNodes).
inline std::vector<mb::Frame> renderStatesWithOptions(const mb::Scene& scene, const std::string& pipeline,
                                                      const mb::PipelineOptions& options,
                                                      const std::vector<mb::AnimState>& states, int size) {
  std::vector<mb::Frame> frames(states.size());
  auto ctx = mb::gl::sharedContext();
  auto fb = mb::gl::Framebuffer::create(size, size);
  std::unique_ptr<mb::Pipeline> p = mb::createPipeline(pipeline);
  if (!ctx || !fb || !p) {
    ADD_FAILURE() << "no context, framebuffer or pipeline " << pipeline;
    return frames;
  }
  p->configure(options);
  mb::Status prepared = p->prepare(scene);
  if (!prepared) {
    ADD_FAILURE() << pipeline << ": " << prepared.error();
    return frames;
  }
  for (size_t i = 0; i < states.size(); ++i) {
    mb::Frame& f = frames[i];
    p->update(states[i]);
    (*fb)->clear(mb::kBackground[0], mb::kBackground[1], mb::kBackground[2], mb::kBackground[3]);
    p->render(mb::frameScene(scene, states[i], 1.0f));
    f.image = {size, size, (*fb)->readRgba()};
    const GLenum err = glGetError();
    EXPECT_EQ(err, GLenum(GL_NO_ERROR)) << pipeline << ": GL error after render: " << mb::gl::errorName(err);
    f.stats = p->stats();
    if (f.stats.morphDraws == 0) f.stats.morphNotDrawnNodes = mb::morphedNodes(scene, states[i]);
  }
  return frames;
}

inline mb::Frame renderWithOptions(const mb::Scene& scene, const std::string& pipeline,
                                   const mb::PipelineOptions& options, const mb::AnimState& anim, int size) {
  return renderStatesWithOptions(scene, pipeline, options, {anim}, size)[0];
}

}  // namespace mbtest
