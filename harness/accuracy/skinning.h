// Skinning: motor blending, like dual-quaternion skinning, keeps the mesh's volume where linear
// blend skinning (LBS) pinches. Both ways are skinned on the CPU from the pipelines' own palettes
// (the matrix pipeline's world-space palette, LBS of the joint matrices; the motor palette,
// motorBlendJoints of shaders/motor_transform.glsl and the skin's uniform scale):
//   - the built-in skinned_tube's candy_wrapper animation (the middle joint turns 180 degrees
//     about the tube's axis): each ring's radius (mean distance of its vertices from their
//     centroid) over the rest radius, at 64 times;
//   - every animated skinned mesh of the glTF files of a folder: a closed mesh's enclosed volume,
//     an open mesh's local volume (det of the skinning map's Jacobian per vertex), posed / rest.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "pipelines/result.h"

namespace mb::accuracy {

// Enclosed volume of a triangle mesh (sum of signed tetrahedra from the origin; meaningful for a
// closed mesh), and whether the mesh is closed once vertices at the same position are welded
// (every edge shared by exactly two triangles).
double enclosedVolume(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices);
bool isClosed(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices);

struct RingRadii {
  bool measured = false;
  std::string why;                  // when not measured
  double lbs = 1e30, motor = 1e30;  // smallest ring radius / rest radius over rings and times
  float lbsTime = 0, motorTime = 0;
  int rings = 0, times = 0;
};
RingRadii measureCandyWrapper();

// The figures skin.ring_radius.candy_wrapper.* into `figures`, the times into `details`.
void putCandyWrapperFigures(const RingRadii& r, nlohmann::json& figures, nlohmann::json& details);

// Every animated skinned mesh of the .gltf/.glb files under `dir` (recursively, sorted, as
// report and inspect walk a folder): {"folder", "files": [every file read, relative to dir],
// "meshes": [{"id" (file/mesh[#primitive]), "file", "closed", "measure", "lbs": {"min", "max"},
// "motor": {"min", "max"}}]} (posed / rest volume over every time), or why not (no such folder,
// no glTF file in it).
Result<nlohmann::json> measureSkinnedFileVolumes(const std::string& dir);

// The figures skin.volume.files.* of such a measurement into `figures`, the measurement itself
// into `details`.
void putSkinnedFileFigures(const nlohmann::json& volumes, nlohmann::json& figures, nlohmann::json& details);

}  // namespace mb::accuracy
