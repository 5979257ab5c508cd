// Signs for tangent rotors that the rasteriser interpolates (motor_cf). R and -R are
// the same frame, but a triangle whose vertex rotors lie in opposite hemispheres interpolates
// through zero and shades a frame that is none of its corners'. No rule per vertex can avoid
// that: a frame turning once around a torus' tube comes back as -R. So this is a mesh pass:
// each triangle takes its three rotors in one hemisphere, and a vertex that two triangles need
// with opposite signs is split in two.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/scene/scene.h"

namespace mb::motor {

struct SignedRotors {
  Primitive primitive;            // the input with split vertices appended, indices rewritten
  std::vector<glm::vec4> rotors;  // per vertex of `primitive`: its rotor with the chosen sign
  std::vector<uint32_t> source;   // per vertex of `primitive`: the vertex of the input it copies
  int splitVertices = 0;          // vertices appended
  int unresolvedTriangles = 0;    // triangles with two rotors still more than 90 degrees apart
                                  // in rotor space (frames turned by more than 180 degrees)
  // The unresolved triangles are moved to the end of primitive.indices: indices [0,
  // interpolableIndices) interpolate their rotors, the rest cannot (motor_cf extracts the frame
  // per vertex there instead, as motor_c does).
  size_t interpolableIndices = 0;
};

// `rotors` has one unit rotor per vertex of `p` (sign irrelevant). Triangles are visited in
// index order; each takes the overall sign that agrees with most of its vertices' earlier
// choices, so a smooth mesh splits only along the seams its rotor field needs. Every stream of
// `p` is copied for a split vertex. Deterministic; patch primitives pass through unchanged.
SignedRotors signRotorsForInterpolation(const Primitive& p, const std::vector<glm::vec4>& rotors);

}  // namespace mb::motor
