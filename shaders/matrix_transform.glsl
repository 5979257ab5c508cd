// matrix_transform.glsl: the per-vertex transform of the matrix pipeline, written once in the
// GLSL subset of shaders/shim/glsl.h so that the same source runs on the GPU (shaders/matrix.vs
// calls these functions), with the op-counting scalar (`motorbench ops`) and as the CPU kernels
// of `motorbench bench`. The matrix baseline is the Khronos glTF-Sample-Viewer's: u_ModelMatrix
// and u_NormalMatrix (= transpose(inverse(model))) as full mat4s, three mat4 * vec4 products
// per vertex (the paper's 48 mul / 36 add). matrixAffineVertex is the cheaper affine baseline
// (3x4 model, mat3 normal matrix) that a fair comparison also shows.
//
// Every "counted:" line is what `motorbench ops` measures by executing this file with
// mb::Counted (subtraction counts as addition, multiplications by literal 1 and 0 count too:
// the shader's mat4 * vec4(p, 1.0) performs them).

#ifndef MB_MATRIX_TRANSFORM_GLSL
#define MB_MATRIX_TRANSFORM_GLSL

// A transformed vertex is a mat3x4 (the shim's subset has no structs, no out parameters):
// [0] world position with w (the caller divides by w, as the Sample Viewer does),
// [1].xyz world normal (not normalised), [2].xyz world tangent (not normalised), [2].w the
// tangent handedness. [1].w is 0 for affine matrices.

// Handedness: the normal matrix's [3][3] entry carries sign(det(model)) (it is never used for a
// direction, whose w is 0), so a mirrored node flips the tangent's w.
// counted: 1 mul
float matrixHandedness(mat4 normalMatrix, float w) { return w * normalMatrix[3][3]; }

// The three products: position and tangent by the model matrix, the normal by the normal
// matrix, all full mat4 * vec4.
// counted: 48 mul, 36 add (paper: 48, 36)
mat3x4 matrixTransformFrame(mat4 model, mat4 normalMatrix, vec4 position, vec4 normal,
                            vec4 tangent) {
  return mat3x4(model * position, normalMatrix * normal, model * tangent);
}

// Rigid vertex with frame: the Sample Viewer's vertex path.
// counted: 49 mul, 36 add (the three products + the handedness)
mat3x4 matrixRigidVertex(mat4 model, mat4 normalMatrix, vec3 position, vec3 normal,
                         vec4 tangent) {
  mat3x4 v = matrixTransformFrame(model, normalMatrix, vec4(position, 1.0), vec4(normal, 0.0),
                                  vec4(tangent.xyz, 0.0));
  v[2].w = matrixHandedness(normalMatrix, tangent.w);
  return v;
}

// Linear blend of four joint matrices (the Sample Viewer blends the joint matrices and, with
// the same weights, the joint normal matrices).
// counted: 64 mul, 48 add
mat4 matrixBlendJoints(mat4 j0, mat4 j1, mat4 j2, mat4 j3, vec4 weights) {
  return weights.x * j0 + weights.y * j1 + weights.z * j2 + weights.w * j3;
}

// Skinned vertex with four joints (linear blend skinning). Joint matrices are
// inverse(mesh node world) * joint world * inverse bind, so the model matrix still applies
// after the skin, as in the Sample Viewer; n0..n3 are the joints' normal matrices.
// counted: 225 mul, 168 add (2 blends, 2 x three products, the handedness)
mat3x4 matrixSkinnedVertex(mat4 j0, mat4 j1, mat4 j2, mat4 j3, mat4 n0, mat4 n1, mat4 n2,
                           mat4 n3, vec4 weights, mat4 model, mat4 normalMatrix, vec3 position,
                           vec3 normal, vec4 tangent) {
  mat4 skin = matrixBlendJoints(j0, j1, j2, j3, weights);
  mat4 skinNormal = matrixBlendJoints(n0, n1, n2, n3, weights);
  mat3x4 s = matrixTransformFrame(skin, skinNormal, vec4(position, 1.0), vec4(normal, 0.0),
                                  vec4(tangent.xyz, 0.0));
  mat3x4 v = matrixTransformFrame(model, normalMatrix, s[0], s[1], s[2]);
  v[2].w = matrixHandedness(normalMatrix, tangent.w);
  return v;
}

// ---- without a tangent attribute --------------------------------------------------------
// The Sample Viewer's shader has no tangent input where the primitive has no TANGENT and its
// material no normal map (HAS_TANGENT_VEC4 unset); the vertex then carries position, normal
// and uv only (32 bytes) and no tangent product is done. [2] is (0, 0, 0, 1): nothing reads
// it (forward.fs uses the tangent only with a normal map).

// counted: 32 mul, 24 add (position and normal products)
mat3x4 matrixRigidVertexNoTangent(mat4 model, mat4 normalMatrix, vec3 position, vec3 normal) {
  return mat3x4(model * vec4(position, 1.0), normalMatrix * vec4(normal, 0.0),
                vec4(0.0, 0.0, 0.0, 1.0));
}

// counted: 192 mul, 144 add (2 blends, 2 x two products)
mat3x4 matrixSkinnedVertexNoTangent(mat4 j0, mat4 j1, mat4 j2, mat4 j3, mat4 n0, mat4 n1,
                                    mat4 n2, mat4 n3, vec4 weights, mat4 model,
                                    mat4 normalMatrix, vec3 position, vec3 normal) {
  mat4 skin = matrixBlendJoints(j0, j1, j2, j3, weights);
  mat4 skinNormal = matrixBlendJoints(n0, n1, n2, n3, weights);
  return mat3x4(model * (skin * vec4(position, 1.0)),
                normalMatrix * (skinNormal * vec4(normal, 0.0)), vec4(0.0, 0.0, 0.0, 1.0));
}

// ---- skinning with a world-space palette ---------------------------------------------------
// The configuration neither reference uses, counted beside theirs so that both pipelines can
// be compared in the same space: joint matrices are joint world * inverse bind (no
// inverse(mesh node world) in front), so the blended skin alone reaches world space and no
// model matrix is applied per vertex. `normalMatrix` is still the draw's, for the handedness
// sign only. The motor counterpart is motorSkinnedVertex (motor_transform.glsl).

// counted: 177 mul, 132 add (2 blends, three products, the handedness)
mat3x4 matrixSkinnedVertexWorld(mat4 j0, mat4 j1, mat4 j2, mat4 j3, mat4 n0, mat4 n1, mat4 n2,
                                mat4 n3, vec4 weights, mat4 normalMatrix, vec3 position,
                                vec3 normal, vec4 tangent) {
  mat4 skin = matrixBlendJoints(j0, j1, j2, j3, weights);
  mat4 skinNormal = matrixBlendJoints(n0, n1, n2, n3, weights);
  mat3x4 v = matrixTransformFrame(skin, skinNormal, vec4(position, 1.0), vec4(normal, 0.0),
                                  vec4(tangent.xyz, 0.0));
  v[2].w = matrixHandedness(normalMatrix, tangent.w);
  return v;
}

// counted: 160 mul, 120 add (2 blends, two products)
mat3x4 matrixSkinnedVertexWorldNoTangent(mat4 j0, mat4 j1, mat4 j2, mat4 j3, mat4 n0, mat4 n1,
                                         mat4 n2, mat4 n3, vec4 weights, vec3 position,
                                         vec3 normal) {
  mat4 skin = matrixBlendJoints(j0, j1, j2, j3, weights);
  mat4 skinNormal = matrixBlendJoints(n0, n1, n2, n3, weights);
  return mat3x4(skin * vec4(position, 1.0), skinNormal * vec4(normal, 0.0),
                vec4(0.0, 0.0, 0.0, 1.0));
}

// World to clip: one mat4 * vec4 with the per-frame view-projection matrix.
// counted: 16 mul, 12 add
vec4 matrixWorldToClip(mat4 viewProjection, vec4 worldPosition) {
  return viewProjection * worldPosition;
}

// The affine baseline: the model matrix as 3 rows x 4 columns (GLSL mat4x3, 12 floats), the
// normal matrix as a mat3, `handedness` = tangent w * sign(det(model)) folded per draw into a
// factor. Not used by matrix.vs; reported as an extra row by `motorbench ops`.
// counted: 28 mul, 21 add (position 9/9, normal 9/6, tangent 9/6, handedness 1/0)
mat3x4 matrixAffineVertex(mat4x3 model, mat3 normalMatrix, float mirror, vec3 position,
                          vec3 normal, vec4 tangent) {
  mat3 linear = mat3(model);
  return mat3x4(linear * position + model[3], 1.0, normalMatrix * normal, 0.0,
                linear * tangent.xyz, tangent.w * mirror);
}

// ---- the building blocks `motorbench bench` times (CPU) ------------------------------------

// Composition of two transforms (a after b).
// counted: 64 mul, 48 add
mat4 matrixCompose(mat4 a, mat4 b) { return a * b; }

// A point: the full product; .w is 1 for affine matrices.
// counted: 16 mul, 12 add
vec4 matrixTransformPoint(mat4 m, vec3 p) { return m * vec4(p, 1.0); }

// A direction (w = 0), as the Sample Viewer transforms the tangent.
// counted: 16 mul, 12 add
vec4 matrixTransformDirection(mat4 m, vec3 d) { return m * vec4(d, 0.0); }

#endif  // MB_MATRIX_TRANSFORM_GLSL
