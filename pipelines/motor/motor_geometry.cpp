#include "pipelines/motor/motor_geometry.h"

#include "pipelines/motor/morph_rotors.h"
#include "pipelines/motor/motor_c_vertices.h"
#include "pipelines/motor/motor_q_vertices.h"
#include "pipelines/motor/motor_vertices.h"

namespace mb::motor {

void MotorGeometry::upload(const Scene& scene, const MotorVariant& variant, MorphMethod method,
                           PipelineStats& stats) {
  release();
  // The compact rotors morph by method (a) only: their rotor is decoded to a frame anyway.
  const gl::MorphPacker packer = variant.compact ? gl::MorphPacker(gl::packFrameDeltas) : morphPacker(method);
  if (variant.compact) cubes = compact::primitiveCubes(scene);
  if (variant.fragmentRotor) {
    uploadSignedCompact(scene, packer, stats);
    return;
  }
  if (variant.compact) {
    vertices.uploadPacked(scene, interleaveCompact, compact::attributes(), stats);
  } else if (variant.quantizedFrame) {
    vertices.uploadPacked(scene, interleaveQuantized, gl::snormFrameAttributes(), stats);
  } else {
    auto format = [&stats](const Primitive& p) {
      VertexStream stream = interleaveVertices(p);
      stats.zeroScalarFrames += stream.zeroScalarFrames;
      stats.biasedFrames += stream.biasedFrames;
      return gl::VertexFormat{std::move(stream.data), {{0, 3}, {1, 4}, {2, 2}}};  // position, tangent rotor, uv0
    };
    vertices.upload(scene, format, stats);
  }
  if (gl::maxMorphTargets(scene)) morph.upload(scene, packer, stats);
}

// motor_cf: every primitive through the sign pass, which may add vertices; the upload reads a
// scene of the split meshes (nodes and materials as `scene`'s), morph deltas split with them.
void MotorGeometry::uploadSignedCompact(const Scene& scene, const gl::MorphPacker& packer, PipelineStats& stats) {
  Scene split;
  split.nodes = scene.nodes;
  split.materials = scene.materials;
  std::vector<std::vector<uint8_t>> streams;  // mesh by mesh, primitive by primitive
  for (const Mesh& mesh : scene.meshes) {
    split.meshes.push_back({mesh.name, {}, mesh.weights});
    interpolable.emplace_back();
    for (const Primitive& p : mesh.primitives) {
      SignedCompactStream s = interleaveCompactSigned(p);
      stats.zeroScalarFrames += s.zeroScalarFrames;
      stats.rotorSplitVertices += s.splitVertices;
      stats.rotorUnresolvedTriangles += s.unresolvedTriangles;
      interpolable.back().push_back(s.interpolableIndices);
      split.meshes.back().primitives.push_back(std::move(s.primitive));
      streams.push_back(std::move(s.bytes));
    }
  }
  size_t next = 0;  // uploadPacked asks for the primitives in that order
  vertices.uploadPacked(split, [&](const Primitive&) { return std::move(streams[next++]); },
                        compact::attributes(), stats);
  if (gl::maxMorphTargets(split)) morph.upload(split, packer, stats);
}

void MotorGeometry::release() {
  vertices.release();
  morph.release();
  cubes.clear();
  interpolable.clear();
}

}  // namespace mb::motor
