// A skinned frame judged by its own skinning method (pipelines/skin_method.h). A pipeline that
// blends joint motors is judged against the motor-blend reference (skin_reference.h: the same
// pose skinned on the CPU by the motor blend, drawn by matrix), one that blends matrices linearly
// against matrix. The two methods pose a skinned mesh differently by design (LBS loses volume
// where joints turn far apart), so a skinned frame is equivalent when it is close to its own
// method's reference; its distance from matrix is measured and shown beside it, and decides
// nothing. compare, report and survey all judge here; check compares each pipeline with its own
// goldens only, so it has nothing to judge across methods.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/render/drawn_check.h"
#include "harness/render/frame_options.h"
#include "harness/render/image_metrics.h"
#include "pipelines/result.h"
#include "pipelines/scene/scene.h"

namespace mb {

// The references, as every output names them.
inline constexpr const char* kMatrixReference = "matrix";
inline constexpr const char* kMotorBlendReference = "motor-blend reference";
// What the motor-blend reference is, for the texts that name it.
inline constexpr const char* kMotorBlendReferenceDefinition =
    "the same pose skinned on the CPU by the motor blend (GLM dual quaternions), drawn by matrix";

// A frame of `scene` draws skinned primitives: a node the scene reaches has a skin and a mesh
// primitive with joints.
bool drawsSkinned(const Scene& scene);

// True when pipelines `a` and `b` blend joints by different methods (both registered with one).
bool skinMethodsDiffer(const std::string& a, const std::string& b);

// The reference `pipeline`'s skinned frames are judged against: kMotorBlendReference for the
// motor-blend pipelines, kMatrixReference for the others.
const char* skinReferenceOf(const std::string& pipeline);

// The motor-blend reference of every frame of `settings`, each seen from the unchanged scene's
// own framing (fixed_views.h) and drawn by matrix. `scene` is changed while it draws and
// restored. Not available (images empty, `why` says why): the pose cannot be pre-skinned
// (PreSkinnedScene::why()) or the draw failed (its error).
struct MotorBlendFrames {
  std::vector<RgbaImage> images;  // one per entry of `settings`
  std::string why;
  bool available() const { return why.empty(); }
};
MotorBlendFrames motorBlendReferenceFrames(Scene& scene, const std::vector<FrameSettings>& settings);

// One image against one reference: the image metrics and the drawn-pixel check.
struct SkinFigures {
  ImageMetrics metrics;
  DrawnCheck drawn;
};

struct SkinnedFrameJudgement {
  std::string pipeline;
  std::string reference;          // skinReferenceOf(pipeline)
  bool judged = false;            // false: the reference could not be made (`why`): nothing decided
  std::string why;
  SkinFigures vsMatrix;           // against matrix (measured, decides nothing for motor-blend pipelines)
  SkinFigures vsReference;        // against its own method's reference (the same as vsMatrix for LBS)
  bool thresholdsApplied = false;
  Verdict thresholds;             // the thresholds given, against the reference
  bool failed = false;            // judged, and drawn pixels more than 1 % apart from the reference,
                                  // one image empty, or a threshold exceeded
  std::string reason;             // why it failed ("" otherwise)
};

// Judges `image`, `pipeline`'s frame of a skinned scene. `matrix`: the matrix pipeline's frame
// of the same settings; `motorBlend`: that frame's motor-blend reference (read for motor-blend
// pipelines only; null when not available, `why` saying why: not judged). `thresholds`: null
// when none were given (the drawn-pixel check alone decides). A drawn-pixel failure says "wrong
// pose, scale or missing mesh": more than 1 % from its own method's reference is more than the
// method's difference allows. Errors: images of different sizes.
Result<SkinnedFrameJudgement> judgeSkinnedFrame(const std::string& pipeline, const RgbaImage& image,
                                                const RgbaImage& matrix, const RgbaImage* motorBlend,
                                                const std::string& why, const Thresholds* thresholds);

// "motor against the motor-blend reference: PSNR 89.10 dB; pixels off by more than 2/255:
// 0.000 %; drawn pixels 41687 vs 41690 (0.01 % apart)", then the same against matrix (LBS
// pipelines: one line, their reference is matrix); or, not judged, the reason and the figures
// against matrix.
std::vector<std::string> judgementLines(const SkinnedFrameJudgement& j);

// {"pipeline", "reference", "judged", "why" (null when judged), "vsMatrix", "vsReference" (each
// {"identical", "psnr" (null when identical), "maxError", "fractionOver1", "fractionOver2",
// "fractionOver4", "drawnPixels", "referenceDrawnPixels", "drawnApartPercent"}; vsReference null
// when not judged), "thresholds" ({"applied", "failed", "failPercent", "reason"}), "failed",
// "reason" (null unless failed)}: compare's metrics.json "skinJudgement" and each report frame's
// "skinJudgement.<pipeline>".
nlohmann::json toJson(const SkinnedFrameJudgement& j);

}  // namespace mb
