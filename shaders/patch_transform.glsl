// patch_transform.glsl: the frame of a tessellated Bezier patch vertex in each pipeline, from
// bezierPatch()'s object-space P, dP/du, dP/dv (bezier_patch.glsl). Here the tangent frame is
// born in the vertex shader instead of being stored per vertex. GLSL subset of
// shaders/shim/glsl.h; needs pga.glsl and matrix_transform.glsl included before it.
// A result is the mat3x4 of matrix_transform.glsl / motor_transform.glsl: [0] world position
// (w 1 for the matrix path, 0 for motors), [1].xyz world normal (any length), [2].xyz world
// tangent (any length), [2].w handedness (bitangent = w * cross(n, t)).

#ifndef MB_PATCH_TRANSFORM_GLSL
#define MB_PATCH_TRANSFORM_GLSL

// Matrix path: normal = dP/du x dP/dv through the normal matrix, tangent = dP/du and the
// position through the model matrix (the Sample Viewer's three mat4 * vec4 products).
// counted: 55 mul, 39 add (cross 6/3, three products 48/36, handedness 1/0)
mat3x4 matrixPatchVertex(mat4 model, mat4 normalMatrix, mat3 surface) {
  mat3x4 v = matrixTransformFrame(model, normalMatrix, vec4(surface[0], 1.0),
                                  vec4(cross(surface[1], surface[2]), 0.0), vec4(surface[1], 0.0));
  v[2].w = matrixHandedness(normalMatrix, 1.0);
  return v;
}

// Affine path (affine_patch.vs: `affine`, `qtangent`, `hybrid`): matrixAffineVertex with the
// draw's mat4x3 model, mat3 normal matrix and mirror factor on P, dP/du x dP/dv and dP/du.
// counted: 34 mul, 24 add (cross 6/3, matrixAffineVertex 28/21)
mat3x4 affinePatchVertex(mat4x3 model, mat3 normalMatrix, float mirror, mat3 surface) {
  return matrixAffineVertex(model, normalMatrix, mirror, surface[0], cross(surface[1], surface[2]),
                            vec4(surface[1], 1.0));
}

// Motor path (a), the one motor_patch.vs uses: both derivatives moved by the direction
// sandwich and crossed in world space (a rotation commutes with the cross product, so this is
// the world normal). `scale` > 0 is the draw's uniform scale (it does not turn directions).
// counted: 66 mul, 45 add (sw_mp 21/18 + scale 3/0, two sw_md 36/24, cross 6/3)
mat3x4 motorPatchVertex(motor toWorld, float scale, mat3 surface) {
  vec3 t = sw_md(toWorld, surface[1]);
  vec3 b = sw_md(toWorld, surface[2]);
  return mat3x4(sw_mp(toWorld, surface[0] * scale), 0.0, cross(t, b), 0.0, t, 1.0);
}

// Motor path (a) for a non-uniform or negative scale (the MB_SCALE_FALLBACK draws): the scaled
// surface's derivatives are the scaled derivatives, so (a) stays exact; a mirroring scale
// flips the cross product's orientation relative to the matrix pipeline's normal matrix
// (cross(M a, M b) = det(M) M^-T (a x b)) and the handedness, as sign(det) does there.
mat3x4 motorScaledPatchVertex(motor toWorld, vec3 scale, mat3 surface) {
  vec3 t = sw_md(toWorld, surface[1] * scale);
  vec3 b = sw_md(toWorld, surface[2] * scale);
  float mirror = sign(scale.x * scale.y * scale.z);
  return mat3x4(sw_mp(toWorld, surface[0] * scale), 0.0, mirror * cross(t, b), 0.0, t, mirror);
}

// The tangent rotor of an orthonormal frame (t = x axis, n = z axis, bitangent n x t), in the
// PGA rotor layout [s, e23, e31, e12] (quaternion (x, y, z, w) -> [w, -x, -y, -z]); the
// largest of trace and diagonal picks the stable formula (Shepperd).
vec4 frameRotor(vec3 t, vec3 n) {
  vec3 b = cross(n, t);
  float trace = t.x + b.y + n.z;
  vec4 q;
  if (trace > 0.0) {
    float s = 0.5 * inversesqrt(trace + 1.0);
    q = vec4((b.z - n.y) * s, (n.x - t.z) * s, (t.y - b.x) * s, 0.25 / s);
  } else if (t.x > b.y && t.x > n.z) {
    float s = 2.0 * sqrt(1.0 + t.x - b.y - n.z);
    q = vec4(0.25 * s, (b.x + t.y) / s, (n.x + t.z) / s, (b.z - n.y) / s);
  } else if (b.y > n.z) {
    float s = 2.0 * sqrt(1.0 + b.y - t.x - n.z);
    q = vec4((b.x + t.y) / s, 0.25 * s, (n.y + b.z) / s, (n.x - t.z) / s);
  } else {
    float s = 2.0 * sqrt(1.0 + n.z - t.x - b.y);
    q = vec4((n.x + t.z) / s, (n.y + b.z) / s, 0.25 * s, (t.y - b.x) / s);
  }
  return vec4(q.w, -q.x, -q.y, -q.z);
}

// Motor path (b), counted and reported, not drawn: the object-space frame as a tangent rotor,
// composed with the world motor's rotor (gp_rr) and decoded (extractNormalTangent), the
// stored-rotor path of motor_transform.glsl with the rotor built per vertex.
// counted: 75 mul, 56 add, 3 div, 1 sqrt, 2 inversesqrt where the frame's trace is <= 0
// (tests/pipelines/test_patch_eval.cpp); 77 mul, 54 add, 1 div, 3 inversesqrt where it is > 0
// (tests/ops/test_pga_vertex_ops.cpp, motorbench ops)
mat3x4 motorPatchVertexRotor(motor toWorld, float scale, mat3 surface) {
  vec4 r = frameRotor(normalize(surface[1]), normalize(cross(surface[1], surface[2])));
  mat2x3 nt = extractNormalTangent(gp_rr(toWorld, motor(r, vec4(0.0))));
  return mat3x4(sw_mp(toWorld, surface[0] * scale), 0.0, nt[0], 0.0, nt[1], 1.0);
}

#endif  // MB_PATCH_TRANSFORM_GLSL
