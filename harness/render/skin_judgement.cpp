#include "harness/render/skin_judgement.h"

#include <cstdio>

#include "harness/render/fixed_views.h"
#include "harness/render/render_frame.h"
#include "harness/render/skin_reference.h"
#include "pipelines/pipeline.h"
#include "pipelines/scene/camera_rule.h"
#include "pipelines/skin_method.h"

namespace mb {
namespace {

using json = nlohmann::json;

Result<SkinFigures> figuresAgainst(const std::string& pipeline, const RgbaImage& image, const std::string& reference,
                                   const RgbaImage& referenceImage) {
  auto m = compareImages(referenceImage, image);
  if (!m) return Result<SkinFigures>::fail(pipeline + " against " + reference + ": " + m.error());
  return SkinFigures{*m, checkDrawn(pipeline, image, reference, referenceImage, true, false)};
}

std::string percentText(double percent) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f %%", percent);
  return b;
}

// "PSNR 36.64 dB; max error 116/255 (0.4549 of full scale); pixels off by more than 1/255: ...;
// drawn pixels motor 41687, matrix 40689 (2.39 % apart)".
std::string figuresText(const SkinFigures& f, const std::string& pipeline, const std::string& reference) {
  const ImageMetrics& m = f.metrics;
  char b[320];
  std::string text = "identical";
  if (m.rmse != 0.0) {
    std::snprintf(b, sizeof b, "PSNR %.2f dB; max error %s; pixels off by more than 1/255: %.3f %%, 2/255: %.3f %%, 4/255: %.3f %%",
                  m.psnr, differenceText(m.maxError).c_str(), 100 * m.fractionOver1, 100 * m.fractionOver2,
                  100 * m.fractionOver4);
    text = b;
  }
  return text + "; drawn pixels " + pipeline + " " + std::to_string(f.drawn.drawnA) + ", " + reference + " " +
         std::to_string(f.drawn.drawnB) + " (" + percentText(f.drawn.apartPercent) + " apart)";
}

json figuresJson(const SkinFigures& f) {
  const ImageMetrics& m = f.metrics;
  return {{"identical", m.rmse == 0.0}, {"psnr", m.rmse == 0.0 ? json(nullptr) : json(m.psnr)},
          {"maxError", m.maxError}, {"fractionOver1", m.fractionOver1}, {"fractionOver2", m.fractionOver2},
          {"fractionOver4", m.fractionOver4}, {"drawnPixels", f.drawn.drawnA},
          {"referenceDrawnPixels", f.drawn.drawnB}, {"drawnApartPercent", f.drawn.apartPercent}};
}

}  // namespace

bool drawsSkinned(const Scene& scene) {
  for (int n : nodesInDrawOrder(scene)) {
    const Node& node = scene.nodes[size_t(n)];
    if (node.skin < 0 || node.mesh < 0 || size_t(node.mesh) >= scene.meshes.size()) continue;
    for (const Primitive& p : scene.meshes[size_t(node.mesh)].primitives)
      if (!p.joints.empty()) return true;
  }
  return false;
}

bool skinMethodsDiffer(const std::string& a, const std::string& b) {
  const SkinMethod ma = skinMethodOf(a), mb = skinMethodOf(b);
  return ma != SkinMethod::None && mb != SkinMethod::None && ma != mb;
}

const char* skinReferenceOf(const std::string& pipeline) {
  return skinMethodOf(pipeline) == SkinMethod::MotorBlend ? kMotorBlendReference : kMatrixReference;
}

MotorBlendFrames motorBlendReferenceFrames(Scene& scene, const std::vector<FrameSettings>& settings) {
  MotorBlendFrames out;
  const std::string matrix = pipelineNames(Space::Euclidean).front();
  const std::vector<View> views = framings(scene, settings);  // the skinned scene's own camera
  for (size_t k = 0; k < settings.size(); ++k) {
    PreSkinnedScene pre(scene, settings[k].anim);
    if (!pre.available()) {
      out = {{}, pre.why()};
      return out;
    }
    auto frame = drawFromViews(scene, matrix, {settings[k]}, {views[k]});
    if (!frame) {
      out = {{}, frame.error()};
      return out;
    }
    out.images.push_back(std::move(frame->front()));
  }
  return out;
}

Result<SkinnedFrameJudgement> judgeSkinnedFrame(const std::string& pipeline, const RgbaImage& image,
                                                const RgbaImage& matrix, const RgbaImage* motorBlend,
                                                const std::string& why, const Thresholds* thresholds) {
  using R = Result<SkinnedFrameJudgement>;
  SkinnedFrameJudgement j;
  j.pipeline = pipeline;
  j.reference = skinReferenceOf(pipeline);
  auto vsMatrix = figuresAgainst(pipeline, image, kMatrixReference, matrix);
  if (!vsMatrix) return R::fail(vsMatrix.error());
  j.vsMatrix = *vsMatrix;
  const bool ownIsMatrix = j.reference == kMatrixReference;
  if (!ownIsMatrix && !motorBlend) {
    j.why = why.empty() ? "the motor-blend reference was not made" : why;
    return j;
  }
  const RgbaImage& reference = ownIsMatrix ? matrix : *motorBlend;
  if (ownIsMatrix) j.vsReference = j.vsMatrix;
  else {
    auto vsReference = figuresAgainst(pipeline, image, j.reference, reference);
    if (!vsReference) return R::fail(vsReference.error());
    j.vsReference = *vsReference;
  }
  j.judged = true;
  const std::string against = pipeline + " against its own method's reference (" + j.reference + ")";
  if (j.vsReference.drawn.failed) {
    j.failed = true;
    j.reason = against + ": " + j.vsReference.drawn.counts +
               (ownIsMatrix ? "" : "; " + percentText(j.vsMatrix.drawn.apartPercent) + " from matrix") +
               ": wrong pose, scale or missing mesh";
  }
  if (thresholds) {
    j.thresholdsApplied = true;
    j.thresholds = judge(reference, image, *thresholds);
    if (j.thresholds.failed) {
      j.reason += (j.failed ? "; " : against + ": ") + j.thresholds.reason;
      j.failed = true;
    }
  }
  return j;
}

std::vector<std::string> judgementLines(const SkinnedFrameJudgement& j) {
  const std::string matrixLine = figuresText(j.vsMatrix, j.pipeline, kMatrixReference);
  if (!j.judged)
    return {j.pipeline + " not judged against the " + j.reference + " (" + j.why + "); against matrix: " + matrixLine};
  if (j.reference == kMatrixReference)
    return {j.pipeline + " against matrix (its own method's reference): " + matrixLine};
  return {j.pipeline + " against the " + j.reference + " (its own method's: " + kMotorBlendReferenceDefinition +
              "): " + figuresText(j.vsReference, j.pipeline, "reference"),
          j.pipeline + " against matrix (the other method, measured, decides nothing): " + matrixLine};
}

json toJson(const SkinnedFrameJudgement& j) {
  return {{"pipeline", j.pipeline},
          {"reference", j.reference},
          {"judged", j.judged},
          {"why", j.judged ? json(nullptr) : json(j.why)},
          {"vsMatrix", figuresJson(j.vsMatrix)},
          {"vsReference", j.judged ? figuresJson(j.vsReference) : json(nullptr)},
          {"thresholds", {{"applied", j.thresholdsApplied}, {"failed", j.thresholds.failed},
                          {"failPercent", j.thresholds.failPercent},
                          {"reason", j.thresholds.failed ? json(j.thresholds.reason) : json(nullptr)}}},
          {"failed", j.failed},
          {"reason", j.failed ? json(j.reason) : json(nullptr)}};
}

}  // namespace mb
