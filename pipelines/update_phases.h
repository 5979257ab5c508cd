// Where Pipeline::update spends its time, phase by phase: measured only when
// the caller asks (Pipeline::timeUpdatePhases), so that the update timed as a whole carries no
// clock reads. A PhaseClock reads std::chrono::steady_clock once per lap and adds the time
// since the previous lap to one phase; every phase is summed over the update.
#pragma once
#include <chrono>

namespace mb {

// Milliseconds per phase of the last update (all 0 when not measured). Which work falls where
// is the same rule for every pipeline:
struct UpdatePhases {
  double samplingMs = 0;    // keyframe search and interpolation of each animation posed (sampleAnimation)
  double blendingMs = 0;    // mixing the two animations of a blend (TRS slerp, or motor blend)
  double conversionMs = 0;  // per-frame representation changes: sampled TRS -> local matrix or
                            // ScaledMotor; hybrid: world / joint motors -> mat4x3
  double hierarchyMs = 0;   // world transforms: parent world x local, parents first; matrix
                            // forms: + the normal matrices of the drawn nodes (computed per
                            // node in the Sample Viewer's hierarchy pass; motors need none)
  double paletteMs = 0;     // skin palettes: joint world x inverse bind (+ normal matrices)
  double total() const { return samplingMs + blendingMs + conversionMs + hierarchyMs + paletteMs; }
};

// Laps of one update into `phases` (cleared at construction); a null `phases` makes every lap a
// no-op, with no clock read.
class PhaseClock {
public:
  using Slot = double UpdatePhases::*;
  explicit PhaseClock(UpdatePhases* phases) : phases_(phases) {
    if (!phases_) return;
    *phases_ = UpdatePhases{};
    last_ = Clock::now();
  }
  // Adds the time since the previous lap (or construction) to `slot`.
  void lap(Slot slot) {
    if (!phases_) return;
    const Clock::time_point now = Clock::now();
    phases_->*slot += std::chrono::duration<double, std::milli>(now - last_).count();
    last_ = now;
  }

private:
  using Clock = std::chrono::steady_clock;
  UpdatePhases* phases_;
  Clock::time_point last_{};
};

}  // namespace mb
