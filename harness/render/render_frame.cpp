#include "harness/render/render_frame.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>

#include "pipelines/gl/context.h"
#include "pipelines/gl/framebuffer.h"
#include "pipelines/scene/animation.h"
#include "pipelines/scene/camera_rule.h"
#include "pipelines/scene/loader.h"

namespace mb {
namespace {

// A pipeline that throws (a bug, e.g. std::map::at on a file no test had) must not take the
// command or the report's worker down with it: the exception becomes the frame's error, naming
// the scene and the pipeline, and the caller goes on (the report records it per pipeline).
template <class R, class F>
R guarded(const Scene& scene, const std::string& pipeline, F&& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    return R::fail(scene.source + " [" + pipeline + "]: internal error (exception): " + e.what());
  } catch (...) {
    return R::fail(scene.source + " [" + pipeline + "]: internal error (unknown exception)");
  }
}

Result<std::vector<RgbaImage>> renderFramesUnguarded(const Scene& scene, const std::string& pipeline,
                                                     const FrameSettings& settings, const std::vector<float>& times) {
  using R = Result<std::vector<RgbaImage>>;
  const std::string where = scene.source + " [" + pipeline + "]: ";
  std::unique_ptr<Pipeline> p = createPipeline(pipeline);
  if (!p) return R::fail(where + "unknown or unimplemented pipeline");
  auto ctx = gl::sharedContext();
  if (!ctx) return R::fail(where + ctx.error());
  auto fb = gl::Framebuffer::create(settings.width, settings.height);
  if (!fb) return R::fail(where + fb.error());
  p->configure(settings.options);
  Status prepared = p->prepare(scene);
  if (!prepared) return R::fail(where + prepared.error());
  std::vector<RgbaImage> images;
  for (float t : times) {
    AnimState anim = settings.anim;
    anim.time = t;
    p->update(anim);
    const View view = frameScene(scene, anim, float(settings.width) / float(settings.height), settings.camera);
    (*fb)->clear(kBackground[0], kBackground[1], kBackground[2], kBackground[3]);
    p->render(view);
    images.push_back({settings.width, settings.height, (*fb)->readRgba()});
    if (GLenum err = glGetError(); err != GL_NO_ERROR) return R::fail(where + "GL error after render: " + gl::errorName(err));
  }
  return images;
}

Result<Frame> renderFrameUnguarded(const Scene& scene, const std::string& pipeline, const FrameSettings& settings) {
  using R = Result<Frame>;
  const std::string where = scene.source + " [" + pipeline + "]: ";
  bool registered = false;
  for (const std::string& n : allPipelineNames()) registered = registered || n == pipeline;
  if (!registered) {
    std::string known;
    for (const std::string& n : allPipelineNames()) known += (known.empty() ? "" : ", ") + n;
    return R::fail("unknown pipeline '" + pipeline + "' (registered: " + known + ")");
  }
  std::unique_ptr<Pipeline> p = createPipeline(pipeline);
  if (!p)
    return R::fail("pipeline '" + pipeline +
                   "' is registered but not implemented yet (its factory is a placeholder "
                   "that returns nullptr)");
  auto ctx = gl::sharedContext();
  if (!ctx) return R::fail(where + ctx.error());
  auto fb = gl::Framebuffer::create(settings.width, settings.height);
  if (!fb) return R::fail(where + fb.error());

  Frame frame;
  frame.image.width = settings.width;
  frame.image.height = settings.height;
  frame.glRenderer = (*ctx)->info().renderer;
  frame.glVersion = (*ctx)->info().version;
  frame.glBackend = (*ctx)->info().backend;
  frame.gl = (*ctx)->info();
  p->configure(settings.options);
  Status prepared = p->prepare(scene);
  if (!prepared) return R::fail(where + prepared.error());
  p->update(settings.anim);
  frame.view = frameScene(scene, settings.anim, float(settings.width) / float(settings.height),
                          settings.camera);
  (*fb)->clear(kBackground[0], kBackground[1], kBackground[2], kBackground[3]);
  p->render(frame.view);
  frame.image.rgba = (*fb)->readRgba();
  GLenum err = glGetError();
  if (err != GL_NO_ERROR) return R::fail(where + "GL error after render: " + gl::errorName(err));
  frame.stats = p->stats();
  if (frame.stats.morphDraws == 0) frame.stats.morphNotDrawnNodes = morphedNodes(scene, settings.anim);
  return frame;
}

}  // namespace

int morphedNodes(const Scene& scene, const AnimState& anim) {
  const std::vector<std::vector<float>> weights = sampleMorphWeights(scene, anim);
  int nodes = 0;
  for (int n : nodesInDrawOrder(scene))
    if (size_t(n) < weights.size() && std::any_of(weights[size_t(n)].begin(), weights[size_t(n)].end(), [](float w) { return w != 0.0f; }))
      ++nodes;
  return nodes;
}

Result<std::vector<RgbaImage>> renderFrames(const Scene& scene, const std::string& pipeline,
                                            const FrameSettings& settings, const std::vector<float>& times) {
  return guarded<Result<std::vector<RgbaImage>>>(scene, pipeline,
                                                 [&] { return renderFramesUnguarded(scene, pipeline, settings, times); });
}

Result<Frame> renderFrame(const Scene& scene, const std::string& pipeline, const FrameSettings& settings) {
  return guarded<Result<Frame>>(scene, pipeline, [&] { return renderFrameUnguarded(scene, pipeline, settings); });
}

int64_t drawnPixels(const RgbaImage& image) {
  std::array<uint8_t, 3> background;
  for (int c = 0; c < 3; ++c) background[size_t(c)] = uint8_t(std::lround(kBackground[c] * 255.0f));
  return countPixelsOtherThan(image, background);
}

nlohmann::json toJson(const PipelineStats& s) {
  const bool timed = s.updatePhases.total() > 0;  // phases are timed only with the phase clock on
  auto phase = [timed](double ms) { return timed ? nlohmann::json(ms) : nlohmann::json(nullptr); };
  return {{"vertexBytes", s.vertexBytes}, {"skinVertexBytes", s.skinVertexBytes},
          {"extraVertexBytes", s.extraVertexBytes}, {"patchBytes", s.patchBytes}, {"patchPatternBytes", s.patchPatternBytes}, {"indexBytes", s.indexBytes},
          {"textureBytes", s.textureBytes}, {"uniformBytesPerFrame", s.uniformBytesPerFrame},
          {"skinBytesPerFrame", s.skinBytesPerFrame}, {"vertices", s.vertices},
          {"instanceBytes", s.instanceBytes}, {"instances", s.instances}, {"drawnVertices", s.drawnVertices},
          {"normalMappedVertexBytes", s.normalMappedVertexBytes},
          {"normalMappedVertices", s.normalMappedVertices},
          {"floatsPerVertex", s.floatsPerVertex}, {"floatsPerTransform", s.floatsPerTransform},
          {"floatsPerTransformWithScale", s.floatsPerTransformWithScale},
          {"floatsPerJoint", s.floatsPerJoint}, {"draws", s.draws},
          {"conversionMs", s.conversionMs}, {"updateMs", s.updateMs},
          {"updateSamplingMs", phase(s.updatePhases.samplingMs)}, {"updateBlendingMs", phase(s.updatePhases.blendingMs)},
          {"updateConversionMs", phase(s.updatePhases.conversionMs)},
          {"updateHierarchyMs", phase(s.updatePhases.hierarchyMs)}, {"updatePaletteMs", phase(s.updatePhases.paletteMs)},
          {"nonUniformScaleNodes", s.nonUniformScaleNodes},
          {"negativeScaleNodes", s.negativeScaleNodes},
          {"shearMatrixNodes", s.shearMatrixNodes}, {"zeroScalarFrames", s.zeroScalarFrames},
          {"biasedFrames", s.biasedFrames}, {"scaleFallbackInstances", s.scaleFallbackInstances},
          {"rotorSplitVertices", s.rotorSplitVertices}, {"rotorUnresolvedTriangles", s.rotorUnresolvedTriangles},
          {"linearFallbackDraws", s.linearFallbackDraws}, {"skinFallbackDraws", s.skinFallbackDraws},
          {"skinFallbackJoints", s.skinFallbackJoints}, {"fallbackVertices", s.fallbackVertices},
          {"skinFallbackVertices", s.skinFallbackVertices}, {"morphNotDrawnNodes", s.morphNotDrawnNodes}};
}

nlohmann::json toJson(const gl::ContextInfo& gl) {
  using nlohmann::json;
  return {{"backend", gl.backend}, {"renderer", gl.renderer}, {"version", gl.version}, {"vendor", gl.vendor},
          {"realGpu", gl.realGpu()}, {"kind", gl.realGpu() ? "gpu" : "cpu-rasterizer"},
          {"device", {{"index", gl.deviceIndex >= 0 ? json(gl.deviceIndex) : json(nullptr)},
                      {"software", gl.deviceSoftware},
                      {"drm", gl.drm.empty() ? json(nullptr) : json(gl.drm)}}}};
}

std::string describeGl(const gl::ContextInfo& gl) { return gl.renderer + " on " + gl.deviceText(); }

nlohmann::json toJson(const FrameSettings& s) {
  nlohmann::json j = {{"anim", s.anim.anim}, {"time", s.anim.time}, {"anim2", s.anim.anim2},
                      {"time2", s.anim.time2}, {"blend", s.anim.blend}, {"camera", s.camera},
                      {"width", s.width}, {"height", s.height}};
  if (s.instances > 1) j["instances"] = s.instances;  // --instances N (absent: 1, as the goldens)
  return j;
}

nlohmann::json toJson(const View& v) {
  return {{"eye", {v.eye.x, v.eye.y, v.eye.z}},
          {"orientation_wxyz", {v.orientation.w, v.orientation.x, v.orientation.y, v.orientation.z}},
          {"yfov", v.yfov}, {"aspect", v.aspect}, {"znear", v.znear}, {"zfar", v.zfar}};
}

nlohmann::json toJson(const ImageMetrics& m) {
  bool identical = m.rmse == 0.0;
  return {{"rmse", m.rmse}, {"psnr", identical ? nlohmann::json(nullptr) : nlohmann::json(m.psnr)},
          {"identical", identical}, {"meanError", m.meanError}, {"maxError", m.maxError},
          {"maxErrorPixel", {{"x", m.maxX}, {"y", m.maxY}, {"channel", m.maxChannel}}},
          {"fractionOver1", m.fractionOver1}, {"fractionOver2", m.fractionOver2},
          {"fractionOver4", m.fractionOver4}};
}

}  // namespace mb
