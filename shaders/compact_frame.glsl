// compact_frame.glsl: decoding the 16-byte vertices of the compact pipelines
// (`matrix_c`, `motor_c`), in the GLSL subset of shaders/shim/glsl.h so that the shaders, the
// CPU tests (which pair it with pipelines/gl/compact_encoding.h's encoders) and `motorbench
// ops` run the same source. No dependencies.
//
// The frame is one 32-bit GL_UNSIGNED_INT_2_10_10_10_REV read WITHOUT normalisation, so the
// shader sees the integer fields as exact floats: x, y, z in 0..1023, w in 0..3. Decoding in
// that integer-valued domain keeps every sign decision exact (no division before a sign test),
// which is what makes the encoder's choice the decoder's choice.
//   matrix_c: x, y = octahedral normal (511 = 0), z = tangent as a diamond code around the
//             normal, w = 1 for handedness -1.
//   motor_c:  the tangent rotor, smallest three: x, y = two components in 10 bits, z = the
//             third in 9 bits plus the reflection bit (512), w = which component was dropped.
//             The handedness is an explicit bit: no sign of a zero to lose (the paper's rule).
//   motor_cf: motor_c's word with that bit meaning "negate" (compactSignedRotor).

#ifndef MB_COMPACT_FRAME_GLSL
#define MB_COMPACT_FRAME_GLSL

// The rotor's stored components lie in [-1/sqrt 2, 1/sqrt 2] (the dropped one is the largest).
const float kRotorStep10 = 0.0013837717;  // 1 / (511 sqrt 2)
const float kRotorStep9 = 0.0027729848;   // 1 / (255 sqrt 2)

// Position from int16x4 SNORM (-1..1) and the mesh's cube: center xyz, half extent w. Only the
// variants that cannot fold it into their transform (skinned, instanced) run it.
// counted: 3 mul, 3 add
vec3 compactPosition(vec3 q, vec4 dequant) {
  return q * dequant.w + vec3(dequant.x, dequant.y, dequant.z);
}

// Unit normal from the two octahedral codes (511 is 0, 0 and 1022 are -1 and +1).
vec3 compactOctNormal(float cx, float cy) {
  float x = cx - 511.0;
  float y = cy - 511.0;
  float z = 511.0 - abs(x) - abs(y);
  float fold = max(-z, 0.0);  // the lower hemisphere is folded over the diagonals
  x = x >= 0.0 ? x - fold : x + fold;
  y = y >= 0.0 ? y - fold : y + fold;
  return normalize(vec3(x, y, z));
}

// Two unit axes of the plane perpendicular to unit `n`, continuous except across n.z = 0
// (Duff et al. 2017, "Building an orthonormal basis, revisited"). The encoder uses the
// decoded normal, so both sides take the same branch.
mat2x3 compactTangentBasis(vec3 n) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float b = n.x * n.y * a;
  return mat2x3(1.0 + s * n.x * n.x * a, s * b, -s * n.x, b, s + n.y * n.y * a, -n.y);
}

// The unnormalised 2D direction of a diamond code (0..1023 around the square |u| + |v| = 256).
vec2 compactDiamond(float c) {
  float u = c < 512.0 ? 256.0 - c : c - 768.0;
  return vec2(u, (c < 512.0 ? 1.0 : -1.0) * (256.0 - abs(u)));
}

// matrix_c's frame: [0].xyz unit normal, [1].xyz tangent (NOT unit: the vertex shader
// normalises after the transform), [1].w handedness.
// counted: 23 mul, 17 add, 1 div, 5 other (normalize, abs x3, max)
mat2x4 compactMatrixFrame(vec4 f) {
  vec3 n = compactOctNormal(f.x, f.y);
  mat2x3 b = compactTangentBasis(n);
  vec2 d = compactDiamond(f.z);
  return mat2x4(n, 0.0, b[0] * d.x + b[1] * d.y, 1.0 - 2.0 * f.w);
}

// motor_c's frame: [0] the unit tangent rotor (s, e23, e31, e12) up to sign, [1].x handedness.
// counted: 8 mul, 8 add, 1 sqrt, 1 other (max)
mat2x4 compactRotor(vec4 f) {
  float mirrored = step(512.0, f.z);
  vec3 c = vec3((f.x - 511.0) * kRotorStep10, (f.y - 511.0) * kRotorStep10,
                (f.z - 512.0 * mirrored - 255.0) * kRotorStep9);
  float d = sqrt(max(1.0 - dot(c, c), 0.0));
  float i = f.w;
  vec4 r = vec4(i == 0.0 ? d : c.x, i == 0.0 ? c.x : (i == 1.0 ? d : c.y),
                i < 2.0 ? c.y : (i == 2.0 ? d : c.z), i == 3.0 ? d : c.z);
  return mat2x4(r, 1.0 - 2.0 * mirrored, 0.0, 0.0, 0.0);
}

// motor_cf's frame: the same word with the bit that motor_c spends on the
// reflection saying "negate": the rotor keeps the sign the mesh pass chose for interpolation
// (pipelines/motor/rotor_signs.h); the handedness travels in the position's w instead.
// counted: 12 mul, 8 add, 1 sqrt, 1 other (compactRotor + the sign)
vec4 compactSignedRotor(vec4 f) {
  mat2x4 r = compactRotor(f);
  return r[0] * r[1].x;
}

#endif  // MB_COMPACT_FRAME_GLSL
