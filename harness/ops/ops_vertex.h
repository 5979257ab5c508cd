// harness/ops/ops_vertex.h: ops per vertex of each pipeline, measured two ways (issue 5):
//  (a) counted: the per-vertex GLSL functions (shaders/matrix_transform.glsl,
//      shaders/motor_transform.glsl) executed once on mb::Counted through the shim;
//  (b) SPIR-V: the same function called from a small probe vertex shader, and every real
//      vertex-shader variant (matrix.vs, motor.vs with their #defines), compiled and counted by
//      harness/ops/spirv_count.h.
// The counted kernels are header-only (tests/pga/test_pga_vertex_ops.cpp counts them without GL or
// tools); the SPIR-V side and the report live in ops_vertex.cpp.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/bench/bench_shaders.h"
#include "harness/ops/spirv_count.h"
#include "shaders/shim/counted.h"
#include "shaders/shim/patch.h"
#include "shaders/shim/pga.h"
#include "shaders/shim/pga_kappa.h"

namespace mb::opsv {

// One per-vertex kernel: a GLSL function of a pipeline, run once on mb::Counted, and a probe
// vertex shader that calls the same function with per-vertex inputs and per-draw uniforms.
struct VertexKernel {
  std::string pipeline;  // "matrix", "motor", "matrix-affine" (extra baseline)
  std::string kernel;    // "rigid vertex with frame", "skinned vertex (4 joints)", ...
  std::string function;  // the GLSL function measured
  std::function<void()> run;  // executes the function once on mb::Counted
  std::string probe;     // GLSL body of the probe's main() (declarations in probeDecls)
  std::string probeDecls;
  std::string note;      // known reason a count differs, "" when none
};

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
inline const char* kStore3 = "o_0 = v[0]; o_1 = v[1]; o_2 = v[2];";
inline const char* kQTangentAttribs =
    "layout(location = 0) in vec3 a_position; layout(location = 1) in vec4 a_qtangent;\n"
    "layout(location = 7) in vec4 a_weights;\n"
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

namespace detail {
inline const char* kCurvedDecls =
    "layout(location = 0) in vec4 a_position; layout(location = 1) in vec4 a_normal;\n"
    "layout(location = 0) out vec4 o_0; layout(location = 1) out vec4 o_1;\n";
inline std::string curvedIncl(int kappa) {
  return std::string("#define MB_KAPPA ") + (kappa > 0 ? "1" : "-1") + "\n#include \"curved_transform.glsl\"\n";
}
// Matrix side: view * (instance * v) for the position and the normal.
template <int K> VertexKernel curvedMatrix(const std::string& pipeline) {
  return {pipeline, "instance vertex (pos + normal)", "curvedMatrixVertex",
          [] {
            using P = PgaK<Counted, K>;
            static const typename P::mat4 m(Counted(0.5));
            static const typename P::vec4 p(0.1, 0.2, 0.3, 0.9), n(0.3, 0.2, 0.1, 0.0);
            pgaK<Counted, K>.curvedMatrixVertex(m, m, p, n);
          },
          "mat2x4 v = curvedMatrixVertex(u_view, a_instance, a_position, a_normal); o_0 = v[0]; "
          "o_1 = v[1];",
          curvedIncl(K) + kCurvedDecls + "uniform mat4 u_view; layout(location = 2) in mat4 a_instance;\n",
          "two mat4 * vec4 per vector"};
}
// Motor side: one product (S3: pairs, H3: motors) and two sandwiches.
template <int K> VertexKernel curvedMotor(const std::string& pipeline) {
  return {pipeline, "instance vertex (pos + normal)", "curvedMotorVertex",
          [] {
            using P = PgaK<Counted, K>;
            static const typename P::motor a(typename P::vec4(0.5, 0.1, 0.2, 0.3),
                                             typename P::vec4(0.4, 0.5, 0.6, 0.7));
            static const typename P::vec4 p(0.1, 0.2, 0.3, 0.9), n(0.3, 0.2, 0.1, 0.0);
            pgaK<Counted, K>.curvedMotorVertex(a, a, p, n);
          },
          "mat2x4 v = curvedMotorVertex(mat2x4(u_camera[0], u_camera[1]), mat2x4(a_i0, a_i1), "
          "a_position, a_normal); o_0 = v[0]; o_1 = v[1];",
          curvedIncl(K) + kCurvedDecls +
              "uniform vec4 u_camera[2]; layout(location = 2) in vec4 a_i0; "
              "layout(location = 3) in vec4 a_i1;\n",
          K > 0 ? "gp_pair + 2 sw_pair" : "gp_mm_k + 2 sw_mp_k"};
}
}  // namespace detail

// The per-vertex kernels of every pipeline, in report order.
inline std::vector<VertexKernel> vertexKernels() {
  using namespace detail;
  static const VertexInputs& in = inputs();  // static: the lambdas outlive this call
  static MC M;
  static AC A;
  static PC P;
  static TC T;
  const std::string matrixIncl = "#include \"matrix_transform.glsl\"\n";
  const std::string motorIncl = "#include \"pga.glsl\"\n#include \"motor_transform.glsl\"\n";
  const std::string affineIncl = "#include \"affine_transform.glsl\"\n";
  const std::string affineJoints = "uniform mat4x3 u_j[4]; uniform float u_mirror;\n";
  const auto& aj = in.affineJoints;
  const auto& an = in.affineNormals;
  const std::string store = kStore3;
  return {
      {"matrix", "rigid vertex with frame", "matrixRigidVertex",
       [&] { M.matrixRigidVertex(in.model, in.normal, in.position, in.normalV, in.tangent); },
       "mat3x4 v = matrixRigidVertex(u_model, u_normal, a_position, a_normal, a_tangent);" + store,
       matrixIncl + kMatrixAttribs + "uniform mat4 u_model; uniform mat4 u_normal;\n",
       "paper 48/36: the three mat4 * vec4 (matrixTransformFrame); +1 mul: handedness of "
       "mirrored nodes (w * sign(det))"},
      {"matrix", "skinned vertex (4 joints)", "matrixSkinnedVertex",
       [&] {
         M.matrixSkinnedVertex(in.j[0], in.j[1], in.j[2], in.j[3], in.n[0], in.n[1], in.n[2],
                               in.n[3], in.weights, in.model, in.normal, in.position,
                               in.normalV, in.tangent);
       },
       "mat3x4 v = matrixSkinnedVertex(u_j[0], u_j[1], u_j[2], u_j[3], u_n[0], u_n[1], u_n[2], "
       "u_n[3], a_weights, u_model, u_normal, a_position, a_normal, a_tangent);" + store,
       matrixIncl + kMatrixAttribs +
           "uniform mat4 u_model; uniform mat4 u_normal; uniform mat4 u_j[4]; uniform mat4 u_n[4];\n",
       ""},
      {"matrix", "skinned vertex, world palette", "matrixSkinnedVertexWorld",
       [&] {
         M.matrixSkinnedVertexWorld(in.j[0], in.j[1], in.j[2], in.j[3], in.n[0], in.n[1],
                                    in.n[2], in.n[3], in.weights, in.normal, in.position,
                                    in.normalV, in.tangent);
       },
       "mat3x4 v = matrixSkinnedVertexWorld(u_j[0], u_j[1], u_j[2], u_j[3], u_n[0], u_n[1], "
       "u_n[2], u_n[3], a_weights, u_normal, a_position, a_normal, a_tangent);" + store,
       matrixIncl + kMatrixAttribs +
           "uniform mat4 u_normal; uniform mat4 u_j[4]; uniform mat4 u_n[4];\n",
       "palette in world space: no model matrix after the skin (neither reference does this)"},
      {"matrix", "rigid vertex, no tangent", "matrixRigidVertexNoTangent",
       [&] { M.matrixRigidVertexNoTangent(in.model, in.normal, in.position, in.normalV); },
       "mat3x4 v = matrixRigidVertexNoTangent(u_model, u_normal, a_position, a_normal);" + store,
       matrixIncl + kMatrixAttribs + "uniform mat4 u_model; uniform mat4 u_normal;\n",
       "no TANGENT and no normal map: the Sample Viewer's shader has no tangent input"},
      {"matrix", "skinned vertex, no tangent", "matrixSkinnedVertexNoTangent",
       [&] {
         M.matrixSkinnedVertexNoTangent(in.j[0], in.j[1], in.j[2], in.j[3], in.n[0], in.n[1],
                                        in.n[2], in.n[3], in.weights, in.model, in.normal,
                                        in.position, in.normalV);
       },
       "mat3x4 v = matrixSkinnedVertexNoTangent(u_j[0], u_j[1], u_j[2], u_j[3], u_n[0], u_n[1], "
       "u_n[2], u_n[3], a_weights, u_model, u_normal, a_position, a_normal);" + store,
       matrixIncl + kMatrixAttribs +
           "uniform mat4 u_model; uniform mat4 u_normal; uniform mat4 u_j[4]; uniform mat4 u_n[4];\n",
       ""},
      {"matrix", "skinned, world palette, no tangent", "matrixSkinnedVertexWorldNoTangent",
       [&] {
         M.matrixSkinnedVertexWorldNoTangent(in.j[0], in.j[1], in.j[2], in.j[3], in.n[0],
                                             in.n[1], in.n[2], in.n[3], in.weights,
                                             in.position, in.normalV);
       },
       "mat3x4 v = matrixSkinnedVertexWorldNoTangent(u_j[0], u_j[1], u_j[2], u_j[3], u_n[0], "
       "u_n[1], u_n[2], u_n[3], a_weights, a_position, a_normal);" + store,
       matrixIncl + kMatrixAttribs + "uniform mat4 u_j[4]; uniform mat4 u_n[4];\n", ""},
      {"matrix", "joint blend (4 joints)", "matrixBlendJoints",
       [&] { M.matrixBlendJoints(in.j[0], in.j[1], in.j[2], in.j[3], in.weights); },
       "mat4 m = matrixBlendJoints(u_j[0], u_j[1], u_j[2], u_j[3], a_weights); o_0 = m[0]; "
       "o_1 = m[1]; o_2 = m[2]; gl_Position = m[3];",
       matrixIncl + kMatrixAttribs + "uniform mat4 u_j[4];\n",
       "part of the skinned vertex, twice: joint matrices and joint normal matrices"},
      {"matrix", "world to clip", "matrixWorldToClip",
       [&] { M.matrixWorldToClip(in.viewProj, in.world); },
       "gl_Position = matrixWorldToClip(u_viewProj, a_world);",
       matrixIncl + "uniform mat4 u_viewProj; layout(location = 0) in vec4 a_world;\n", ""},
      {"matrix-affine", "rigid vertex with frame", "matrixAffineVertex",
       [&] {
         M.matrixAffineVertex(in.affine, in.affineNormal, 1.0, in.position, in.normalV, in.tangent);
       },
       "mat3x4 v = matrixAffineVertex(u_model, u_normal, u_mirror, a_position, a_normal, "
       "a_tangent);" + store,
       matrixIncl + kMatrixAttribs +
           "uniform mat4x3 u_model; uniform mat3 u_normal; uniform float u_mirror;\n",
       ""},
      {"affine", "skinned vertex (4 joints)", "affineSkinnedVertex",
       [&] {
         A.affineSkinnedVertex(aj[0], aj[1], aj[2], aj[3], in.weights, 1.0, in.position,
                               in.normalV, in.tangent);
       },
       "mat3x4 v = affineSkinnedVertex(u_j[0], u_j[1], u_j[2], u_j[3], a_weights, u_mirror, "
       "a_position, a_normal, a_tangent);" + store,
       affineIncl + kMatrixAttribs + affineJoints,
       "mat4x3 per joint (joint world * inverse bind, no model matrix after); normal through the "
       "cofactor of the blended matrix (18 mul, 9 add), cheaper than blending a mat3 normal "
       "matrix per joint (affineSkinnedNormalsVertex)"},
      {"affine", "joint blend (4 joints)", "affineBlendJoints",
       [&] { A.affineBlendJoints(aj[0], aj[1], aj[2], aj[3], in.weights); },
       "mat4x3 m = affineBlendJoints(u_j[0], u_j[1], u_j[2], u_j[3], a_weights); "
       "o_0 = vec4(m[0], m[1].x); o_1 = vec4(m[1].yz, m[2].xy); o_2 = vec4(m[2].z, m[3]);",
       affineIncl + kMatrixAttribs + affineJoints, "part of the skinned vertex"},
      {"affine", "rigid vertex, cofactor normal (alternative)", "affineAdjugateVertex",
       [&] { A.affineAdjugateVertex(in.affine, 1.0, in.position, in.normalV, in.tangent); },
       "mat3x4 v = affineAdjugateVertex(u_model, u_mirror, a_position, a_normal, a_tangent);" + store,
       affineIncl + kMatrixAttribs + "uniform mat4x3 u_model; uniform float u_mirror;\n",
       "not used: 12 floats per draw instead of 21, but 18 mul / 9 add more per vertex than the "
       "uploaded mat3 of matrixAffineVertex"},
      {"affine", "skinned, mat3 normal per joint (alternative)", "affineSkinnedNormalsVertex",
       [&] {
         A.affineSkinnedNormalsVertex(aj[0], aj[1], aj[2], aj[3], an[0], an[1], an[2], an[3],
                                      in.weights, 1.0, in.position, in.normalV, in.tangent);
       },
       "mat3x4 v = affineSkinnedNormalsVertex(u_j[0], u_j[1], u_j[2], u_j[3], u_n[0], u_n[1], "
       "u_n[2], u_n[3], a_weights, u_mirror, a_position, a_normal, a_tangent);" + store,
       affineIncl + kMatrixAttribs + affineJoints + "uniform mat3 u_n[4];\n",
       "not used: 21 floats per joint and more ops than the cofactor of affineSkinnedVertex"},
      {"qtangent", "frame decode (int16 quaternion)", "qtangentFrame",
       [&] { A.qtangentFrame(in.qtangent); },
       "mat2x4 f = qtangentFrame(a_qtangent); o_0 = f[0]; o_1 = f[1];",
       affineIncl + kQTangentAttribs, "normal and tangent columns of the quaternion's rotation"},
      {"qtangent", "rigid vertex with frame", "qtangentRigidVertex",
       [&] { A.qtangentRigidVertex(in.affine, in.affineNormal, 1.0, in.position, in.qtangent); },
       "mat3x4 v = qtangentRigidVertex(u_model, u_normal, u_mirror, a_position, a_qtangent);" + store,
       affineIncl + kQTangentAttribs +
           "uniform mat4x3 u_model; uniform mat3 u_normal; uniform float u_mirror;\n",
       "qtangentFrame + matrixAffineVertex"},
      {"qtangent", "skinned vertex (4 joints)", "qtangentSkinnedVertex",
       [&] {
         A.qtangentSkinnedVertex(aj[0], aj[1], aj[2], aj[3], in.weights, 1.0, in.position,
                                 in.qtangent);
       },
       "mat3x4 v = qtangentSkinnedVertex(u_j[0], u_j[1], u_j[2], u_j[3], a_weights, u_mirror, "
       "a_position, a_qtangent);" + store,
       affineIncl + kQTangentAttribs + affineJoints, "qtangentFrame + affineSkinnedVertex"},
      {"motor", "rigid vertex with frame", "motorRigidVertex",
       [&] { P.motorRigidVertex(in.toWorld, 1.25, in.position, in.rotor); },
       "mat3x4 v = motorRigidVertex(motor(u_world[0], u_world[1]), u_scale, a_position, "
       "a_tangentRotor);" + store,
       motorIncl + kMotorAttribs + "uniform vec4 u_world[2]; uniform float u_scale;\n",
       "paper 47/38 = sw_mp 21/18 + gp_rr 16/12 + extractNormalTangent 9/8 + 1 mul handedness; "
       "here +3 mul: the uniform scale of the position, and the handedness is sign(1/x) "
       "(1 div, 1 other: IEEE signed zero) instead of 1 mul"},
      {"motor", "skinned vertex (4 joints)", "motorSkinnedVertex",
       [&] {
         P.motorSkinnedVertex(in.joints[0], in.joints[1], in.joints[2], in.joints[3],
                              PC::vec4(0.4, 0.3, 0.2, 0.1), 1.25, in.position, in.rotor);
       },
       "mat3x4 v = motorSkinnedVertex(motor(u_j[0], u_j[1]), motor(u_j[2], u_j[3]), "
       "motor(u_j[4], u_j[5]), motor(u_j[6], u_j[7]), a_weights, u_scale, a_position, "
       "a_tangentRotor);" + store,
       motorIncl + kMotorAttribs + "uniform vec4 u_j[8]; uniform float u_scale;\n", ""},
      {"motor", "skinned vertex, reference", "motorSkinnedVertexReference",
       [&] {
         P.motorSkinnedVertexReference(in.toWorld, in.joints[0], in.joints[1], in.joints[2],
                                       in.joints[3], PC::vec4(0.4, 0.3, 0.2, 0.1), 1.25,
                                       in.position, in.rotor);
       },
       "mat3x4 v = motorSkinnedVertexReference(motor(u_world[0], u_world[1]), "
       "motor(u_j[0], u_j[1]), motor(u_j[2], u_j[3]), motor(u_j[4], u_j[5]), "
       "motor(u_j[6], u_j[7]), a_weights, u_scale, a_position, a_tangentRotor);" + store,
       motorIncl + kMotorAttribs + "uniform vec4 u_world[2]; uniform vec4 u_j[8]; uniform float u_scale;\n",
       "the paper's form: palette relative to the mesh node, toWorld = gp(toWorld, blend) per vertex"},
      {"motor", "joint blend (4 joints)", "motorBlendJoints",
       [&] {
         P.motorBlendJoints(in.joints[0], in.joints[1], in.joints[2], in.joints[3],
                            PC::vec4(0.4, 0.3, 0.2, 0.1));
       },
       "motor m = motorBlendJoints(motor(u_j[0], u_j[1]), motor(u_j[2], u_j[3]), "
       "motor(u_j[4], u_j[5]), motor(u_j[6], u_j[7]), a_weights); o_0 = m[0]; o_1 = m[1];",
       motorIncl + kMotorAttribs + "uniform vec4 u_j[8];\n",
       "part of the skinned vertex: shortest-arc blend + normalize_m"},
      {"motor", "world to clip", "motorWorldToClip",
       [&] {
         P.motorWorldToClip(in.camera, PC::vec3(1.5, 0.25, -3.0), 0.05, 100.0, 0.8, 1.5);
       },
       "gl_Position = motorWorldToClip(motor(u_camera[0], u_camera[1]), a_world, "
       "u_projection.x, u_projection.y, u_projection.z, u_projection.w);",
       motorIncl + "uniform vec4 u_camera[2]; uniform vec4 u_projection;\n"
                   "layout(location = 0) in vec3 a_world;\n",
       "project() recomputes its per-draw constants (cot of half the fov, depth terms: 6 mul, "
       "3 add, 4 div, 1 sin, 1 cos) per vertex, in the shim and in the SPIR-V alike; per "
       "vertex proper: sw_mp + 3 mul, 1 add"},
      {"motor_q", "world to clip (per-frame constants)", "motorWorldToClipConstants",
       [&] {
         P.motorWorldToClipConstants(in.camera, PC::vec3(1.5, 0.25, -3.0),
                                     PC::vec4(-1.2, 1.8, -0.1, -1.001));
       },
       "gl_Position = motorWorldToClipConstants(motor(u_camera[0], u_camera[1]), a_world, u_k);",
       motorIncl + "uniform vec4 u_camera[2]; uniform vec4 u_k;\n"
                   "layout(location = 0) in vec3 a_world;\n",
       "project() with its constants computed once per frame (motorProjectionConstants) as the "
       "matrix side builds its projection matrix once per frame"},
      // Bezier patches (issue 14): the evaluation both patch shaders share, then each frame.
      {"matrix", "patch: bicubic evaluation (P, dP/du, dP/dv)", "bezierPatch",
       [&] { T.bezierPatch(in.rows[0], in.rows[1], in.rows[2], in.rows[3], in.uv); },
       patchEvalProbe(), patchEvalDecls(),
       "shared by matrix_patch.vs and motor_patch.vs (the 16 control points come from texelFetch, "
       "no arithmetic)"},
      {"matrix", "patch frame (normal = dP/du x dP/dv)", "matrixPatchVertex",
       [&] { T.matrixPatchVertex(in.model, in.normal, in.surface); },
       "mat3x4 v = matrixPatchVertex(u_model, u_normal, mat3(a_s0, a_s1, a_s2));" + store,
       patchFrameDecls() + "uniform mat4 u_model; uniform mat4 u_normal;\n",
       "cross 6/3 + the Sample Viewer's three mat4 * vec4 48/36 + handedness 1/0"},
      {"motor", "patch: bicubic evaluation (P, dP/du, dP/dv)", "bezierPatch",
       [&] { T.bezierPatch(in.rows[0], in.rows[1], in.rows[2], in.rows[3], in.uv); },
       patchEvalProbe(), patchEvalDecls(), "the same evaluation as the matrix pipeline's"},
      {"motor", "patch frame (a): derivatives sandwiched, crossed", "motorPatchVertex",
       [&] { T.motorPatchVertex(in.toWorld, 1.25, in.surface); },
       "mat3x4 v = motorPatchVertex(motor(u_world[0], u_world[1]), u_scale, mat3(a_s0, a_s1, a_s2));" + store,
       patchFrameDecls() + "uniform vec4 u_world[2]; uniform float u_scale;\n",
       "drawn: sw_mp 21/18 + scale 3/0, two sw_md 36/24, cross 6/3"},
      {"motor (b)", "patch frame (b): tangent rotor + gp_rr (not drawn)", "motorPatchVertexRotor",
       [&] { T.motorPatchVertexRotor(in.toWorld, 1.25, in.surface); },
       "mat3x4 v = motorPatchVertexRotor(motor(u_world[0], u_world[1]), u_scale, mat3(a_s0, a_s1, a_s2));" + store,
       patchFrameDecls() + "uniform vec4 u_world[2]; uniform float u_scale;\n",
       "the alternative, counted and not drawn: two normalisations, the rotor of the frame "
       "(branches: Shepperd), gp_rr, extractNormalTangent"},
      {"motor", "patch frame (a), scaled fallback", "motorScaledPatchVertex",
       [&] { T.motorScaledPatchVertex(in.toWorld, TC::vec3(1.0, -2.0, 0.5), in.surface); },
       "mat3x4 v = motorScaledPatchVertex(motor(u_world[0], u_world[1]), u_scale3, mat3(a_s0, a_s1, a_s2));" + store,
       patchFrameDecls() + "uniform vec4 u_world[2]; uniform vec3 u_scale3;\n", ""},
      {"motor", "scaled vertex (fallback)", "motorScaledVertex",
       [&] { P.motorScaledVertex(in.toWorld, PC::vec3(1.0, -2.0, 0.5), in.position, in.rotor); },
       "mat3x4 v = motorScaledVertex(motor(u_world[0], u_world[1]), u_scale3, a_position, "
       "a_tangentRotor);" + store,
       motorIncl + kMotorAttribs + "uniform vec4 u_world[2]; uniform vec3 u_scale3;\n", ""},
      // Curved space (issue 15): shaders/curved_transform.glsl, position and normal.
      curvedMatrix<1>("s3_matrix"), curvedMotor<1>("s3_motor"),
      curvedMatrix<-1>("h3_matrix"), curvedMotor<-1>("h3_motor"),
  };
}

// The counted ops of one kernel.
inline OpCounts countVertexKernel(const VertexKernel& k) { return countOps(k.run); }

// One real vertex-shader variant and the kernels whose counted sum it is compared with.
struct ShaderVariant {
  std::string pipeline;  // "matrix", "motor"
  std::string file;      // relative to the shader folder
  std::vector<std::pair<std::string, std::string>> defines;
  std::string label;     // "rigid", "skinned", ...
  std::vector<std::string> kernels;  // VertexKernel::function names the variant's main() calls
  std::string note = "";             // what main() does besides those kernels, "" when nothing
};

// Labels: "rigid", "skinned", "scaled fallback" are what each pipeline draws by default (the
// report weights them by its vertex mix). The skinned configurations of issue 18 are counted
// side by side for both pipelines: "skinned, reference" (as the references do: the node's
// transform after the blend) and "skinned, world palette" (neither reference); the matrix
// default "skinned" is the former, the motor default the latter. "..., no tangent": the
// matrix variants without a tangent attribute (primitives without TANGENT or normal map).
inline std::vector<ShaderVariant> shaderVariants() {
  const std::string matrixMain =
      "main() divides the position by w and normalises normal and tangent for the varyings "
      "(motor.vs leaves normalisation to forward.fs, which normalises both anyway)";
  const std::string curvedMain =
      "main() adds the projection u_Projection * position (mat4 * vec4: 16 mul, 12 add), the "
      "same on both sides of a space";
  const std::string ref = "the Sample Viewer's: skin, then u_ModelMatrix per vertex";
  const std::string world = "joint world * inverse bind; no model matrix per vertex";
  const std::string instanced = "the per-draw transform read from per-instance attributes (divisor 1)";
  using D = std::vector<std::pair<std::string, std::string>>;
  const std::string affineMain =
      "main() normalises normal and tangent for the varyings, as matrix.vs (the position's w is "
      "1: no divide)";
  return {
      {"matrix", "matrix.vs", {}, "rigid", {"matrixRigidVertex", "matrixWorldToClip"}, matrixMain},
      {"matrix", "matrix.vs", {{"SKINNED", ""}}, "skinned", {"matrixSkinnedVertex", "matrixWorldToClip"},
       matrixMain + "; = skinned, reference"},
      {"matrix", "matrix.vs", {{"SKINNED", ""}}, "skinned, reference",
       {"matrixSkinnedVertex", "matrixWorldToClip"}, ref},
      {"matrix", "matrix.vs", D{{"SKINNED", ""}, {"MB_WORLD_PALETTE", ""}}, "skinned, world palette",
       {"matrixSkinnedVertexWorld", "matrixWorldToClip"}, world},
      {"matrix", "matrix.vs", D{{"MB_NO_TANGENT", ""}}, "rigid, no tangent",
       {"matrixRigidVertexNoTangent", "matrixWorldToClip"}},
      {"matrix", "matrix.vs", D{{"SKINNED", ""}, {"MB_NO_TANGENT", ""}}, "skinned, no tangent",
       {"matrixSkinnedVertexNoTangent", "matrixWorldToClip"}, ref},
      {"matrix", "matrix.vs", D{{"SKINNED", ""}, {"MB_WORLD_PALETTE", ""}, {"MB_NO_TANGENT", ""}},
       "skinned, world palette, no tangent", {"matrixSkinnedVertexWorldNoTangent", "matrixWorldToClip"},
       world},
      {"motor", "motor.vs", {}, "rigid", {"motorRigidVertex", "motorWorldToClip"}},
      {"motor", "motor.vs", {{"MB_SKINNED", ""}}, "skinned", {"motorSkinnedVertex", "motorWorldToClip"},
       "= skinned, world palette"},
      {"motor", "motor.vs", D{{"MB_SKINNED", ""}, {"MB_SKIN_REFERENCE", ""}}, "skinned, reference",
       {"motorSkinnedVertexReference", "motorWorldToClip"},
       "the paper's: gp(toWorld, blend) per vertex"},
      {"motor", "motor.vs", {{"MB_SKINNED", ""}}, "skinned, world palette",
       {"motorSkinnedVertex", "motorWorldToClip"}, "joint world * inverse bind motors"},
      {"motor", "motor.vs", {{"MB_SCALE_FALLBACK", ""}}, "scaled fallback",
       {"motorScaledVertex", "motorWorldToClip"}},
      {"motor", "motor.vs", D{{"MB_SKINNED", ""}, {"MB_SCALE_FALLBACK", ""}}, "skinned+scaled",
       {"motorBlendJoints", "motorScaledVertex", "motorWorldToClip"}},
      {"affine", "affine.vs", {}, "rigid", {"matrixAffineVertex", "matrixWorldToClip"}, affineMain},
      {"affine", "affine.vs", {{"MB_SKINNED", ""}}, "skinned",
       {"affineSkinnedVertex", "matrixWorldToClip"}, affineMain},
      {"qtangent", "affine.vs", {{"MB_QTANGENT", ""}}, "rigid",
       {"qtangentRigidVertex", "matrixWorldToClip"}, affineMain},
      {"qtangent", "affine.vs", {{"MB_QTANGENT", ""}, {"MB_SKINNED", ""}}, "skinned",
       {"qtangentSkinnedVertex", "matrixWorldToClip"}, affineMain},
      {"hybrid", "affine.vs", {{"MB_QTANGENT", ""}}, "rigid",
       {"qtangentRigidVertex", "matrixWorldToClip"}, affineMain + "; the GPU side of qtangent"},
      {"hybrid", "affine.vs", {{"MB_QTANGENT", ""}, {"MB_SKINNED", ""}}, "skinned",
       {"qtangentSkinnedVertex", "matrixWorldToClip"}, affineMain + "; the GPU side of qtangent"},
      {"motor_q", "motor.vs", {{"MB_PROJECT_CONSTANTS", ""}}, "rigid",
       {"motorRigidVertex", "motorWorldToClipConstants"}},
      {"motor_q", "motor.vs", {{"MB_SKINNED", ""}, {"MB_PROJECT_CONSTANTS", ""}}, "skinned",
       {"motorSkinnedVertex", "motorWorldToClipConstants"}},
      {"motor_q", "motor.vs", {{"MB_SCALE_FALLBACK", ""}, {"MB_PROJECT_CONSTANTS", ""}},
       "scaled fallback", {"motorScaledVertex", "motorWorldToClipConstants"}},
      {"motor_q", "motor.vs",
       {{"MB_SKINNED", ""}, {"MB_SCALE_FALLBACK", ""}, {"MB_PROJECT_CONSTANTS", ""}},
       "skinned+scaled", {"motorBlendJoints", "motorScaledVertex", "motorWorldToClipConstants"}},
      // Instanced draws (EXT_mesh_gpu_instancing, --instances): the rigid transform with its
      // per-draw data read from per-instance attributes; the same arithmetic as "rigid".
      {"matrix", "matrix.vs", {{"MB_INSTANCED", ""}}, "rigid, instanced",
       {"matrixRigidVertex", "matrixWorldToClip"}, matrixMain + "; " + instanced},
      {"matrix", "matrix.vs", D{{"MB_INSTANCED", ""}, {"MB_NO_TANGENT", ""}}, "rigid, no tangent, instanced",
       {"matrixRigidVertexNoTangent", "matrixWorldToClip"}, instanced},
      {"affine", "affine.vs", {{"MB_INSTANCED", ""}}, "rigid, instanced",
       {"matrixAffineVertex", "matrixWorldToClip"}, affineMain + "; " + instanced},
      {"qtangent", "affine.vs", D{{"MB_QTANGENT", ""}, {"MB_INSTANCED", ""}}, "rigid, instanced",
       {"qtangentRigidVertex", "matrixWorldToClip"}, affineMain + "; " + instanced},
      {"hybrid", "affine.vs", D{{"MB_QTANGENT", ""}, {"MB_INSTANCED", ""}}, "rigid, instanced",
       {"qtangentRigidVertex", "matrixWorldToClip"}, affineMain + "; " + instanced},
      {"motor", "motor.vs", {{"MB_INSTANCED", ""}}, "rigid, instanced",
       {"motorRigidVertex", "motorWorldToClip"}, instanced},
      {"motor", "motor.vs", D{{"MB_INSTANCED", ""}, {"MB_SCALE_FALLBACK", ""}}, "scaled fallback, instanced",
       {"motorScaledVertex", "motorWorldToClip"}, instanced},
      {"motor_q", "motor.vs", D{{"MB_INSTANCED", ""}, {"MB_PROJECT_CONSTANTS", ""}}, "rigid, instanced",
       {"motorRigidVertex", "motorWorldToClipConstants"}, instanced},
      {"motor_q", "motor.vs", D{{"MB_INSTANCED", ""}, {"MB_SCALE_FALLBACK", ""}, {"MB_PROJECT_CONSTANTS", ""}},
       "scaled fallback, instanced", {"motorScaledVertex", "motorWorldToClipConstants"}, instanced},
      {"s3_matrix", "curved_matrix.vs", {{"MB_KAPPA", "1"}}, "S3 instance", {"curvedMatrixVertex"}, curvedMain},
      {"s3_motor", "curved_motor.vs", {{"MB_KAPPA", "1"}}, "S3 instance", {"curvedMotorVertex"}, curvedMain},
      {"h3_matrix", "curved_matrix.vs", {{"MB_KAPPA", "-1"}}, "H3 instance", {"curvedMatrixVertex"}, curvedMain},
      {"h3_motor", "curved_motor.vs", {{"MB_KAPPA", "-1"}}, "H3 instance", {"curvedMotorVertex"}, curvedMain},
      {"matrix", "matrix_patch.vs", {}, "bezier patch", {"bezierPatch", "matrixPatchVertex", "matrixWorldToClip"},
       matrixMain + "; the 16 control points are texelFetch (no arithmetic)"},
      {"motor", "motor_patch.vs", {}, "bezier patch", {"bezierPatch", "motorPatchVertex", "motorWorldToClip"},
       "the 16 control points are texelFetch (no arithmetic)"},
      {"motor", "motor_patch.vs", {{"MB_SCALE_FALLBACK", ""}}, "bezier patch, scaled fallback",
       {"bezierPatch", "motorScaledPatchVertex", "motorWorldToClip"}, "the 16 control points are texelFetch"},
  };
}

// ---- measurement and report (ops_vertex.cpp) ------------------------------------------------

struct KernelRow {
  VertexKernel kernel;
  OpCounts counted;
  // The probe after inlining only, after -O without instruction folding, after spirv-opt -O.
  std::optional<spirv::Counts> inlined, noFold, optimised;
  std::string error;  // why the SPIR-V side is missing
  std::string why;    // "" when counted and optimised SPIR-V agree
};

struct VariantRow {
  ShaderVariant variant;
  OpCounts counted;                       // sum of the counted kernels it calls
  std::optional<spirv::Counts> probes;    // sum of those kernels' optimised probes
  std::optional<spirv::Counts> shader;    // the whole variant, spirv-opt -O
  std::string error, why;
};

struct VertexOps {
  std::vector<KernelRow> kernels;
  std::vector<VariantRow> variants;
  std::string toolsProblem;  // non-empty: no SPIR-V column
};

// Counts every kernel and, when the tools run, compiles every probe and variant.
VertexOps measureVertexOps();
std::string formatVertexOps(const VertexOps& ops);
nlohmann::json toJson(const VertexOps& ops);

}  // namespace mb::opsv
