#include "harness/render/render_frame.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "pipelines/gl/context.h"
#include "pipelines/gl/framebuffer.h"
#include "pipelines/scene/camera_rule.h"
#include "pipelines/scene/loader.h"

namespace mb {
namespace {

// Index of `value` among `count` items named by `nameOf`, accepting a number or a name.
template <class NameOf>
Result<int> resolveIndex(const std::string& option, const std::string& value, size_t count,
                         NameOf nameOf, const std::string& source) {
  char* end = nullptr;
  long i = std::strtol(value.c_str(), &end, 10);
  if (!value.empty() && *end == '\0') {
    if (i >= 0 && size_t(i) < count) return int(i);
    if (count == 0) return Result<int>::fail("--" + option + " " + value + ": " + source + " has none");
    return Result<int>::fail("--" + option + " " + value + ": " + source + " has " +
                             std::to_string(count) + " (indices 0.." +
                             std::to_string(long(count) - 1) + ")");
  }
  for (size_t k = 0; k < count; ++k)
    if (nameOf(k) == value) return int(k);
  return Result<int>::fail("--" + option + " " + value + ": no such name in " + source);
}

Result<std::pair<int, int>> parseSize(const std::string& s) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  int n = std::sscanf(s.c_str(), "%d%c%d%c", &w, &x, &h, &extra);
  if (n == 1) h = w;
  else if (n != 3 || (x != 'x' && x != 'X'))
    return Result<std::pair<int, int>>::fail("--size " + s + ": expected WxH, e.g. 512x512");
  if (w < 1 || h < 1 || w > 16384 || h > 16384)
    return Result<std::pair<int, int>>::fail("--size " + s + ": out of range 1..16384");
  return std::make_pair(w, h);
}

}  // namespace

const std::vector<std::string>& frameOptionNames() {
  static const std::vector<std::string> names = {"anim", "time", "anim2", "time2",
                                                 "blend", "camera", "size"};
  return names;
}

Result<SceneCommand> parseSceneCommand(const Args& args, const std::set<std::string>& options,
                                       const std::string& outputWhat) {
  using R = Result<SceneCommand>;
  std::set<std::string> known = options;
  known.insert({"o", "output"});
  known.insert(frameOptionNames().begin(), frameOptionNames().end());
  if (!args.error().empty()) return R::fail(args.error());
  if (auto unknown = args.unknown(known); !unknown.empty()) return R::fail("unknown option " + unknown[0]);
  if (args.positional().size() != 1) return R::fail("expected one SCENE (a file or a built-in scene name)");
  SceneCommand c;
  c.output = args.get("o", args.get("output", ""));
  if (c.output.empty()) return R::fail("missing -o " + outputWhat);
  auto scene = loadScene(args.positional()[0]);
  if (!scene) return R::fail(scene.error());
  c.scene = scene.take();
  auto settings = frameSettingsFromArgs(args, c.scene);
  if (!settings) return R::fail(settings.error());
  c.settings = *settings;
  return c;
}

Result<double> numberOption(const Args& args, const std::string& key, double fallback) {
  auto v = args.get(key);
  if (!v) return fallback;
  char* end = nullptr;
  double d = std::strtod(v->c_str(), &end);
  if (v->empty() || *end != '\0' || std::isnan(d))
    return Result<double>::fail("--" + key + " " + *v + ": not a number");
  return d;
}

int commandError(const char* command, const std::string& message) {
  std::fprintf(stderr, "motorbench %s: error: %s\n", command, message.c_str());
  return 2;
}

Result<FrameSettings> frameSettingsFromArgs(const Args& args, const Scene& scene) {
  using R = Result<FrameSettings>;
  FrameSettings s;
  auto animName = [&](size_t k) { return scene.animations[k].name; };
  const std::string& src = scene.source;
  if (auto a = args.get("anim")) {
    auto i = resolveIndex("anim", *a, scene.animations.size(), animName, src + " (animations)");
    if (!i) return R::fail(i.error());
    s.anim.anim = *i;
  }
  if (auto a = args.get("anim2")) {
    auto i = resolveIndex("anim2", *a, scene.animations.size(), animName, src + " (animations)");
    if (!i) return R::fail(i.error());
    s.anim.anim2 = *i;
  }
  if (auto c = args.get("camera")) {
    auto camName = [&](size_t k) { return scene.cameras[k].name; };
    auto i = resolveIndex("camera", *c, scene.cameras.size(), camName, src + " (cameras)");
    if (!i) return R::fail(i.error());
    s.camera = *i;
  }
  auto time = numberOption(args, "time", 0.0);
  if (!time) return R::fail(time.error());
  auto time2 = numberOption(args, "time2", *time);
  if (!time2) return R::fail(time2.error());
  auto blend = numberOption(args, "blend", s.anim.anim2 >= 0 ? 0.5 : 0.0);
  if (!blend) return R::fail(blend.error());
  s.anim.time = float(*time);
  s.anim.time2 = float(*time2);
  s.anim.blend = float(*blend);
  if (s.anim.blend < 0.0f || s.anim.blend > 1.0f)
    return R::fail("--blend " + args.get("blend", "") + ": expected a weight in [0, 1]");
  if (args.has("blend") && s.anim.anim2 < 0)
    return R::fail("--blend needs --anim2 (the animation to blend towards)");
  if (auto size = args.get("size")) {
    auto wh = parseSize(*size);
    if (!wh) return R::fail(wh.error());
    s.width = wh->first;
    s.height = wh->second;
  }
  return s;
}

Result<std::vector<RgbaImage>> renderFrames(const Scene& scene, const std::string& pipeline,
                                            const FrameSettings& settings, const std::vector<float>& times) {
  using R = Result<std::vector<RgbaImage>>;
  const std::string where = scene.source + " [" + pipeline + "]: ";
  std::unique_ptr<Pipeline> p = createPipeline(pipeline);
  if (!p) return R::fail(where + "unknown or unimplemented pipeline");
  auto ctx = gl::sharedContext();
  if (!ctx) return R::fail(where + ctx.error());
  auto fb = gl::Framebuffer::create(settings.width, settings.height);
  if (!fb) return R::fail(where + fb.error());
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

Result<Frame> renderFrame(const Scene& scene, const std::string& pipeline,
                          const FrameSettings& settings) {
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
  return frame;
}

nlohmann::json toJson(const PipelineStats& s) {
  return {{"vertexBytes", s.vertexBytes}, {"skinVertexBytes", s.skinVertexBytes},
          {"extraVertexBytes", s.extraVertexBytes}, {"patchBytes", s.patchBytes}, {"indexBytes", s.indexBytes},
          {"textureBytes", s.textureBytes}, {"uniformBytesPerFrame", s.uniformBytesPerFrame},
          {"skinBytesPerFrame", s.skinBytesPerFrame}, {"vertices", s.vertices},
          {"floatsPerVertex", s.floatsPerVertex}, {"floatsPerTransform", s.floatsPerTransform},
          {"floatsPerJoint", s.floatsPerJoint}, {"draws", s.draws},
          {"conversionMs", s.conversionMs}, {"updateMs", s.updateMs},
          {"nonUniformScaleNodes", s.nonUniformScaleNodes},
          {"negativeScaleNodes", s.negativeScaleNodes},
          {"shearMatrixNodes", s.shearMatrixNodes}, {"zeroScalarFrames", s.zeroScalarFrames}};
}

nlohmann::json toJson(const FrameSettings& s) {
  return {{"anim", s.anim.anim}, {"time", s.anim.time}, {"anim2", s.anim.anim2},
          {"time2", s.anim.time2}, {"blend", s.anim.blend}, {"camera", s.camera},
          {"width", s.width}, {"height", s.height}};
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

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

}  // namespace mb
