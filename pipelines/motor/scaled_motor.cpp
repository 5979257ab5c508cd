#include "pipelines/motor/scaled_motor.h"

#include <cmath>

#include "pipelines/motor/companion.h"
#include "pipelines/scene/scale_analysis.h"

namespace mb::motor {
namespace {

// Half turn about axis `i` (0 = x, 1 = y, 2 = z): quaternion (axis, w = 0) -> rotor.
Motor halfTurn(int i) {
  glm::quat q(0.0f, 0.0f, 0.0f, 0.0f);
  q[i] = 1.0f;  // glm::quat indexes x, y, z, w
  return companion::rotorFromQuat(q);
}

float sgn(float x) { return x < 0.0f ? -1.0f : 1.0f; }

}  // namespace

// flatten (here and in blend): the shim's motor functions inlined. Called per node per frame;
// left to itself GCC -O2 calls normalize_m and gp_* out of line with the motors passed through
// the stack, which cost more than the arithmetic (measured: the motor update was 1.2-1.8x the
// matrix update without flatten).
[[gnu::flatten]] ScaledMotor fromTRS(const TRS& trs, bool leaf, ConversionFlags* flags) {
  ConversionFlags f;
  const glm::vec3 s = trs.scale;
  Motor rotor = mk().normalize_m(companion::rotorFromQuat(trs.rotation));
  ScaledMotor out;
  f.negative = s.x < 0.0f || s.y < 0.0f || s.z < 0.0f;
  const float det = sgn(s.x) * sgn(s.y) * sgn(s.z);
  if (!isNonUniform(s)) {
    // diag(s) = sigma * F with sigma = det * |s| and F = diag(sign(s_i) * det): F has det +1,
    // so it is the identity or a half turn about the one axis whose entry is +1.
    out.scale = det * (std::fabs(s.x) + std::fabs(s.y) + std::fabs(s.z)) / 3.0f;
    const float F[3] = {sgn(s.x) * det, sgn(s.y) * det, sgn(s.z) * det};
    if (F[0] < 0.0f || F[1] < 0.0f || F[2] < 0.0f)
      for (int i = 0; i < 3; ++i)
        if (F[i] > 0.0f) rotor = mk().gp_rr(rotor, halfTurn(i));  // F first, then R
  } else if (leaf) {
    out.residual = s;  // exact: applied to the vertices before the motor
    f.nonUniform = true;
  } else {
    // Not representable below this node; keep the volume and the orientation sign.
    out.scale = det * std::cbrt(std::fabs(s.x * s.y * s.z));
    f.nonUniform = f.nonUniformInner = true;
  }
  out.motor = mk().gp_tr(companion::translator(trs.translation), rotor);
  if (flags) *flags = f;
  return out;
}

ScaledMotor fromMatrix(const glm::mat4& m, const TRS& approx, bool leaf, ConversionFlags* flags) {
  const companion::MatrixMotor mm = companion::motorFromMatrix(m);
  if (mm.degenerate) {
    ScaledMotor out = fromTRS(approx, leaf, flags);
    if (flags) flags->shear = true;
    return out;
  }
  ConversionFlags f;
  f.negative = mm.negative;
  f.shear = mm.sheared;
  ScaledMotor out;
  out.motor = mm.motor;  // sheared: the nearest rotation of the normalised columns
  if (mm.kind != companion::ScaleKind::NonUniform && !mm.sheared) {
    out.scale = mm.uniformScale();  // negative for a reflection: a point reflection
  } else if (leaf && !mm.sheared) {
    out.residual = mm.scale;        // matrix = motor * diag(scale), exact on a leaf
    f.nonUniform = true;
  } else {
    // Not representable: keep the volume and the orientation sign.
    const glm::vec3 s = mm.scale;
    out.scale = (mm.negative ? -1.0f : 1.0f) * std::cbrt(std::fabs(s.x * s.y * s.z));
    f.nonUniform = mm.kind == companion::ScaleKind::NonUniform;
    f.nonUniformInner = f.nonUniform;
  }
  if (flags) *flags = f;
  return out;
}

[[gnu::flatten]] ScaledMotor blend(const ScaledMotor& a, const ScaledMotor& b, float w) {
  const float wb = mk().dot(a.motor[0], b.motor[0]) < 0.0f ? -w : w;
  ScaledMotor out;
  out.motor = mk().normalize_m(a.motor * (1.0f - w) + b.motor * wb);
  out.scale = a.scale + (b.scale - a.scale) * w;
  out.residual = glm::mix(a.residual, b.residual, w);
  return out;
}

glm::vec3 applyToPoint(const ScaledMotor& x, const glm::vec3& p) {
  const glm::vec3 q = p * x.residual * x.scale;
  MK::vec3 r = mk().sw_mp(x.motor, MK::vec3(q.x, q.y, q.z));
  return {r.x, r.y, r.z};
}

}  // namespace mb::motor
