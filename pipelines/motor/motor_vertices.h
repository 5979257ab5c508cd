// The motor pipeline's vertex layout: position (3), tangent rotor (4) and TEXCOORD_0 (2)
// interleaved, 9 floats (36 bytes) per vertex, against the matrix pipeline's 12. The normal
// and the tangent live in the rotor; the handedness in the sign of its scalar part.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/scene/scene.h"

namespace mb::motor {

constexpr int kFloatsPerVertex = 9;  // stride; stats are still measured from upload sizes

struct VertexStream {
  std::vector<float> data;    // kFloatsPerVertex floats per vertex
  int zeroScalarFrames = 0;   // frames whose rotor scalar part was exactly 0 (see companion.h)
  int biasedFrames = 0;       // frames whose scalar the bias rule raised to +-1/32767
};

// Vertex v's tangent rotor: companion::encodeTangentRotor of the frame gl::vertexFrame fills;
// a scalar part of exactly 0 counts into `zeroScalarFrames`.
glm::vec4 vertexRotor(const Primitive& p, size_t v, int& zeroScalarFrames);

// Interleaves `p`'s streams: position, vertexRotor, uv0 (a missing uv0 (0, 0)), counting the
// frames as motor_q's stream does.
VertexStream interleaveVertices(const Primitive& p);

}  // namespace mb::motor
