// What corpus-check's rigid and 16-byte rules are judged with (survey draws the frames; these
// measure pixels): the 16-byte position bound, the envelope test, the tie probes, and the
// geometry view. README: Corpus check.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "harness/render/fixed_views.h"
#include "harness/render/frame_options.h"
#include "harness/render/image_metrics.h"
#include "pipelines/gl/program.h"
#include "pipelines/result.h"
#include "pipelines/scene/animation.h"
#include "pipelines/scene/camera_rule.h"
#include "pipelines/scene/scene.h"

namespace mb::survey {

// The 16-byte pipelines' position error for a rigid frame (posed by `anim`, framed by `view`,
// `width` x `height`): in world units, in pixels, and as the envelope radius that covers it.
struct PositionBound {
  double world = 0, pixels = 0;
  int radius = 1;
};
PositionBound positionBound(const Scene& scene, const AnimState& anim, const View& view, int width, int height);

// Pixels of `a` whose farthest channel lies more than `tolerance` bytes outside the min..max of
// that channel over the (2r+1)^2 neighbourhood of the same pixel in `b`: what a displacement of
// at most r pixels cannot explain. `ties` (a mask, or null): the same counted outside it.
struct Envelope {
  int64_t over = 0, overNotTies = 0;
  int worst = 0, worstNotTies = 0;
};
Envelope envelope(const RgbaImage& a, const RgbaImage& b, int r, int tolerance, const std::vector<uint8_t>* ties);

// The channel change the envelope allows, in byte steps: 4 is the diff heat map's "red" stop
// (image_metrics.h), fixed before any corpus run; it covers the half-float uv of the 16-byte
// vertex in the geometry view.
constexpr int kShadeTolerance = 4;

// 1 per pixel that differs (any RGB channel) between `a` and `b`, same size.
std::vector<uint8_t> differingMask(const RgbaImage& a, const RgbaImage& b);

// How a tie probe moves every vertex coordinate of the baseline's scene.
enum class TieJitter {
  // By a pseudo-random amount of at most 2^-20 of its primitive's largest coordinate: the
  // rounding by which two correct float pipelines differ (rigid rule).
  FloatRounding,
  // To a corner of its int16 quantisation cell, +-half the step h/32767 of the 16-byte
  // pipelines' positions (h: the primitive's largest half side), and in one more render to the
  // int16 grid point the 16-byte pipelines store (compact_encoding.h): what the quantised
  // positions leave undetermined (16-byte rule).
  Int16Cell,
};
struct TieProbe {
  TieJitter jitter;
  int pairs;  // antithetic pairs of renders (+j, -j) per frame
};
// The baseline's renders per frame: the pairs, plus the int16 grid render for Int16Cell.
int tieRenders(TieProbe probe);
constexpr TieProbe kFloatTies{TieJitter::FloatRounding, 1};
constexpr TieProbe kInt16Ties{TieJitter::Int16Cell, 2};

// framings and drawFromViews: harness/render/fixed_views.h.

// The tie masks of every frame: the pixels `baseline` draws differently from `base` (its images
// of the unjittered scene, one per `settings`) in any of the probe's jittered renders. The
// positions are jittered in place and restored before it returns, whatever happens.
Result<std::vector<std::vector<uint8_t>>> tieMasks(Scene& scene, const std::string& baseline,
                                                   const std::vector<FrameSettings>& settings,
                                                   const std::vector<RgbaImage>& base, TieProbe probe);

// While it lives, every program linked draws the geometry view (forward.fs MB_GEOMETRY_VIEW:
// the base colour alone, no frame and no light): a pixel then depends on positions, uv and vertex
// colour only, so the 16-byte rule judges the positions apart from how a pipeline shades.
class GeometryView {
public:
  GeometryView() : saved_(gl::globalDefines()) {
    gl::Defines d = saved_;
    d.emplace_back("MB_GEOMETRY_VIEW", "");
    gl::setGlobalDefines(std::move(d));
  }
  ~GeometryView() { gl::setGlobalDefines(saved_); }
  GeometryView(const GeometryView&) = delete;
  GeometryView& operator=(const GeometryView&) = delete;

private:
  gl::Defines saved_;
};

}  // namespace mb::survey
