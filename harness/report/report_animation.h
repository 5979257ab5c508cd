// The animated comparison of one scene for the report: one loop of one animation in
// kAnimationFrames frames, each [baseline | pipeline | diff heat map] side by side, written as
// a looping GIF per compared pipeline, so a reader can watch where two pipelines part (LBS
// pinching against motor skinning, for example) instead of guessing from three stills.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "harness/report/report_scene.h"
#include "pipelines/scene/scene.h"

namespace mb::report {

inline constexpr int kAnimationFrames = 24;
inline constexpr int kAnimationFps = 12;

// {pipeline: {"file" (relative to the report folder), "frames", "fps", "duration",
// "maxPixelsOver2" (largest fraction of pixels over 2/255 in any frame)} or {"error"}} for every
// pipeline after the baseline; null when animation `anim` is absent or not of positive duration.
// Files: <relFolder>animation_<pipeline>.gif for animation 0, animation<anim>_<pipeline>.gif else.
nlohmann::json animatedComparisons(const Scene& scene, const SceneJob& job, const std::string& relFolder,
                                   int anim = 0);

}  // namespace mb::report
