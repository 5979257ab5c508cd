// affine_transform.glsl: the per-vertex transform of the production matrix pipelines
// (pipelines/matrix: `affine`, `qtangent`, `hybrid`), in the GLSL subset of shaders/shim/glsl.h
// so that shaders/affine.vs, `motorbench ops` and the CPU tests run the same source.
// Transforms are affine: GLSL mat4x3 (4 columns of 3 rows, 12 floats); the rigid vertex is
// matrix_transform.glsl's matrixAffineVertex (model mat4x3 + normal mat3 + mirror factor).
// Returned vertices use matrix_transform.glsl's mat3x4 layout ([0] position with w = 1,
// [1].xyz normal, [2].xyz tangent, [2].w handedness).

#ifndef MB_AFFINE_TRANSFORM_GLSL
#define MB_AFFINE_TRANSFORM_GLSL

#include "matrix_transform.glsl"
#include "compact_frame.glsl"

// Cofactor matrix of a 3x3 linear map: det(m) * transpose(inverse(m)), whose columns are the
// cross products of m's columns. It maps normals as the normal matrix does, up to the factor
// det(m) (> 0 for the joints of a skin; the fragment shader normalises).
// counted: 18 mul, 9 add
mat3 affineCofactor(mat3 m) { return mat3(cross(m[1], m[2]), cross(m[2], m[0]), cross(m[0], m[1])); }

// Rigid vertex, the alternative to an uploaded normal matrix: the cofactor computed per vertex
// from the model (12 floats per draw instead of 21). Counted beside matrixAffineVertex; the
// pipelines keep the uploaded mat3 (cheaper per vertex).
// counted: 46 mul, 30 add
mat3x4 affineAdjugateVertex(mat4x3 model, float mirror, vec3 position, vec3 normal, vec4 tangent) {
  return matrixAffineVertex(model, affineCofactor(mat3(model)), mirror, position, normal, tangent);
}

// Linear blend of four affine joint matrices.
// counted: 48 mul, 36 add
mat4x3 affineBlendJoints(mat4x3 j0, mat4x3 j1, mat4x3 j2, mat4x3 j3, vec4 weights) {
  return weights.x * j0 + weights.y * j1 + weights.z * j2 + weights.w * j3;
}

// Linear blend of four joint normal matrices (the per-joint mat3 alternative to the cofactor).
// counted: 36 mul, 27 add
mat3 affineBlendNormals(mat3 n0, mat3 n1, mat3 n2, mat3 n3, vec4 weights) {
  return weights.x * n0 + weights.y * n1 + weights.z * n2 + weights.w * n3;
}

// Skinned vertex with four joints (linear blend skinning). Joint matrices are joint world *
// inverse bind: glTF ignores a skinned node's own transform, so no model matrix follows. The
// normal goes through the cofactor of the blended linear part (correct for any affine joint
// with det > 0); `mirror` = sign(det) of the skinned node's world, as the matrix pipeline's.
// counted: 94 mul, 66 add (blend 48/36, cofactor 18/9, matrixAffineVertex 28/21)
mat3x4 affineSkinnedVertex(mat4x3 j0, mat4x3 j1, mat4x3 j2, mat4x3 j3, vec4 weights,
                           float mirror, vec3 position, vec3 normal, vec4 tangent) {
  mat4x3 skin = affineBlendJoints(j0, j1, j2, j3, weights);
  return matrixAffineVertex(skin, affineCofactor(mat3(skin)), mirror, position, normal, tangent);
}

// Rigid vertex without a tangent: primitives without TANGENT and without a normal map, whose
// vertex is position + normal + uv (8 floats, as matrix.vs's MB_NO_TANGENT). [2] is
// (0, 0, 0, 1): forward.fs reads the tangent only with a normal map.
// counted: 18 mul, 15 add
mat3x4 affineVertexNoTangent(mat4x3 model, mat3 normalMatrix, vec3 position, vec3 normal) {
  return mat3x4(vec4(mat3(model) * position + model[3], 1.0), vec4(normalMatrix * normal, 0.0),
                vec4(0.0, 0.0, 0.0, 1.0));
}

// Skinned vertex without a tangent (8-float vertex + skin attributes).
// counted: 84 mul, 60 add (blend 48/36, cofactor 18/9, affineVertexNoTangent 18/15)
mat3x4 affineSkinnedVertexNoTangent(mat4x3 j0, mat4x3 j1, mat4x3 j2, mat4x3 j3, vec4 weights,
                                    vec3 position, vec3 normal) {
  mat4x3 skin = affineBlendJoints(j0, j1, j2, j3, weights);
  return affineVertexNoTangent(skin, affineCofactor(mat3(skin)), position, normal);
}

// The same with a normal matrix per joint (21 floats per joint instead of 12); counted only.
// counted: 112 mul, 84 add
mat3x4 affineSkinnedNormalsVertex(mat4x3 j0, mat4x3 j1, mat4x3 j2, mat4x3 j3, mat3 n0, mat3 n1,
                                  mat3 n2, mat3 n3, vec4 weights, float mirror, vec3 position,
                                  vec3 normal, vec4 tangent) {
  return matrixAffineVertex(affineBlendJoints(j0, j1, j2, j3, weights),
                            affineBlendNormals(n0, n1, n2, n3, weights), mirror, position, normal,
                            tangent);
}

// ---- QTangent: the vertex frame as one quaternion (int16x4 SNORM on the GPU) ---------------

// The frame of a unit quaternion q = (x, y, z, w) of the rotation whose columns are
// (tangent, bitangent, normal): [0].xyz normal (third column), [1].xyz tangent (first column),
// [1].w handedness = sign(w). The encoder keeps |w| >= 1/32767 (the bias rule), so the sign
// survives integer storage and sign() never sees 0.
// counted: 12 mul, 8 add, 1 other (sign)
mat2x4 qtangentFrame(vec4 q) {
  vec3 q2 = q.xyz * 2.0;
  float xx = q.x * q2.x;
  float yy = q.y * q2.y;
  float zz = q.z * q2.z;
  float xy = q.x * q2.y;
  float xz = q.x * q2.z;
  float yz = q.y * q2.z;
  float wx = q.w * q2.x;
  float wy = q.w * q2.y;
  float wz = q.w * q2.z;
  return mat2x4(xz + wy, yz - wx, 1.0 - xx - yy, 0.0, 1.0 - yy - zz, xy + wz, xz - wy, sign(q.w));
}

// Rigid vertex from a QTangent: decode, then matrixAffineVertex.
// counted: 40 mul, 29 add, 1 other
mat3x4 qtangentRigidVertex(mat4x3 model, mat3 normalMatrix, float mirror, vec3 position,
                           vec4 qtangent) {
  mat2x4 f = qtangentFrame(qtangent);
  return matrixAffineVertex(model, normalMatrix, mirror, position, vec3(f[0].xyz), f[1]);
}

// Skinned vertex from a QTangent: decode, then affineSkinnedVertex.
// counted: 106 mul, 74 add, 1 other
mat3x4 qtangentSkinnedVertex(mat4x3 j0, mat4x3 j1, mat4x3 j2, mat4x3 j3, vec4 weights,
                             float mirror, vec3 position, vec4 qtangent) {
  mat2x4 f = qtangentFrame(qtangent);
  return affineSkinnedVertex(j0, j1, j2, j3, weights, mirror, position, vec3(f[0].xyz), f[1]);
}

// ---- matrix_c: octahedral normal + diamond tangent in 4 bytes (compact_frame.glsl) ----------

// Rigid vertex of matrix_c: decode, then matrixAffineVertex. The position's dequantisation is
// folded into `model` on the CPU (model * translate(center) * scale(extent)).
mat3x4 compactRigidVertex(mat4x3 model, mat3 normalMatrix, float mirror, vec3 position,
                          vec4 frame) {
  mat2x4 f = compactMatrixFrame(frame);
  return matrixAffineVertex(model, normalMatrix, mirror, position, vec3(f[0].xyz), f[1]);
}

// Skinned vertex of matrix_c: the position dequantised per vertex (see motorCompactSkinnedVertex).
mat3x4 compactSkinnedVertex(mat4x3 j0, mat4x3 j1, mat4x3 j2, mat4x3 j3, vec4 weights,
                            float mirror, vec3 position, vec4 dequant, vec4 frame) {
  mat2x4 f = compactMatrixFrame(frame);
  return affineSkinnedVertex(j0, j1, j2, j3, weights, mirror, compactPosition(position, dequant),
                             vec3(f[0].xyz), f[1]);
}

#endif  // MB_AFFINE_TRANSFORM_GLSL
