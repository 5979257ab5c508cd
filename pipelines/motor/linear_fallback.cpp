#include "pipelines/motor/linear_fallback.h"

#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "pipelines/motor/companion.h"

namespace mb::motor {
namespace {

// Orthogonal polar factor of M (det M > 0) by the scaled Newton iteration X <- (g X + X^-T / g)/2
// (Higham, "Computing the polar decomposition", 1986), in double so that S = R^T M stays symmetric
// to float precision. Converges quadratically; 30 steps bound a pathological input.
glm::dmat3 polarRotation(const glm::dmat3& m) {
  glm::dmat3 x = m;
  for (int i = 0; i < 30; ++i) {
    const glm::dmat3 inv = glm::inverse(x);
    double nx = 0, ni = 0;
    for (int c = 0; c < 3; ++c) nx += glm::dot(x[c], x[c]), ni += glm::dot(inv[c], inv[c]);
    const double g = std::sqrt(std::sqrt(ni / nx));
    const glm::dmat3 next = 0.5 * (g * x + glm::transpose(inv) / g);
    double change = 0;
    for (int c = 0; c < 3; ++c) change = std::max(change, glm::length(next[c] - x[c]));
    x = next;
    if (change < 1e-12) break;
  }
  return x;
}

glm::mat3 cofactor(const glm::mat3& m) {
  return glm::mat3(glm::cross(m[1], m[2]), glm::cross(m[2], m[0]), glm::cross(m[0], m[1]));
}

}  // namespace

LinearTransform linearFromAffine(const glm::mat4& a) {
  LinearTransform out;
  const glm::mat3 l(a);
  const glm::vec3 t(a[3]);
  const double det = glm::determinant(glm::dmat3(l));
  double scale = 0;
  for (int c = 0; c < 3; ++c) scale = std::max(scale, double(glm::length(l[c])));
  if (!(std::fabs(det) > 1e-18 * scale * scale * scale) || !std::isfinite(det)) {
    out.motor = companion::translator(t);  // singular: no rotation to take out
    out.linear = l;
    out.normalLinear = cofactor(l);
    return out;
  }
  // A reflection is kept in S: R is the polar rotation of sign(det) * l.
  const double sign = det < 0 ? -1.0 : 1.0;
  const glm::dmat3 r = polarRotation(sign * glm::dmat3(l));
  const glm::dmat3 s = glm::transpose(r) * glm::dmat3(l);
  out.motor = mk().gp_tr(companion::translator(t),
                         mk().normalize_m(companion::rotorFromQuat(glm::quat_cast(glm::mat3(r)))));
  out.linear = glm::mat3(s);
  out.normalLinear = glm::mat3(glm::transpose(glm::inverse(s)));
  return out;
}

LinearTransform linearFromScaled(const ScaledMotor& m) {
  LinearTransform out;
  out.motor = m.motor;
  const glm::vec3 s = m.scale * m.residual;
  out.linear = glm::mat3(glm::vec3(s.x, 0, 0), glm::vec3(0, s.y, 0), glm::vec3(0, 0, s.z));
  out.normalLinear = glm::mat3(glm::vec3(1 / s.x, 0, 0), glm::vec3(0, 1 / s.y, 0), glm::vec3(0, 0, 1 / s.z));
  return out;
}

void packLinear(const LinearTransform& t, float* out) {
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) {
      out[4 * c + r] = t.linear[c][r];
      out[12 + 4 * c + r] = t.normalLinear[c][r];
    }
    out[4 * c + 3] = 0.0f;
    out[12 + 4 * c + 3] = 0.0f;
  }
}

glm::mat3 unpackLinear(const float* p) {
  return glm::mat3(p[0], p[1], p[2], p[4], p[5], p[6], p[8], p[9], p[10]);
}

}  // namespace mb::motor
