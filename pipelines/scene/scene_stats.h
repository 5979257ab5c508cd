// Per-file statistics of a loaded Scene and their aggregate over many files, as printed and
// written by `motorbench inspect`.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipelines/scene/scale_analysis.h"
#include "pipelines/scene/scene.h"

namespace mb {

struct FileStats {
  std::string file;
  bool loaded = false;
  std::string error;  // when !loaded
  // Geometry (meshes counted once) and what the nodes draw (instances).
  int nodes = 0, matrixNodes = 0, meshes = 0, primitives = 0, vertices = 0, triangles = 0;
  // drawnVertices: vertex-shader runs per frame: mesh vertices per instancing node, plus for
  // Bezier patch primitives (Primitive::patchPoints) (N+1)^2 per patch at N = Scene::patchLevel.
  // Instances: EXT_mesh_gpu_instancing / --instances (Node::instances); an instanced node
  // draws its mesh once per instance (drawnVertices counts each).
  int meshNodes = 0, drawnVertices = 0;
  int instancedNodes = 0, instances = 0;
  int patches = 0;  // bicubic Bezier patches (meshes counted once)
  int materials = 0, textures = 0, images = 0, cameras = 0;
  int normalMappedPrimitives = 0, authoredTangentPrimitives = 0, skinnedPrimitives = 0;
  int skins = 0, joints = 0, maxJointsPerSkin = 0;
  int animations = 0, channels = 0, translationChannels = 0, rotationChannels = 0, scaleChannels = 0;
  int linearChannels = 0, stepChannels = 0, cubicChannels = 0;
  // Morph targets (meshes counted once): meshes and primitives with targets, targets summed
  // over meshes, the most any mesh has, and the animation channels that drive weights.
  int morphMeshes = 0, morphPrimitives = 0, morphTargets = 0, maxMorphTargets = 0, weightsChannels = 0;
  ScaleReport scale;
  std::vector<std::string> unsupported;
  LoadStats fallbacks;
  CompressionStats compression;
  std::string notDrawn;  // whyNothingDrawn (drawable.h): "" when the file draws something
};

FileStats computeFileStats(const Scene& scene);
FileStats failedFileStats(const std::string& file, const std::string& error);

nlohmann::json toJson(const FileStats& s);
nlohmann::json toJson(const LoadStats& s);
nlohmann::json toJson(const CompressionStats& c);
// inspect's line: "KHR_draco_mesh_compression 2 primitives, 1234 -> 5678 bytes; ..." or "none".
std::string describeCompression(const CompressionStats& c);
// Aggregate over files: counts, sums and fractions (e.g. of loaded files with animated scale).
nlohmann::json aggregateJson(const std::vector<FileStats>& files);
// The same from the files' JSON (toJson(FileStats) of each), so that sharded inspect runs can be
// aggregated by `motorbench merge` exactly as one run would.
nlohmann::json aggregateFileJson(const nlohmann::json& files);

}  // namespace mb
