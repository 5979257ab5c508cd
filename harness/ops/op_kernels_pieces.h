// harness/ops/op_kernels_pieces.h: counts the claims quote that are not one function of
// op_kernels.h or of the per-vertex kernels: the glTF quaternion -> rotor conversion, the
// affine mat4x3 composition, and the vertex with frame as the paper adds it up, piece by piece,
// each piece as the shader executes it. Counted on mb::Counted like every other kernel; kept
// out of the `motorbench ops` table (they appear in ops.json's figures). Header-only.
#pragma once
#include <vector>

#include "harness/bench/affine_compose.h"
#include "harness/bench/bench_shaders.h"
#include "harness/ops/op_count.h"
#include "harness/ops/vertex_inputs.h"
#include "pipelines/motor/motor_kernels.h"
#include "shaders/shim/counted.h"

namespace mb::ops {

inline std::vector<Kernel> pieceKernels() {
  using K = MotorKernels<Counted>;
  using PC = MotorShader<Counted>;
  using MC = MatrixShader<Counted>;
  static K kernels;
  static PC P;
  static const opsv::detail::VertexInputs& in = opsv::detail::inputs();
  // A unit quaternion (x, y, z, w) as the loader reads it; two generic affine transforms.
  static const Counted x(0.2), y(-0.4), z(0.5), w(0.74);
  static const MC::mat4x3 a = [] {
    MC::mat4x3 m;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 3; ++r) m[c][r] = Counted(0.3 + 0.4 * c - 0.25 * r);
    return m;
  }();
  static const MC::mat4x3 b = [] {
    MC::mat4x3 m;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 3; ++r) m[c][r] = Counted(-0.2 + 0.3 * c + 0.15 * r);
    return m;
  }();
  static const MC::mat4 model = in.model, normal = in.normal;
  static const MC::vec4 position(in.position, Counted(1.0)), normalV(in.normalV, Counted(0.0)),
      tangent(in.tangent.x, in.tangent.y, in.tangent.z, Counted(0.0));
  const auto paper = [](int mul, int add) { return Claim{mul, add, "paper"}; };
  // companion::rotorFromQuat expression for expression: three sign changes (negation is free).
  const auto rotorFromQuat = [] { return K::motor(K::vec4(w, -x, -y, -z), K::vec4(Counted(0.0))); };
  return {
      {"conversion", "quat_to_rotor", "glTF quaternion (x, y, z, w) -> rotor [w, -x, -y, -z] (companion::rotorFromQuat)",
       paper(0, 0), [rotorFromQuat] { (void)rotorFromQuat(); }},
      {"conversion", "quat_to_rotor_as_run",
       "rotorFromQuat + normalize_m, as the motor pipeline's fromTRS runs it per animated node (the normalisation "
       "is a defensive extra the conversion does not need)",
       std::nullopt, [rotorFromQuat] { (void)kernels.normalize_m(rotorFromQuat()); }},
      {"affine", "mat4x3*mat4x3",
       "affine composition: mat4x3 * mat4x3 (3x3 linear part and translation, the last row 0 0 0 1 implied; "
       "harness/bench/affine_compose.h), the strongest matrix composition",
       std::nullopt, [] { (void)bench::affineCompose<Counted>(a, b); }},
      {"motor", "motor_vertex_frame",
       "motor vertex with frame by the paper's pieces, as the shader executes them: sw_mp + gp_rr + "
       "extractNormalTangent + motorHandedness (sign(1/x)); no uniform scale (the paper counts it apart)",
       paper(47, 38),
       [] {
         (void)P.sw_mp(in.toWorld, in.position);
         (void)P.extractNormalTangent(P.gp_rr(in.toWorld, PC::motor(in.rotor, PC::vec4(0.0))));
         (void)P.motorHandedness(in.rotor);
       }},
      {"motor", "motor_handedness", "motorHandedness: sign(1 / tangentRotor.x) (the paper counts it as 1 mul)",
       std::nullopt, [] { (void)P.motorHandedness(in.rotor); }},
      {"matrix", "three_mat4*vec4",
       "the paper's matrix vertex: three mat4 * vec4 (position and tangent by the model matrix, normal by the "
       "normal matrix), without the shader's handedness",
       paper(48, 36),
       [] {
         (void)(model * position);
         (void)(normal * normalV);
         (void)(model * tangent);
       }},
  };
}

}  // namespace mb::ops
