// The full frame qtangent packs (interleaveQTangent): position, normal, tangent (xyz +
// handedness w), uv0 on every primitive, 12 floats: frames as gl::vertexFrame fills them, a
// missing uv0 (0, 0). `affine` itself uploads pipelines/gl/frame_vertices.h's vertex.
#pragma once
#include <vector>

#include "pipelines/scene/scene.h"

namespace mb::affine {

constexpr int kFloatsPerVertex = 12;

std::vector<float> interleaveFullFrame(const Primitive& p);

}  // namespace mb::affine
