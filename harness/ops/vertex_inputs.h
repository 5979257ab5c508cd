// The inputs every counted vertex kernel runs on (generic values: no product skipped by a
// branch) and the GLSL declarations the kernels' probe shaders share.
#pragma once
#include <string>

#include "harness/bench/bench_shaders.h"
#include "shaders/shim/counted.h"
#include "shaders/shim/patch.h"
#include "shaders/shim/pga.h"

namespace mb::opsv {

namespace detail {

using MC = MatrixShader<Counted>;
using AC = AffineShader<Counted>;
using PC = MotorShader<Counted>;
using PD = Pga<double>;
using TC = PatchShaders<Counted>;
using TD = PatchShaders<double>;

// Generic inputs: no zero coefficients (no product is skipped by a branch), unit motors built
// in double, matrices with arbitrary entries (counting does not depend on the values).
struct VertexInputs {
  MC::mat4 model, normal, viewProj, j[4], n[4];
  MC::mat4x3 affine, affineJoints[4];
  MC::mat3 affineNormal, affineNormals[4];
  MC::vec4 qtangent;
  MC::vec3 position, normalV;
  MC::vec4 tangent, weights, world;
  PC::motor toWorld, camera, joints[4];
  PC::vec4 rotor;
  // Compact: 2_10_10_10 words as the shader reads them (integer-valued floats) and
  // a mesh cube; generic codes: tangent and rotor on their second branch, handedness -1.
  MC::vec4 compactMatrixFrame{700.0, 300.0, 900.0, 1.0}, compactRotor{700.0, 300.0, 900.0, 1.0};
  MC::vec4 dequant{0.1, -0.2, 0.3, 2.5};
  VertexInputs() {
    auto mat = [](double seed) {
      MC::mat4 m;
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) m[c][r] = Counted(seed + 0.37 * c - 0.21 * r + 0.05 * c * r);
      return m;
    };
    model = mat(0.9), normal = mat(-0.4), viewProj = mat(1.3);
    for (int i = 0; i < 4; ++i) j[i] = mat(0.1 * i + 0.2), n[i] = mat(-0.1 * i + 0.5);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 3; ++r) affine[c][r] = Counted(0.3 + 0.4 * c - 0.25 * r);
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) affineNormal[c][r] = Counted(-0.6 + 0.3 * c + 0.2 * r);
    for (int i = 0; i < 4; ++i) {
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 3; ++r) affineJoints[i][c][r] = Counted(0.1 * i + 0.3 + 0.4 * c - 0.25 * r);
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) affineNormals[i][c][r] = Counted(-0.1 * i - 0.6 + 0.3 * c + 0.2 * r);
    }
    qtangent = MC::vec4(0.5, -0.5, 0.5, -0.5);  // handedness -1
    position = MC::vec3(0.5, -1.25, 2.0), normalV = MC::vec3(0.36, 0.48, 0.8);
    tangent = MC::vec4(0.8, -0.6, 0.1, -1.0), weights = MC::vec4(0.4, 0.3, 0.2, 0.1);
    world = MC::vec4(1.5, 0.25, -3.0, 1.0);
    PD& P = pga<double>;
    auto motor = [&](double w, double x, double y, double z, double tx, double ty, double tz) {
      PD::motor r = P.normalize_m(PD::motor(PD::vec4(w, -x, -y, -z), PD::vec4(0.0)));
      PD::motor t(PD::vec4(1.0, 0.0, 0.0, 0.0), PD::vec4(-0.5 * tx, -0.5 * ty, -0.5 * tz, 0.0));
      return PC::motor(P.gp_tr(t, r));
    };
    toWorld = motor(0.8, 0.3, -0.4, 0.2, 1.5, -2.0, 0.75);
    camera = motor(0.1, -0.7, 0.5, 0.4, -0.25, 3.0, 1.25);
    // Joint 2 points away from joint 0 (negative dot): the blend's shortest-arc flip is taken.
    joints[0] = toWorld, joints[1] = motor(0.7, 0.2, 0.5, -0.1, 0.1, 0.2, 0.3);
    joints[2] = motor(-0.6, 0.4, 0.3, 0.2, -0.5, 0.4, 0.0);
    joints[3] = motor(0.9, -0.1, 0.2, 0.3, 0.3, -0.2, 0.1);
    rotor = PC::vec4(-0.5, 0.5, -0.5, 0.5);  // handedness -1
    // A Bezier patch: a curved 4x4 net with no coincident points, an interior uv; the frame
    // kernels take the surface it evaluates to.
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        rows[r][c] = TC::vec3(0.7 * c - 0.1 * r * r, 0.5 * r + 0.05 * c * c, 0.3 * (c - 1.5) * (r - 1.5) + 0.1 * c);
    uv = TC::vec2(0.3, 0.6);
    TD::mat4x3 rd[4];
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) rd[r][c] = TD::vec3(rows[r][c].x.v, rows[r][c].y.v, rows[r][c].z.v);
    TD t;
    TD::mat3 sd = t.bezierPatch(rd[0], rd[1], rd[2], rd[3], TD::vec2(0.3, 0.6));
    for (int i = 0; i < 3; ++i) surface[i] = TC::vec3(sd[i].x, sd[i].y, sd[i].z);
  }
  TC::mat4x3 rows[4];
  TC::vec2 uv;
  TC::mat3 surface;
};

inline const VertexInputs& inputs() {
  static const VertexInputs in;
  return in;
}

inline const char* kMatrixAttribs =
    "layout(location = 0) in vec3 a_position; layout(location = 1) in vec3 a_normal;\n"
    "layout(location = 2) in vec4 a_tangent; layout(location = 7) in vec4 a_weights;\n"
    "layout(location = 0) out vec4 o_0; layout(location = 1) out vec4 o_1;\n"
    "layout(location = 2) out vec4 o_2;\n";
inline const char* kMotorAttribs =
    "layout(location = 0) in vec3 a_position; layout(location = 1) in vec4 a_tangentRotor;\n"
    "layout(location = 7) in vec4 a_weights;\n"
    "layout(location = 0) out vec4 o_0; layout(location = 1) out vec4 o_1;\n"
    "layout(location = 2) out vec4 o_2;\n";
// The shader modules a probe includes.
inline const char* kMatrixIncl = "#include \"matrix_transform.glsl\"\n";
inline const char* kMotorIncl = "#include \"pga.glsl\"\n#include \"motor_transform.glsl\"\n";
inline const char* kAffineIncl = "#include \"affine_transform.glsl\"\n";
inline const char* kAffineJoints = "uniform mat4x3 u_j[4]; uniform float u_mirror;\n";
inline const char* kStore3 = "o_0 = v[0]; o_1 = v[1]; o_2 = v[2];";
inline const char* kQTangentAttribs =
    "layout(location = 0) in vec3 a_position; layout(location = 1) in vec4 a_qtangent;\n"
    "layout(location = 7) in vec4 a_weights;\n"
    "layout(location = 0) out vec4 o_0; layout(location = 1) out vec4 o_1;\n"
    "layout(location = 2) out vec4 o_2;\n";

inline const char* kCompactAttribs =
    "layout(location = 0) in vec3 a_position; layout(location = 1) in vec4 a_compactFrame;\n"
    "layout(location = 7) in vec4 a_weights; uniform vec4 u_dequant;\n"
    "layout(location = 0) out vec4 o_0; layout(location = 1) out vec4 o_1;\n"
    "layout(location = 2) out vec4 o_2;\n";

// Probes of the Bezier patch kernels: the control points as uniforms (the real shaders fetch
// them), the evaluated surface as vertex inputs of the frame kernels.
inline std::string patchEvalDecls() {
  return "#include \"bezier_patch.glsl\"\nuniform mat4x3 u_r[4]; layout(location = 0) in vec2 a_uv;\n"
         "layout(location = 0) out vec4 o_0; layout(location = 1) out vec4 o_1;\n"
         "layout(location = 2) out vec4 o_2;\n";
}
inline std::string patchEvalProbe() {
  return "mat3 s = bezierPatch(u_r[0], u_r[1], u_r[2], u_r[3], a_uv); o_0 = vec4(s[0], 0.0); "
         "o_1 = vec4(s[1], 0.0); o_2 = vec4(s[2], 0.0);";
}
inline std::string patchFrameDecls() {
  return "#include \"pga.glsl\"\n#include \"matrix_transform.glsl\"\n#include \"patch_transform.glsl\"\n"
         "layout(location = 0) in vec3 a_s0; layout(location = 1) in vec3 a_s1; layout(location = 2) in vec3 a_s2;\n"
         "layout(location = 0) out vec4 o_0; layout(location = 1) out vec4 o_1;\n"
         "layout(location = 2) out vec4 o_2;\n";
}

}  // namespace detail

}  // namespace mb::opsv
