// Frames of a scene changed in place (positions jittered, the pose skinned on the CPU) seen by
// the unchanged scene's camera: the views are taken first (framings), the changed scene is then
// drawn from them (drawFromViews), not framed anew. The tie probes of survey and the motor-blend
// reference (skin_judgement.h) draw through here.
#pragma once
#include <string>
#include <vector>

#include "harness/render/frame_options.h"
#include "harness/render/image_metrics.h"
#include "pipelines/result.h"
#include "pipelines/scene/camera_rule.h"
#include "pipelines/scene/scene.h"

namespace mb {

// The automatic framing of each frame (frameScene with its animation, aspect and camera), as
// renderFrame frames it.
std::vector<View> framings(const Scene& scene, const std::vector<FrameSettings>& settings);

// Every frame of `settings` drawn by `pipeline` (configured with the first frame's options and
// prepared once) from `views`, one per frame. Errors name the scene and the pipeline; an exception
// thrown inside the pipeline is returned as one.
Result<std::vector<RgbaImage>> drawFromViews(const Scene& scene, const std::string& pipeline,
                                             const std::vector<FrameSettings>& settings, const std::vector<View>& views);

}  // namespace mb
