#include "harness/render/drawn_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "harness/render/render_frame.h"

namespace mb {

DrawnCheck checkDrawn(const std::string& a, int64_t drawnA, const std::string& b, int64_t drawnB, bool skinnedDrawn,
                      bool methodsDiffer) {
  DrawnCheck c;
  c.drawnA = drawnA, c.drawnB = drawnB;
  const int64_t most = std::max(drawnA, drawnB);
  c.apartPercent = most > 0 ? 100.0 * double(std::llabs(drawnA - drawnB)) / double(most) : 0.0;
  if (most == 0) {
    c.kind = DrawnCheck::Kind::NothingDrawn;
    return c;
  }
  if (drawnA == 0 || drawnB == 0) {
    const bool aEmpty = drawnA == 0;
    c.kind = DrawnCheck::Kind::OneEmpty;
    c.failed = true;
    c.counts = (aEmpty ? a : b) + " drew nothing (0 pixels) where " + (aEmpty ? b : a) + " drew " + std::to_string(most);
    c.reason = c.counts + ": one image is empty";
    return c;
  }
  // 1 % of the larger count: 1000 vs 1010 agrees (10 <= 10.1), 1000 vs 1011 does not.
  if (double(std::llabs(drawnA - drawnB)) > kDrawnApartFraction * double(most)) {
    char pct[32];
    std::snprintf(pct, sizeof pct, "%.2f", c.apartPercent);
    c.kind = DrawnCheck::Kind::CountsApart;
    c.failed = true;
    c.counts = "drawn-pixel counts more than 1 % apart (" + a + " " + std::to_string(drawnA) + ", " + b + " " +
               std::to_string(drawnB) + ": " + pct + " %)";
    c.reason = c.counts + ": the two pipelines did not draw the same shape";
    return c;
  }
  c.skinningMethodNote = skinnedDrawn && methodsDiffer;
  return c;
}

DrawnCheck checkDrawn(const std::string& a, const RgbaImage& imageA, const std::string& b, const RgbaImage& imageB,
                      bool skinnedDrawn, bool methodsDiffer) {
  return checkDrawn(a, drawnPixels(imageA), b, drawnPixels(imageB), skinnedDrawn, methodsDiffer);
}

const char* kindName(DrawnCheck::Kind kind) {
  switch (kind) {
    case DrawnCheck::Kind::Agree: return "agree";
    case DrawnCheck::Kind::NothingDrawn: return "nothing drawn";
    case DrawnCheck::Kind::OneEmpty: return "one empty";
    case DrawnCheck::Kind::CountsApart: return "counts apart";
  }
  return "agree";
}

nlohmann::json toJson(const DrawnCheck& c) {
  return {{"kind", kindName(c.kind)},
          {"failed", c.failed},
          {"reason", c.failed ? nlohmann::json(c.reason) : nlohmann::json(nullptr)},
          {"apartPercent", c.apartPercent},
          {"skinningMethodNote", c.skinningMethodNote}};
}

}  // namespace mb
