// Did two pipelines draw the same shape? Judged from the pixels each drew (not the background),
// before any threshold: a pipeline that drew nothing where the other drew, or drawn-pixel
// counts more than 1 % apart, is a wrong image. A skinned frame of two skinning methods is checked
// against the pipeline's own method's reference instead (skin_judgement.h), with this same
// check. compare's exit status and note and the report's frame marks both come from checkDrawn,
// so the two never disagree.
#pragma once
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "harness/render/image_metrics.h"

namespace mb {

// Drawn-pixel counts further apart than this fraction of the larger one fail.
inline constexpr double kDrawnApartFraction = 0.01;

struct DrawnCheck {
  enum class Kind {
    Agree,         // both drew, counts within 1 %
    NothingDrawn,  // neither drew a pixel: nothing to compare (the caller's rule)
    OneEmpty,      // one drew nothing, the other drew: fails
    CountsApart,   // both drew, counts more than 1 % apart: fails
  };
  Kind kind = Kind::Agree;
  bool failed = false;              // OneEmpty or CountsApart
  bool skinningMethodNote = false;  // Agree, skinned primitives drawn, the blend methods differ
  int64_t drawnA = 0, drawnB = 0;
  double apartPercent = 0;          // |a - b| / max(a, b) x 100 (0 when both are 0)
  std::string counts;               // what failed, naming both: "drawn-pixel counts more than 1 % apart
                                    // (a N, b M: x %)" or "a drew nothing (0 pixels) where b drew M"
  std::string reason;               // counts and what it means; "" unless failed
};

// `skinnedDrawn`: the frame draws skinned primitives; `methodsDiffer`: pipelines a and b blend
// joints by different methods (report::skinBlendOf).
DrawnCheck checkDrawn(const std::string& a, int64_t drawnA, const std::string& b, int64_t drawnB, bool skinnedDrawn,
                      bool methodsDiffer);
// The same from the two frames (render_frame.h's drawnPixels of each).
DrawnCheck checkDrawn(const std::string& a, const RgbaImage& imageA, const std::string& b, const RgbaImage& imageB,
                      bool skinnedDrawn, bool methodsDiffer);

// "agree", "nothing drawn", "one empty", "counts apart".
const char* kindName(DrawnCheck::Kind kind);
// {"kind", "failed", "reason" (null unless failed), "apartPercent", "skinningMethodNote"}: compare's
// metrics.json "drawnCheck" and each report frame's "drawnCheck.<pipeline>".
nlohmann::json toJson(const DrawnCheck& check);

}  // namespace mb
