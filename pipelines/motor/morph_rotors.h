// Morph deltas of the motor family: which method a pipeline draws with and the
// deltas it uploads (pipelines/gl/morph_buffers.h), beside shaders/motor_transform.glsl's
// morph kernels.
#pragma once
#include <vector>

#include "pipelines/gl/morph_buffers.h"

namespace mb::motor {

// Method (b)'s deltas: per target and vertex the position delta, then the rotor of the morphed
// frame (base normal and tangent plus that target's deltas, encodeTangentRotor) minus the
// vertex's base rotor, the former negated when needed to share the latter's hemisphere.
// layout: stride 7, the rotor delta at 3 (normalOffset), no tangent part.
std::vector<float> packRotorDeltas(const Primitive& p, gl::MorphLayout& layout);

// The packer of `method` (pipeline.h's MorphMethod; Frame and PipelineDefault: gl::packFrameDeltas).
gl::MorphPacker morphPacker(MorphMethod method);

}  // namespace mb::motor
