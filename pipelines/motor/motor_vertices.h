// The motor pipeline's vertex layout: position (3), tangent rotor (4) and TEXCOORD_0 (2)
// interleaved, 9 floats (36 bytes) per vertex, against the matrix pipeline's 12. The normal
// and the tangent live in the rotor; the handedness in the sign of its scalar part.
#pragma once
#include <vector>

#include "pipelines/scene/scene.h"

namespace mb::motor {

constexpr int kFloatsPerVertex = 9;  // stride; stats are still measured from upload sizes

struct VertexStream {
  std::vector<float> data;    // kFloatsPerVertex floats per vertex
  int zeroScalarFrames = 0;   // frames whose rotor scalar part was exactly 0 (see companion.h)
};

// The frame of vertex v as interleaveVertices encodes it (absent streams filled as below).
struct VertexFrame {
  glm::vec3 normal;
  glm::vec4 tangent;  // xyz + handedness w
};
VertexFrame vertexFrame(const Primitive& p, size_t v);

// Interleaves `p`'s streams, converting (normal, tangent, w) to tangent rotors
// (companion::encodeTangentRotor). Absent streams are filled as the matrix pipeline fills them,
// so both pipelines shade the same frames: a missing tangent becomes
// normalize(cross(n, |n.x| < 0.9 ? x : y)) with w = +1, missing uv0 (0, 0), a missing normal
// (0, 0, 1).
VertexStream interleaveVertices(const Primitive& p);

}  // namespace mb::motor
