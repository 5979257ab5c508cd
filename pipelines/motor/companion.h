// pipelines/motor/companion.h: the CPU-only part of the PGA toolbox (what never runs on the
// GPU), header-only, built on the float instantiation of shaders/pga.glsl (mb::Pga<float>).
//
//   motorFromMatrix                      4x4 (column-major, GLM / glTF) -> motor, with the
//                                        scale check: per-axis scales, rigid / uniform /
//                                        non-uniform, negative (reflection), shear
//   motorToMatrix                        motor -> 4x4 (column-major)
//   rotorFromQuat, translator,           glTF TRS -> motor (quaternion (x,y,z,w) ->
//   motorFromTRS                         [w,-x,-y,-z], translation t -> [1,0,0,0,-t/2,0])
//   encodeTangentRotor                   (normal, tangent, handedness w) -> 4-float rotor
//                                        (the shaders' decoder: motor_transform.glsl rotorFrame)
//
// Tangent-rotor handedness rule (see encodeTangentRotor): the frame (tangent, normal x tangent,
// normal) is a proper rotation; its rotor R and -R give the same frame, and the sign of R's
// scalar part carries glTF's handedness w. The reference implementation breaks when that
// scalar is exactly 0 (180-degree turns of the basis frame, e.g. on axis-aligned boxes): it
// compares Math.sign(s), which is 0, and stores -0, so w = +1 decodes as -1; signed zero also
// does not survive SNORM/half packing or GPUs that flush. Here the sign is chosen with signbit
// (so +-0 are handled) and then |s| is clamped to at least kMinTangentScalar = 1/32767 (the
// QTangent bias of Crytek and Filament), renormalising the vector part, so the stored scalar
// is never zero, survives 16-bit SNORM, and every decoder (sign(s), sign(1/s), s < 0) agrees.
// The clamp turns the frame by at most 2 * kMinTangentScalar rad (6.1e-5), only for frames
// within that angle of a 180-degree turn.
#pragma once
#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "pipelines/motor/motor_kernels.h"
#include "pipelines/scene/similarity_tolerance.h"
#include "shaders/shim/pga.h"

namespace mb::companion {

using P = Pga<float>;
using Motor = P::motor;
using Vec3 = P::vec3;
using Vec4 = P::vec4;

// pipelines/scene/similarity_tolerance.h: relative scale spread, and |cos| between columns.
inline constexpr float kScaleTolerance = float(kSimilarityTolerance);
inline constexpr float kShearTolerance = float(kSimilarityTolerance);
inline constexpr float kMinTangentScalar = 1.0f / 32767.0f;

inline glm::vec3 toGlm(const Vec3& v) { return glm::vec3(v.x, v.y, v.z); }

// ---- glTF TRS -------------------------------------------------------------------------------

// Unit quaternion (GLM stores w, x, y, z; glTF x, y, z, w) -> rotor [w, -x, -y, -z].
inline Motor rotorFromQuat(const glm::quat& q) {
  return Motor(Vec4(q.w, -q.x, -q.y, -q.z), Vec4(0.0f));
}
// Translation t -> translator [1, 0, 0, 0, -t/2, 0].
inline Motor translator(const glm::vec3& t) {
  return Motor(Vec4(1.0f, 0.0f, 0.0f, 0.0f), Vec4(-0.5f * t.x, -0.5f * t.y, -0.5f * t.z, 0.0f));
}
// Node transform T R (scale is tracked separately, see classifyScale).
inline Motor motorFromTRS(const glm::vec3& t, const glm::quat& q) {
  return pga<float>.gp_tr(translator(t), rotorFromQuat(q));
}

// ---- scale check ----------------------------------------------------------------------------

enum class ScaleKind { Rigid, Uniform, NonUniform };

// Rigid: every |s_i| within kScaleTolerance of 1 and no reflection. Uniform: the three scales
// (signs included) agree within the relative tolerance. Otherwise non-uniform.
inline ScaleKind classifyScale(const glm::vec3& s) {
  auto near = [](float a, float b) { return std::abs(a / b - 1.0f) <= kScaleTolerance; };
  if (near(s.x, 1.0f) && near(s.y, 1.0f) && near(s.z, 1.0f)) return ScaleKind::Rigid;
  if (near(s.x, s.y) && near(s.y, s.z)) return ScaleKind::Uniform;
  return ScaleKind::NonUniform;
}

struct MatrixMotor {
  Motor motor = identityMotor();  // the rigid part (rotation, then translation)
  glm::vec3 scale{1.0f};          // per-axis scale applied before the motor; all three are
                                  // negated when the matrix reflects (det < 0), so that
                                  // matrix = motor-matrix * diag(scale) holds
  ScaleKind kind = ScaleKind::Rigid;
  bool negative = false;          // det < 0: a reflection, carried by the negative scale
  bool sheared = false;           // columns not orthogonal: the motor is the nearest rotation
                                  // of the normalised columns, not exact
  bool degenerate = false;        // a zero column: motor is the translation only
  float uniformScale() const { return (scale.x + scale.y + scale.z) / 3.0f; }
};

namespace detail {

// Rotor of an orthonormal, proper 3x3 matrix given by columns (Shepperd's method: pick the
// largest of the four quaternion magnitudes, then normalise).
inline Vec4 rotorFromColumns(const glm::vec3& c0, const glm::vec3& c1, const glm::vec3& c2) {
  // m_ij = column i, row j.
  const float m00 = c0.x, m01 = c0.y, m02 = c0.z, m10 = c1.x, m11 = c1.y, m12 = c1.z,
              m20 = c2.x, m21 = c2.y, m22 = c2.z;
  const float tr = m00 + m11 + m22;
  Vec4 r;
  if (tr > 0.0f)
    r = Vec4(tr + 1.0f, m21 - m12, m02 - m20, m10 - m01);
  else if (m00 > m11 && m00 > m22)
    r = Vec4(m21 - m12, 1.0f + m00 - m11 - m22, m01 + m10, m02 + m20);
  else if (m11 > m22)
    r = Vec4(m02 - m20, m01 + m10, 1.0f + m11 - m00 - m22, m12 + m21);
  else
    r = Vec4(m10 - m01, m02 + m20, m12 + m21, 1.0f + m22 - m00 - m11);
  return r * (1.0f / std::sqrt(P::dot(r, r)));
}

}  // namespace detail

// 4x4 affine (last row 0 0 0 1) -> motor T R + scale check of the linear part. Column-major
// (m[i] is column i), as GLM and glTF.
inline MatrixMotor motorFromMatrix(const glm::mat4& m) {
  MatrixMotor out;
  const glm::mat3 l(m);
  glm::vec3 s(glm::length(l[0]), glm::length(l[1]), glm::length(l[2]));
  out.degenerate = !(s.x > 0.0f && s.y > 0.0f && s.z > 0.0f);
  if (out.degenerate) {
    out.kind = ScaleKind::NonUniform;
  } else {
    out.negative = glm::determinant(l) < 0.0f;
    if (out.negative) s = -s;
    out.kind = classifyScale(s);
    const glm::vec3 c0 = l[0] / s.x, c1 = l[1] / s.y, c2 = l[2] / s.z;
    out.sheared = std::abs(glm::dot(c0, c1)) > kShearTolerance ||
                  std::abs(glm::dot(c1, c2)) > kShearTolerance ||
                  std::abs(glm::dot(c0, c2)) > kShearTolerance;
    out.motor = Motor(detail::rotorFromColumns(c0, c1, c2), Vec4(0.0f));
  }
  out.scale = s;
  out.motor = pga<float>.gp_tr(translator(glm::vec3(m[3])), out.motor);
  return out;
}

// Normalised motor -> 4x4 matrix: columns are the images of x, y, z (sw_mx.. doubled) and
// of the origin.
inline glm::mat4 motorToMatrix(const Motor& M) {
  P& p = pga<float>;
  const Vec3 x = p.sw_mx(M) * 2.0f, y = p.sw_my(M) * 2.0f, z = p.sw_mz(M) * 2.0f, o = p.sw_mo(M);
  return glm::mat4(glm::vec4(toGlm(x), 0.0f), glm::vec4(toGlm(y), 0.0f),
                   glm::vec4(toGlm(z), 0.0f), glm::vec4(toGlm(o), 1.0f));
}

// ---- tangent rotors -------------------------------------------------------------------------

struct TangentRotor {
  glm::vec4 rotor{1.0f, 0.0f, 0.0f, 0.0f};  // (s, e23, e31, e12); sign(s) = handedness
  bool scalarWasZero = false;               // the frame's rotor scalar was exactly +-0
  bool clamped = false;                     // |s| was raised to kMinTangentScalar
};

// (normal, tangent, w) -> tangent rotor. normal and tangent need not be unit or orthogonal
// (Gram-Schmidt: the normal wins); w < 0 means handedness -1, anything else +1. The rotor maps
// x -> tangent, y -> normal x tangent, z -> normal (extractNormalTangent's convention).
inline TangentRotor encodeTangentRotor(const glm::vec3& normal, const glm::vec3& tangent, float w) {
  const glm::vec3 n = glm::normalize(normal);
  const glm::vec3 t = glm::normalize(tangent - n * glm::dot(n, tangent));
  const glm::vec3 b = glm::cross(n, t);
  Vec4 r = detail::rotorFromColumns(t, b, n);
  TangentRotor out;
  out.scalarWasZero = r.x == 0.0f;
  const bool wantNegative = w < 0.0f;
  if (std::signbit(r.x) != wantNegative) r = -r;  // signbit: +0 and -0 count too
  if (std::abs(r.x) < kMinTangentScalar) {
    const Vec3 v = r.yzw;
    const float k = std::sqrt(1.0f - kMinTangentScalar * kMinTangentScalar) / P::length(v);
    r = Vec4(wantNegative ? -kMinTangentScalar : kMinTangentScalar, v * k);
    out.clamped = true;
  }
  out.rotor = glm::vec4(r.x, r.y, r.z, r.w);
  return out;
}

}  // namespace mb::companion
