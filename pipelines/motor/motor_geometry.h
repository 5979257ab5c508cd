// The motor pipelines' vertices and morph deltas in each variant's form, uploaded once by
// prepare(): the paper's 9 floats (motor), the int16 rotor (motor_q), the 16-byte vertex
// (motor_c) or motor_c's bytes with the rotors signed per triangle (motor_cf, whose vertices
// may split: rotor_signs.h). Morph deltas (gl/morph_buffers.h) follow the uploaded
// vertices (motor_cf: its split ones): frame deltas (method (a)) or rotor deltas (method (b),
// float and int16 rotors only).
#pragma once
#include <vector>

#include "pipelines/compact/compact_encoding.h"
#include "pipelines/gl/gpu_geometry.h"
#include "pipelines/gl/morph_buffers.h"
#include "pipelines/motor/motor_pipeline.h"

namespace mb::motor {

struct MotorGeometry {
  gl::SceneGeometry vertices;
  gl::MorphBuffers morph;
  std::vector<std::vector<compact::PositionCube>> cubes;  // compact: per mesh, per primitive
  std::vector<std::vector<size_t>> interpolable;          // motor_cf: per mesh, per primitive

  // Counts into `stats` what the uploads measure (vertex and morph bytes, zero-scalar, biased
  // frames, motor_cf's split vertices and unresolved triangles).
  void upload(const Scene& scene, const MotorVariant& variant, MorphMethod method, PipelineStats& stats);
  void release();

private:
  void uploadSignedCompact(const Scene& scene, const gl::MorphPacker& packer, PipelineStats& stats);
};

}  // namespace mb::motor
