#include "harness/render/fixed_views.h"

#include <exception>
#include <memory>

#include "harness/render/render_frame.h"
#include "pipelines/gl/context.h"
#include "pipelines/gl/framebuffer.h"
#include "pipelines/pipeline.h"

namespace mb {

std::vector<View> framings(const Scene& scene, const std::vector<FrameSettings>& settings) {
  std::vector<View> views;
  for (const FrameSettings& f : settings) views.push_back(frameScene(scene, f.anim, float(f.width) / float(f.height), f.camera));
  return views;
}

Result<std::vector<RgbaImage>> drawFromViews(const Scene& scene, const std::string& pipeline,
                                             const std::vector<FrameSettings>& settings, const std::vector<View>& views) {
  using R = Result<std::vector<RgbaImage>>;
  const std::string where = scene.source + " [" + pipeline + "]: ";
  try {
    auto ctx = gl::sharedContext();
    if (!ctx) return R::fail(where + ctx.error());
    std::unique_ptr<Pipeline> p = createPipeline(pipeline);
    if (!p) return R::fail(where + "unknown or unimplemented pipeline");
    if (!settings.empty()) p->configure(settings.front().options);
    if (Status ok = p->prepare(scene); !ok) return R::fail(where + ok.error());
    std::vector<RgbaImage> images;
    for (size_t k = 0; k < settings.size() && k < views.size(); ++k) {
      const FrameSettings& f = settings[k];
      auto fb = gl::Framebuffer::create(f.width, f.height);
      if (!fb) return R::fail(where + fb.error());
      p->update(f.anim);
      (*fb)->clear(kBackground[0], kBackground[1], kBackground[2], kBackground[3]);
      p->render(views[k]);
      images.push_back(RgbaImage{f.width, f.height, (*fb)->readRgba()});
    }
    return images;
  } catch (const std::exception& e) {
    return R::fail(where + "internal error (exception): " + e.what());
  }
}

}  // namespace mb
