// What the motor family's exact fallback (linear_fallback.h) takes on a scene at rest, counted
// on the CPU without drawing: for `inspect` and the corpus statistics. The GPU pipelines count
// the same per frame in PipelineStats (linearFallbackDraws, skinFallbackDraws, ...).
#pragma once
#include <cstdint>

#include "pipelines/scene/scene.h"

namespace mb::motor {

struct FallbackCensus {
  int generalNodes = 0;      // nodes whose world may not be a similarity (Rig::general)
  int linearDraws = 0;       // rigid primitives drawn on the fallback (per instance)
  int skinPalettes = 0;      // skinned mesh nodes whose palette takes the per-joint fallback
  int skinJoints = 0;        // the joints of those palettes
  uint64_t vertices = 0;     // vertices of all those draws
};

FallbackCensus restFallbackCensus(const Scene& scene);

}  // namespace mb::motor
