// The curved-space pipelines, one class for four registered names:
//   s3_matrix / h3_matrix: one O(4) / O(3,1) mat4 per instance (16 floats), as
//     non-euclidean-rendering.txt does (shaders/curved_matrix.vs);
//   s3_motor / h3_motor: 8 floats per instance (S3: the quaternion pair, H3: the motor),
//     sandwiched in the vertex shader (shaders/curved_motor.vs).
// Both sides of a space share shaders/curved.fs. They draw only scenes of their space
// (Scene::curved) and refuse glTF scenes; the glTF pipelines refuse curved scenes.
#pragma once
#include <memory>

#include "pipelines/pipeline.h"
#include "pipelines/registry.h"

namespace mb {
// The registry entry of the curved pipeline of `space` (Spherical or Hyperbolic), matrix or motor.
PipelineEntry curvedEntry(Space space, bool motor);
}  // namespace mb
