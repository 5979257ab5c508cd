#include "harness/report/report_animation.h"

#include <algorithm>
#include <filesystem>

#include "harness/render/render_frame.h"

namespace mb::report {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// a | b | c, each w x h, into one 3w x h image.
RgbaImage sideBySide(const RgbaImage& a, const RgbaImage& b, const RgbaImage& c) {
  RgbaImage out{a.width * 3, a.height, {}};
  out.rgba.resize(size_t(out.width) * size_t(out.height) * 4);
  const size_t row = size_t(a.width) * 4;
  for (int y = 0; y < a.height; ++y) {
    uint8_t* dst = out.rgba.data() + size_t(y) * row * 3;
    for (const RgbaImage* img : {&a, &b, &c}) {
      std::copy_n(img->rgba.data() + size_t(y) * row, row, dst);
      dst += row;
    }
  }
  return out;
}

}  // namespace

json animatedComparisons(const Scene& scene, const SceneJob& job, const std::string& rel, int anim) {
  if (anim < 0 || size_t(anim) >= scene.animations.size() || !(scene.animations[size_t(anim)].duration > 0.0f) ||
      job.pipelines.size() < 2)
    return nullptr;
  const float duration = scene.animations[size_t(anim)].duration;
  std::vector<float> times;  // one loop: the end equals the start, so it is left out
  for (int k = 0; k < kAnimationFrames; ++k) times.push_back(duration * float(k) / float(kAnimationFrames));
  FrameSettings settings;
  settings.width = job.width, settings.height = job.height;
  settings.anim.anim = anim;
  const std::string& base = job.pipelines.front();
  const std::string& name = scene.animations[size_t(anim)].name;
  const std::string what = (name.empty() ? "animation " + std::to_string(anim) : name) + ", " +
                           std::to_string(kAnimationFrames) + " frames";
  progress(job, "animating " + base + " (" + what + ")");
  auto baseFrames = renderFrames(scene, base, settings, times);
  json out = json::object();
  for (size_t i = 1; i < job.pipelines.size(); ++i) {
    const std::string& p = job.pipelines[i];
    if (!baseFrames) {
      out[p] = {{"error", baseFrames.error()}};
      continue;
    }
    progress(job, "animating " + p + " (" + what + ")");
    auto frames = renderFrames(scene, p, settings, times);
    if (!frames) {
      out[p] = {{"error", frames.error()}};
      continue;
    }
    std::vector<RgbaImage> strip;
    double worst = 0;
    for (size_t k = 0; k < times.size(); ++k) {
      const RgbaImage& a = (*baseFrames)[k];
      const RgbaImage& b = (*frames)[k];
      if (auto m = compareImages(a, b)) worst = std::max(worst, m->fractionOver2);
      strip.push_back(sideBySide(a, b, diffHeatmap(a, b)));
    }
    const std::string file = rel + (anim == 0 ? "animation_" : "animation" + std::to_string(anim) + "_") + p + ".gif";
    Status written = writeAnimation((fs::path(job.outDir) / file).string(), strip, kAnimationFps);
    if (!written) {
      out[p] = {{"error", written.error()}};
      continue;
    }
    out[p] = {{"file", file}, {"frames", kAnimationFrames}, {"fps", kAnimationFps}, {"duration", duration},
              {"animation", anim}, {"name", scene.animations[size_t(anim)].name},
              {"baseline", base}, {"maxPixelsOver2", worst}};
  }
  return out;
}

}  // namespace mb::report
