#include "pipelines/curved/curved_motor.h"

#include <cmath>
#include <string>

#include <glm/gtc/quaternion.hpp>

#include "pipelines/scene/curved_space.h"
#include "shaders/shim/pga_kappa.h"

namespace mb::curved {
namespace {

template <int K> using P = PgaK<double, K>;
template <int K> using M = typename P<K>::motor;

template <int K> M<K> toShim(const Motor8& a) {
  using V4 = typename P<K>::vec4;
  return M<K>(V4(a[0], a[1], a[2], a[3]), V4(a[4], a[5], a[6], a[7]));
}
template <int K> Motor8 fromShim(const M<K>& a) {
  return {a[0].x, a[0].y, a[0].z, a[0].w, a[1].x, a[1].y, a[1].z, a[1].w};
}

template <int K> Motor8 composeK(const Motor8& a, const Motor8& b) {
  return fromShim<K>(pgaK<double, K>.gp_mm_k(toShim<K>(a), toShim<K>(b)));
}
template <int K> glm::dvec4 sandwichK(const Motor8& m, const glm::dvec4& p) {
  auto r = pgaK<double, K>.sw_mp_k(toShim<K>(m), typename P<K>::vec4(p.x, p.y, p.z, p.w));
  return {r.x, r.y, r.z, r.w};
}
template <int K> Motor8 translatorK(double dist, const glm::dvec3& u) {
  return fromShim<K>(pgaK<double, K>.translator_k(dist, typename P<K>::vec3(u.x, u.y, u.z)));
}

Motor8 reverse(const Motor8& a) { return {a[0], -a[1], -a[2], -a[3], -a[4], -a[5], -a[6], a[7]}; }

}  // namespace

Motor8 compose(int kappa, const Motor8& a, const Motor8& b) {
  return kappa > 0 ? composeK<1>(a, b) : composeK<-1>(a, b);
}

glm::dvec4 sandwich(int kappa, const Motor8& m, const glm::dvec4& p) {
  return kappa > 0 ? sandwichK<1>(m, p) : sandwichK<-1>(m, p);
}

glm::dmat4 matrixOfMotor(int kappa, const Motor8& m) {
  glm::dmat4 r;
  for (int c = 0; c < 4; ++c) {
    glm::dvec4 e(0.0);
    e[c] = 1.0;
    r[c] = sandwich(kappa, m, e);
  }
  return r;
}

Motor8 elementaryMotor(int kappa, int i, int j, double angle) {
  if (j < 3) {  // e_i turns towards e_j: about the axis e_i x e_j; glTF rotor [w, -x, -y, -z]
    glm::dvec3 a(0.0), b(0.0);
    a[i] = 1.0, b[j] = 1.0;
    const glm::dquat q = glm::angleAxis(angle, glm::cross(a, b));
    return {q.w, -q.x, -q.y, -q.z, 0, 0, 0, 0};
  }
  glm::dvec3 u(0.0);
  u[i] = 1.0;
  return kappa > 0 ? translatorK<1>(angle, u) : translatorK<-1>(angle, u);
}

Result<Motor8> motorOfMatrix(int kappa, const glm::dmat4& m) {
  const glm::dvec4 o = m[3];  // where the origin goes
  const glm::dvec3 xyz(o);
  const double r = glm::length(xyz);
  if (kappa < 0 && o.w <= 0.0)
    return Result<Motor8>::fail("isometry reverses time orientation (w of the origin's image <= 0)");
  const double dist = kappa > 0 ? std::atan2(r, o.w) : std::asinh(r);
  const glm::dvec3 u = r > 0.0 ? xyz / r : glm::dvec3(1, 0, 0);  // any axis when it stays put
  const Motor8 t = kappa > 0 ? translatorK<1>(dist, u) : translatorK<-1>(dist, u);
  const glm::dmat4 rest = matrixOfMotor(kappa, reverse(t)) * m;  // fixes the origin
  const glm::dquat q = glm::quat_cast(glm::dmat3(rest));
  const Motor8 motor = compose(kappa, t, {q.w, -q.x, -q.y, -q.z, 0, 0, 0, 0});
  const glm::dmat4 back = matrixOfMotor(kappa, motor);
  double worst = 0.0;
  for (int c = 0; c < 4; ++c)
    for (int k = 0; k < 4; ++k) worst = std::max(worst, std::abs(back[c][k] - m[c][k]) / (1.0 + std::abs(m[c][k])));
  if (!(worst <= 1e-6))
    return Result<Motor8>::fail("not an orientation-preserving isometry of the space (motor "
                                "round trip differs by " + std::to_string(worst) + ")");
  return motor;
}

Motor8 shaderMotor(int kappa, const Motor8& m) {
  return kappa > 0 ? fromShim<1>(pgaK<double, 1>.pair_from_motor(toShim<1>(m))) : m;
}

Motor8 viewMotor(const CurvedScene& scene, double t) {
  const int k = kappaOf(scene.space);
  Motor8 v = {1, 0, 0, 0, 0, 0, 0, 0};
  for (const CurvedMove& mv : scene.camera)  // (E1 E2 ... En)^-1 = En^-1 ... E1^-1
    v = compose(k, elementaryMotor(k, mv.i, mv.j, -(mv.angle0 + mv.rate * t)), v);
  return v;
}

}  // namespace mb::curved
