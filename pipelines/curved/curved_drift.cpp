#include "pipelines/curved/curved_drift.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "pipelines/curved/curved_motor.h"
#include "pipelines/scene/curved_space.h"
#include "shaders/shim/pga_kappa.h"

namespace mb::curved {

template <class Mat> void gramSchmidt(int kappa, Mat& m) {
  using S = std::remove_cvref_t<decltype(m[0][0])>;
  // kappa = +-1 enters as a sign (free), as on the motor side.
  auto form = [&](const auto& a, const auto& b) {
    const S xyz = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    return kappa > 0 ? xyz + a[3] * b[3] : xyz - a[3] * b[3];
  };
  const int order[4] = {3, 0, 1, 2};  // the origin's image first (timelike in H3)
  for (int n = 0; n < 4; ++n) {
    auto& c = m[order[n]];
    for (int p = 0; p < n; ++p) {  // remove the parts along the columns already done
      const auto& q = m[order[p]];
      const S fq = form(c, q);     // / form(q, q) = +-1: kappa for the w column, 1 otherwise
      const S f = (p == 0 && kappa < 0) ? -fq : fq;
      for (int r = 0; r < 4; ++r) c[r] = c[r] - f * q[r];
    }
    const S fc = form(c, c);
    const S len = (n == 0 && kappa < 0) ? -fc : fc;
    const S inv = glsl::scalar_ops<S>::inversesqrt(len);  // as the motor side: one call
    for (int r = 0; r < 4; ++r) c[r] = c[r] * inv;
  }
}
template void gramSchmidt(int, glm::mat4&);
template void gramSchmidt(int, double (&)[4][4]);
template void gramSchmidt(int, Counted (&)[4][4]);

double matrixDistance(int kappa, const glm::mat4& m) {
  double worst = 0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      const glm::dvec4 a(m[c]), b(m[r]);
      const double f = a.x * b.x + a.y * b.y + a.z * b.z + kappa * a.w * b.w;
      const double d = std::abs(f - (c == r ? (c == 3 ? double(kappa) : 1.0) : 0.0));
      worst = d == d ? std::max(worst, d) : HUGE_VAL;  // NaN: as far as it gets
    }
  return worst;
}

double motorDistance(int kappa, const float (&m)[8]) {
  auto sq = [&](int o) {
    double s = 0;
    for (int i = 0; i < 4; ++i) s += double(m[o + i]) * m[o + i];
    return s;
  };
  if (kappa > 0) return std::max(std::abs(sq(0) - 1.0), std::abs(sq(4) - 1.0));
  const double n = sq(0) - sq(4);  // |a0|^2 + kappa |a1|^2
  const double e = double(m[7]) * m[0] - (double(m[4]) * m[1] + double(m[5]) * m[2] + double(m[6]) * m[3]);
  const double d = std::max(std::abs(n - 1.0), std::abs(2.0 * e));
  return d == d ? d : HUGE_VAL;
}

namespace {

template <int K> DriftResult run(int64_t steps) {
  DriftResult r;
  r.kappa = K;
  r.steps = steps;
  // One step: a turn of 2e-3 rad and a move of 1e-3 forward, in double, rounded once: a
  // circle of geodesic curvature 2 (closed in H3 too, where curvature <= 1 runs off to
  // infinity), radius atan(1/2) in S3, atanh(1/2) in H3.
  const glm::dmat4 stepD = elementaryMatrix(K, 0, 2, 2e-3) * elementaryMatrix(K, 2, 3, -1e-3);
  const Motor8 stepU = shaderMotor(K, compose(K, elementaryMotor(K, 0, 2, 2e-3), elementaryMotor(K, 2, 3, -1e-3)));
  using M = typename PgaK<float, K>::mat2x4;
  using V4 = typename PgaK<float, K>::vec4;
  auto& pk = pgaK<float, K>;
  const M stepMotor{V4(float(stepU[0]), float(stepU[1]), float(stepU[2]), float(stepU[3])),
                    V4(float(stepU[4]), float(stepU[5]), float(stepU[6]), float(stepU[7]))};
  const glm::mat4 stepMatrix(stepD);
  // The motor side's step and renormalisation on the pga of any scalar (S3: on the pair).
  auto composeMotor = [](auto& pga, const auto& a, const auto& b) {
    if constexpr (K > 0) return pga.gp_pair(a, b); else return pga.gp_mm_k(a, b);
  };
  auto renormMotor = [](auto& pga, const auto& a) {
    if constexpr (K > 0) return pga.normalize_pair(a); else return pga.normalize_m_k(a);
  };
  const M identity(V4(1.0f, 0.0f, 0.0f, 0.0f), V4(K > 0 ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f));
  for (int renorm = 0; renorm < 2; ++renorm) {
    glm::mat4 v(1.0f);
    M mv = identity;
    for (int64_t n = 0; n < steps; ++n) {
      v = stepMatrix * v;
      mv = composeMotor(pk, stepMotor, mv);
      if (renorm) {
        gramSchmidt(K, v);
        mv = renormMotor(pk, mv);
      }
    }
    float arr[8];
    for (int i = 0; i < 8; ++i) arr[i] = float(mv[i / 4][i % 4]);
    (renorm ? r.matrix.renormalised : r.matrix.raw) = matrixDistance(K, v);
    (renorm ? r.motor.renormalised : r.motor.raw) = motorDistance(K, arr);
  }
  // Op counts of one step and one renormalisation, by execution on mb::Counted.
  {
    using C = Counted;
    auto& pc = pgaK<C, K>;
    using MC = typename PgaK<C, K>::mat2x4;
    using VC = typename PgaK<C, K>::vec4;
    const MC a(VC(C(0.9), C(0.1), C(0.2), C(0.3)), VC(C(0.1), C(0.2), C(0.3), C(0.4)));
    r.motor.stepOps = countOps([&] { composeMotor(pc, a, a); });
    r.motor.renormOps = countOps([&] { renormMotor(pc, a); });
    using M4 = typename PgaK<C, K>::mat4;
    const M4 m4(C(1.0));
    r.matrix.stepOps = countOps([&] { M4 p = m4 * m4; (void)p; });
    C g[4][4];
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 4; ++k) g[c][k] = C(c == k ? 1.0 : 0.01 * (c + k));
    r.matrix.renormOps = countOps([&] { gramSchmidt(K, g); });
  }
  return r;
}

}  // namespace

DriftResult measureDrift(int kappa, int64_t steps) { return kappa > 0 ? run<1>(steps) : run<-1>(steps); }

}  // namespace mb::curved
