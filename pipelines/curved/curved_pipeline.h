// The curved-space pipelines s3_matrix, s3_motor, h3_matrix, h3_motor: one class for four
// registered names (pipelines/curved/README.md).
#pragma once
#include "pipelines/registry.h"

namespace mb {
// The registry entry of the curved pipeline of `space` (Spherical or Hyperbolic), matrix or motor.
PipelineEntry curvedEntry(Space space, bool motor);
}  // namespace mb
