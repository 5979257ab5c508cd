// The counted per-vertex kernels of the matrix forms: matrix.vs (the Sample Viewer's mat4s) and
// affine.vs (mat4x3 + mat3, float frame, int16 quaternion, or matrix_c's 4-byte frame).
#include "harness/ops/vertex_inputs.h"
#include "harness/ops/vertex_kernels.h"

namespace mb::opsv::detail {

namespace {

// The counting shaders every kernel below runs (one instance each; static: the kernels'
// lambdas outlive the calls that list them).
MC& matrixShader() {
  static MC M;
  return M;
}

AC& affineShader() {
  static AC A;
  return A;
}

// matrix.vs: the Sample Viewer's mat4 forms, rigid and skinned, with and without tangent; the
// joint blend; world to clip.
std::vector<VertexKernel> matrixFormKernels() {
  static const VertexInputs& in = inputs();  // static: the lambdas outlive this call
  static MC& M = matrixShader();
  const std::string matrixIncl = kMatrixIncl;
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
  };
}

// affine.vs: mat4x3 + mat3 forms (the float frame), and the two alternatives not drawn.
std::vector<VertexKernel> affineKernels() {
  static const VertexInputs& in = inputs();  // static: the lambdas outlive this call
  static MC& M = matrixShader();
  static AC& A = affineShader();
  const auto& aj = in.affineJoints;
  const auto& an = in.affineNormals;
  const std::string matrixIncl = kMatrixIncl, affineIncl = kAffineIncl, affineJoints = kAffineJoints;
  const std::string store = kStore3;
  return {
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
      {"affine", "rigid vertex, no tangent", "affineVertexNoTangent",
       [&] { A.affineVertexNoTangent(in.affine, in.affineNormal, in.position, in.normalV); },
       "mat3x4 v = affineVertexNoTangent(u_model, u_normal, a_position, a_normal);" + store,
       affineIncl + kMatrixAttribs + "uniform mat4x3 u_model; uniform mat3 u_normal;\n",
       "no TANGENT and no normal map: position 9/9 + normal 9/6, as matrix.vs's MB_NO_TANGENT"},
      {"affine", "skinned vertex, no tangent", "affineSkinnedVertexNoTangent",
       [&] {
         A.affineSkinnedVertexNoTangent(aj[0], aj[1], aj[2], aj[3], in.weights, in.position, in.normalV);
       },
       "mat3x4 v = affineSkinnedVertexNoTangent(u_j[0], u_j[1], u_j[2], u_j[3], a_weights, a_position, "
       "a_normal);" + store,
       affineIncl + kMatrixAttribs + affineJoints, "blend 48/36 + cofactor 18/9 + position and normal 18/15"},
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
  };
}

// qtangent: the int16 quaternion frame and the vertices that read it.
std::vector<VertexKernel> qtangentKernels() {
  static const VertexInputs& in = inputs();  // static: the lambdas outlive this call
  static AC& A = affineShader();
  const auto& aj = in.affineJoints;
  const std::string affineIncl = kAffineIncl, affineJoints = kAffineJoints;
  const std::string store = kStore3;
  return {
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
  };
}

// matrix_c: the int16 position, the 4-byte frame and the vertices that read it.
std::vector<VertexKernel> compactMatrixKernels() {
  static const VertexInputs& in = inputs();  // static: the lambdas outlive this call
  static AC& A = affineShader();
  const auto& aj = in.affineJoints;
  const std::string affineIncl = kAffineIncl, affineJoints = kAffineJoints;
  const std::string store = kStore3;
  return {
      {"matrix_c, motor_c", "position dequantisation (skinned, instanced)", "compactPosition",
       [&] { A.compactPosition(in.position, in.dequant); },
       "o_0 = vec4(compactPosition(a_position, u_dequant), 1.0);", affineIncl + kCompactAttribs,
       "int16 position in the mesh's cube; rigid draws fold it into their transform (0 per vertex)"},
      {"matrix_c", "frame decode (4 bytes)", "compactMatrixFrame",
       [&] { A.compactMatrixFrame(in.compactMatrixFrame); },
       "mat2x4 f = compactMatrixFrame(a_compactFrame); o_0 = f[0]; o_1 = f[1];",
       affineIncl + kCompactAttribs,
       "octahedral normal (normalised), Duff et al. tangent basis, diamond tangent (unnormalised)"},
      {"matrix_c", "rigid vertex with frame", "compactRigidVertex",
       [&] { A.compactRigidVertex(in.affine, in.affineNormal, 1.0, in.position, in.compactMatrixFrame); },
       "mat3x4 v = compactRigidVertex(u_model, u_normal, u_mirror, a_position, a_compactFrame);" + store,
       affineIncl + kCompactAttribs + "uniform mat4x3 u_model; uniform mat3 u_normal; uniform float u_mirror;\n",
       "compactMatrixFrame + matrixAffineVertex"},
      {"matrix_c", "skinned vertex (4 joints)", "compactSkinnedVertex",
       [&] {
         A.compactSkinnedVertex(aj[0], aj[1], aj[2], aj[3], in.weights, 1.0, in.position, in.dequant,
                                in.compactMatrixFrame);
       },
       "mat3x4 v = compactSkinnedVertex(u_j[0], u_j[1], u_j[2], u_j[3], a_weights, u_mirror, "
       "a_position, u_dequant, a_compactFrame);" + store,
       affineIncl + kCompactAttribs + affineJoints, "compactMatrixFrame + compactPosition + affineSkinnedVertex"},
  };
}

}  // namespace

std::vector<VertexKernel> matrixKernels() {
  std::vector<VertexKernel> all;
  for (auto group : {matrixFormKernels, affineKernels, qtangentKernels, compactMatrixKernels})
    for (VertexKernel& k : group()) all.push_back(std::move(k));
  return all;
}

}  // namespace mb::opsv::detail
