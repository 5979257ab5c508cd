// motor_transform.glsl: the per-vertex transform of the motor pipeline, written once in the
// GLSL subset that also compiles as C++ through shaders/shim/glsl.h, so the same source runs
// on the GPU (shaders/motor.vs), in CPU tests, and with the op-counting scalar (the kernels
// "rigid vertex with frame", "skinned vertex with 4 joints" and "world to clip").
// Needs pga.glsl (motor = mat2x4 [[s,e23,e31,e12],[e01,e02,e03,e0123]]) included before it.

#ifndef MB_MOTOR_TRANSFORM_GLSL
#define MB_MOTOR_TRANSFORM_GLSL

#include "compact_frame.glsl"

// A transformed vertex is returned as a mat3x4 (the shim's subset has no structs and no out
// parameters): [0].xyz world position, [1].xyz world normal (any length; forward.fs
// normalises), [2] = world tangent xyz and handedness w (+1 / -1). [0].w and [1].w are 0.

// Handedness encoded in the sign of the tangent rotor's scalar part. 1/x keeps the sign of an
// IEEE signed zero (1/-0 = -inf), so frames whose scalar part is exactly 0 decode correctly.
float motorHandedness(vec4 tangentRotor) { return sign(1.0 / tangentRotor.x); }

// Rigid vertex with frame (the paper's path). Contract: `toWorld` is a unit motor,
// `scale` > 0 is the draw's uniform scale, applied to the position before the motor (the
// scale was factored out of the hierarchy to the right of every motor); `tangentRotor` is the
// unit rotor taking the basis frame (x = tangent, z = normal) to the vertex frame.
mat3x4 motorRigidVertex(motor toWorld, float scale, vec3 position, vec4 tangentRotor) {
  vec3 worldPosition = sw_mp(toWorld, position * scale);
  // The frame is invariant to translation: only the rotor half of the world motor matters.
  mat2x3 nt = extractNormalTangent(gp_rr(toWorld, motor(tangentRotor, vec4(0.0))));
  return mat3x4(worldPosition, 0.0, nt[0], 0.0, nt[1], motorHandedness(tangentRotor));
}

// motorRigidVertex with the handedness given apart from the rotor (whose sign then does not
// matter): the compact rotors, whose handedness is a bit of their own.
mat3x4 motorRigidRotorVertex(motor toWorld, float scale, vec3 position, vec4 rotor, float handedness) {
  vec3 worldPosition = sw_mp(toWorld, position * scale);
  mat2x3 nt = extractNormalTangent(gp_rr(toWorld, motor(rotor, vec4(0.0))));
  return mat3x4(worldPosition, 0.0, nt[0], 0.0, nt[1], handedness);
}

// The documented fallback for draws whose scale is not a positive uniform scale: a
// non-uniformly scaled leaf, or a mirrored (negative-scale) node. `scale` is applied to the
// object-space position first; the frame is decoded in object space, the normal divided and
// the tangent multiplied by the scale (the inverse-transpose rule of a normal matrix), then
// both are moved by the motor and normalised (their lengths now differ per vertex, and the
// matrix pipeline interpolates unit vectors). A mirroring scale (odd number of negative
// components) flips the handedness, as the matrix pipeline's sign(det(model)) does.
// Contract: no component of `scale` is 0. The handedness is given apart from the rotor (whose
// sign then does not matter): motorScaledVertex reads it from the rotor's scalar sign, the
// compact forms from their own bits.
mat3x4 motorScaledRotorVertex(motor toWorld, vec3 scale, vec3 position, vec4 rotor, float handedness) {
  vec3 worldPosition = sw_mp(toWorld, position * scale);
  mat2x3 nt = extractNormalTangent(motor(rotor, vec4(0.0)));
  float mirror = sign(scale.x * scale.y * scale.z);
  return mat3x4(worldPosition, 0.0, normalize(sw_md(toWorld, nt[0] / scale)), 0.0,
                normalize(sw_md(toWorld, nt[1] * scale)), mirror * handedness);
}

// The fallback with the paper's vertex (handedness in the sign of the scalar part).
mat3x4 motorScaledVertex(motor toWorld, vec3 scale, vec3 position, vec4 tangentRotor) {
  return motorScaledRotorVertex(toWorld, scale, position, tangentRotor, motorHandedness(tangentRotor));
}

// The exact fallback for a transform that is not a similarity (pipelines/motor/linear_fallback.h:
// an inherited non-uniform scale, a sheared matrix, a skin whose joints' scales differ): the
// polar factors x -> toWorld(linear * x), normals through normalLinear = inverse-transpose of
// linear, the tangent through linear, both then moved by the motor and normalised; a mirroring
// linear part (det < 0) flips the handedness as the matrix pipeline's sign(det(model)) does.
// motorScaledRotorVertex is its diagonal case.
mat3x4 motorLinearRotorVertex(motor toWorld, mat3 linear, mat3 normalLinear, vec3 position,
                              vec4 rotor, float handedness) {
  vec3 worldPosition = sw_mp(toWorld, linear * position);
  mat2x3 nt = extractNormalTangent(motor(rotor, vec4(0.0)));
  float mirror = sign(dot(linear[0], cross(linear[1], linear[2])));
  return mat3x4(worldPosition, 0.0, normalize(sw_md(toWorld, normalLinear * nt[0])), 0.0,
                normalize(sw_md(toWorld, linear * nt[1])), mirror * handedness);
}

// The linear parts of four joints blended with the skin weights (the motors blend by
// motorBlendJoints): at a pose where the joints agree, the joints' common transform exactly.
mat3 motorBlendLinear(mat3 l0, mat3 l1, mat3 l2, mat3 l3, vec4 weights) {
  return l0 * weights.x + l1 * weights.y + l2 * weights.z + l3 * weights.w;
}

// Motor skinning: the weighted blend of four joint motors along the shortest arc,
// renormalised, with the reference's hemisphere rule: each joint after the first is compared
// with the running sum of those before it and negated (here: its weight) when the rotor
// halves' dot product is <= 0. Negating the weight instead of the motor gives the same floats
// (negation is exact). Contract: weights sum to 1 and joint motors are unit.
motor motorBlendJoints(motor j0, motor j1, motor j2, motor j3, vec4 weights) {
  motor r = j0 * weights.x;
  r = r + j1 * (dot(r[0], j1[0]) <= 0.0 ? -weights.y : weights.y);
  r = r + j2 * (dot(r[0], j2[0]) <= 0.0 ? -weights.z : weights.z);
  r = r + j3 * (dot(r[0], j3[0]) <= 0.0 ? -weights.w : weights.w);
  return normalize_m(r);
}

// Skinned vertex with four joints, world-space palette (the pipeline's default): the joint
// motors are joint world * inverse bind, so the blended joint motor alone takes the vertex to
// world space (glTF: a skinned mesh ignores its node's transform). `scale` > 0 is the skin's
// uniform scale (the joints' common world scale times the inverse-bind scale).
mat3x4 motorSkinnedVertex(motor j0, motor j1, motor j2, motor j3, vec4 weights,
                               float scale, vec3 position, vec4 tangentRotor) {
  return motorRigidVertex(motorBlendJoints(j0, j1, j2, j3, weights), scale, position,
                          tangentRotor);
}

// Skinned vertex as the paper's shader does it: the joint motors are relative to the mesh
// node (reverse(node world) * joint world * inverse bind) and the node's world motor is
// composed per vertex, toWorld = gp(toWorld, blend). The same pose as motorSkinnedVertex
// (left-multiplying every joint by one unit motor commutes with the blend, the hemisphere
// test and normalize_m); one gp_mm more per vertex.
mat3x4 motorSkinnedVertexReference(motor toWorld, motor j0, motor j1, motor j2, motor j3,
                                   vec4 weights, float scale, vec3 position,
                                   vec4 tangentRotor) {
  return motorRigidVertex(gp_mm(toWorld, motorBlendJoints(j0, j1, j2, j3, weights)), scale,
                          position, tangentRotor);
}

// ---- morph targets (the delta sums themselves are morph.glsl's) -------------------
// glTF's deltas are normal and tangent deltas; the motor vertex carries a tangent rotor. Two
// ways to morph it, both in object space before the skin or the motor:
//  (a) frame: the rotor's unit normal and tangent (rotorFrame), plus the weighted deltas, back
//      to a rotor per vertex (rotorFromFrame). Exact: the frame the matrix pipeline shades.
//  (b) rotor: per target a rotor delta made at load (the morphed frame's rotor minus the base
//      rotor, in its hemisphere), blended with the weights and renormalised (renormaliseRotor).
//      4 floats per target instead of 6; a linear blend of rotors is not the rotor of the
//      blended frame, so it is exact only at weights 0 and 1 of a single target.

// The object-space unit normal (column 0) and tangent (column 1) a unit tangent rotor encodes.
mat2x3 rotorFrame(vec4 rotor) {
  mat2x3 nt = extractNormalTangent(motor(rotor, vec4(0.0)));
  return mat2x3(nt[0] * 2.0, nt[1] * 2.0);
}

// A rotor of any length back to unit length with its scalar's sign set to `handedness` (+1 /
// -1, motorHandedness's rule: a rotor and its negation are the same frame).
vec4 renormaliseRotor(vec4 rotor, float handedness) {
  float flip = (rotor.x < 0.0) == (handedness < 0.0) ? 1.0 : -1.0;
  return rotor * (flip * inversesqrt(dot(rotor, rotor)));
}

// The tangent rotor of the frame (normal, tangent), neither unit nor orthogonal (Gram-Schmidt,
// the normal wins), carrying `handedness`: encodeTangentRotor's construction
// (pipelines/motor/companion.h; the largest of the trace and the diagonal picks the formula).
vec4 rotorFromFrame(vec3 normal, vec3 tangent, float handedness) {
  vec3 n = normalize(normal);
  vec3 t = normalize(tangent - n * dot(n, tangent));
  vec3 b = cross(n, t);  // the columns are t, b, n
  float tr = t.x + b.y + n.z;
  vec4 r;
  if (tr > 0.0)
    r = vec4(tr + 1.0, n.y - b.z, t.z - n.x, b.x - t.y);
  else if (t.x > b.y && t.x > n.z)
    r = vec4(n.y - b.z, 1.0 + t.x - b.y - n.z, t.y + b.x, t.z + n.x);
  else if (b.y > n.z)
    r = vec4(t.z - n.x, t.y + b.x, 1.0 + b.y - t.x - n.z, b.z + n.y);
  else
    r = vec4(b.x - t.y, t.z + n.x, b.z + n.y, 1.0 + n.z - t.x - b.y);
  return renormaliseRotor(r, handedness);
}

// Method (a) with the handedness given apart from the rotor (of either sign): the frame of
// `rotor` plus the deltas, re-formed into a rotor whose scalar's sign is `handedness`.
vec4 morphRotorFrameHanded(vec4 rotor, float handedness, vec3 normalDelta, vec3 tangentDelta) {
  mat2x3 f = rotorFrame(rotor);
  return rotorFromFrame(f[0] + normalDelta, f[1] + tangentDelta, handedness);
}

// Method (a) per vertex: the rotor of its frame plus the summed weighted normal and tangent
// deltas (morph.glsl's sums), handedness kept.
vec4 morphRotorFrame(vec4 rotor, vec3 normalDelta, vec3 tangentDelta) {
  return morphRotorFrameHanded(rotor, motorHandedness(rotor), normalDelta, tangentDelta);
}

// Method (a) for motor_cf's signed rotor: the re-formed rotor put in the hemisphere of the
// stored one (the sign the mesh pass chose so that a triangle's corners interpolate), the
// handedness travelling apart (the position's w).
vec4 morphSignedRotorFrame(vec4 signedRotor, float handedness, vec3 normalDelta, vec3 tangentDelta) {
  vec4 r = morphRotorFrameHanded(signedRotor, handedness, normalDelta, tangentDelta);
  return dot(r, signedRotor) < 0.0 ? -r : r;
}

// Method (b) per vertex: the rotor plus the summed weighted rotor deltas, renormalised,
// handedness kept.
vec4 morphRotorBlend(vec4 rotor, vec4 rotorDelta) {
  return renormaliseRotor(rotor + rotorDelta, motorHandedness(rotor));
}

// World to clip: the camera motor (world -> view, camera looking down +z with x mirrored, the
// convention of pga.glsl's project()) and the perspective projection. With the same near,
// far, vertical fov and aspect this equals glm::perspective * view (GL depth range -1..1).
vec4 motorWorldToClip(motor camera, vec3 worldPosition, float znear, float zfar, float yfov,
                      float aspect) {
  return project(znear, zfar, yfov, aspect, sw_mp(camera, worldPosition));
}

// project()'s constants, evaluated once per frame on the CPU instead of per vertex (the matrix
// side builds its projection matrix once per frame too): (x scale, y scale, depth offset,
// depth slope) = (-cot(fov/2) / aspect, cot(fov/2), 2 f n / (n - f), (n + f) / (n - f)).
// counted: 4 mul, 3 add, 4 div, 1 sin, 1 cos (once per frame)
vec4 motorProjectionConstants(float znear, float zfar, float yfov, float aspect) {
  float cthf = cos(0.5 * yfov) / sin(0.5 * yfov);
  return vec4(-cthf / aspect, cthf, 2.0 * zfar * znear / (znear - zfar),
              (znear + zfar) / (znear - zfar));
}

// World to clip with motorProjectionConstants' `k`: the camera sandwich and project()'s
// per-vertex part only. Same result as motorWorldToClip (the paper's form, which recomputes
// the constants per vertex; both are counted by `motorbench ops`).
// counted: 24 mul, 19 add (sw_mp 21/18, projection 3/1)
vec4 motorWorldToClipConstants(motor camera, vec3 worldPosition, vec4 k) {
  vec3 p = sw_mp(camera, worldPosition);
  return vec4(p.xy * k.xy, k.z - k.w * p.z, p.z);
}

// The orthographic projection's constants in the same layout (an orthographic View, e.g. a glTF
// orthographic camera): (x scale, y scale, depth offset, depth slope) = (-1 / xmag, 1 / ymag,
// (n + f) / (n - f), 2 / (n - f)), xmag and ymag the half-width and half-height of the frame.
// With them motorWorldToClipOrthographic equals glm::ortho(-xmag, xmag, -ymag, ymag, n, f) * view.
// counted: 0 mul, 2 add, 4 div (once per frame)
vec4 motorOrthographicConstants(float znear, float zfar, float xmag, float ymag) {
  float depth = znear - zfar;
  return vec4(-1.0 / xmag, 1.0 / ymag, (znear + zfar) / depth, 2.0 / depth);
}

// World to clip with motorOrthographicConstants' `k`: motorWorldToClipConstants with w = 1 (an
// orthographic projection does not divide by depth).
// counted: 24 mul, 19 add (sw_mp 21/18, projection 3/1)
vec4 motorWorldToClipOrthographic(motor camera, vec3 worldPosition, vec4 k) {
  vec3 p = sw_mp(camera, worldPosition);
  return vec4(p.xy * k.xy, k.z - k.w * p.z, 1.0);
}

// ---- motor_c: the 4-byte tangent rotor (compact_frame.glsl) ---------------------------------

// Rigid vertex of motor_c: motorRigidVertex with the frame decoded from compactRotor and its
// handedness bit (no signed zero involved). The position's dequantisation is folded into
// `toWorld` and `scale` on the CPU (scale * extent, and a translation by scale * center).
mat3x4 motorCompactVertex(motor toWorld, float scale, vec3 position, vec4 frame) {
  mat2x4 r = compactRotor(frame);
  return motorRigidRotorVertex(toWorld, scale, position, r[0], r[1].x);
}

// motorScaledVertex's fallback (non-uniform or negative scale) with the compact frame.
mat3x4 motorCompactScaledVertex(motor toWorld, vec3 scale, vec3 position, vec4 frame) {
  mat2x4 r = compactRotor(frame);
  return motorScaledRotorVertex(toWorld, scale, position, r[0], r[1].x);
}

// Skinned vertex of motor_c (world-space palette): the position dequantised per vertex (a
// palette is shared by the skin's meshes, so the mesh's cube is not folded into it).
mat3x4 motorCompactSkinnedVertex(motor j0, motor j1, motor j2, motor j3, vec4 weights,
                                 float scale, vec3 position, vec4 dequant, vec4 frame) {
  return motorCompactVertex(motorBlendJoints(j0, j1, j2, j3, weights), scale,
                            compactPosition(position, dequant), frame);
}

// The paper's skin form (MB_SKIN_REFERENCE) of motorCompactSkinnedVertex: toWorld composed per
// vertex, as motorSkinnedVertexReference.
mat3x4 motorCompactSkinnedVertexReference(motor toWorld, motor j0, motor j1, motor j2, motor j3,
                                          vec4 weights, float scale, vec3 position, vec4 dequant,
                                          vec4 frame) {
  return motorCompactVertex(gp_mm(toWorld, motorBlendJoints(j0, j1, j2, j3, weights)), scale,
                            compactPosition(position, dequant), frame);
}

// ---- motor_cf: the rotor carried to the fragment shader (frame_shading.glsl) ----------------

// [0].xyz world position, [1] the world tangent rotor toWorld * rotor (rotor's sign kept).
mat2x4 motorRotorVertex(motor toWorld, float scale, vec3 position, vec4 rotor) {
  return mat2x4(sw_mp(toWorld, position * scale), 0.0, gp_rr(toWorld, motor(rotor, vec4(0.0)))[0]);
}

// Rigid vertex of motor_cf: [0].xyz world position, [1] the world tangent rotor, the draw's
// rotor times the vertex's, with the vertex rotor's sign (compactSignedRotor): no normal or
// tangent is extracted per vertex. Left-multiplying by one unit rotor keeps every dot
// product, so a triangle whose rotors share a hemisphere still does in world space.
mat2x4 motorCompactRotorVertex(motor toWorld, float scale, vec3 position, vec4 frame) {
  return motorRotorVertex(toWorld, scale, position, compactSignedRotor(frame));
}

// Skinned vertex of motor_cf (world-space palette; the palette's motors are put in one
// hemisphere on the CPU so that neighbouring vertices blend to rotors of one sign).
mat2x4 motorCompactRotorSkinnedVertex(motor j0, motor j1, motor j2, motor j3, vec4 weights,
                                      float scale, vec3 position, vec4 dequant, vec4 frame) {
  return motorCompactRotorVertex(motorBlendJoints(j0, j1, j2, j3, weights), scale,
                                 compactPosition(position, dequant), frame);
}

// The paper's skin form (MB_SKIN_REFERENCE) of motorCompactRotorSkinnedVertex.
mat2x4 motorCompactRotorSkinnedVertexReference(motor toWorld, motor j0, motor j1, motor j2, motor j3,
                                               vec4 weights, float scale, vec3 position, vec4 dequant,
                                               vec4 frame) {
  return motorCompactRotorVertex(gp_mm(toWorld, motorBlendJoints(j0, j1, j2, j3, weights)), scale,
                                 compactPosition(position, dequant), frame);
}

#endif  // MB_MOTOR_TRANSFORM_GLSL
