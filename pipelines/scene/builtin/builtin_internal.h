// Generators of the built-in scenes (builtin_*.cpp) and the procedural pieces they share.
#pragma once
#include <cstdint>
#include <vector>

#include "pipelines/scene/builtin/gltf_writer.h"

namespace mb {

// pi as the built-in scenes' float geometry uses it.
inline constexpr float kPi = 3.14159265359f;

void buildNormalTorus(GlbBuilder& b);
void buildDenseTorus(GlbBuilder& b);
void buildTexturedBox(GlbBuilder& b);
void buildSkinnedTube(GlbBuilder& b);
void buildScaledHierarchy(GlbBuilder& b);
void buildCrowd(GlbBuilder& b);
void buildTeapot(GlbBuilder& b);
void buildInstancedGrid(GlbBuilder& b);
void buildMorphTorus(GlbBuilder& b);

// Tangent-space normal map (RGBA8, size x size) of a height field of sin bumps with the given
// number of periods along u and v; deterministic.
std::vector<uint8_t> bumpNormalMap(int size, int periodsU, int periodsV, float strength);

// Base-colour texture: checker of two colours with an asymmetric "L" mark in the first cell,
// so mirrored or rotated uv frames are visible.
std::vector<uint8_t> markedChecker(int size, int cells, glm::u8vec3 a, glm::u8vec3 b);

// The textured, normal-mapped box (mesh + material + 2 textures). Returns the mesh index.
// Six faces with axis-aligned tangent frames; those of -Z and -Y are 180-degree turns of the
// basis frame (T,B,N) = (X,Y,Z).
int addTexturedBoxMesh(GlbBuilder& b);

// Skinned tube along +Y from y = 0 to y = length: `joints` joints at equal spacing (joint j
// at y = j * length / (joints - 1)), each vertex blended linearly between its two nearest
// joints; normal-mapping tangents along the circumference.
MeshData makeSkinnedTube(int rings, int sides, float length, float radius, int joints);

}  // namespace mb
