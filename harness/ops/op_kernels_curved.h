// harness/ops/op_kernels_curved.h: the curved-space rows of `motorbench ops`:
// shaders/pga_kappa.glsl per curvature, executed on mb::Counted, beside the 4x4 matrix rows.
// kappa = 0 rows claim pga.glsl's counts (the kappa-generic source reproduces them); kappa = +-1
// rows have no claim (no paper figure). Header-only, like op_kernels.h.
#pragma once
#include <vector>

#include "harness/ops/op_count.h"
#include "shaders/shim/counted.h"
#include "shaders/shim/pga_kappa.h"

namespace mb::ops {

namespace detail {
template <int K> struct KappaInputs {
  using P = PgaK<Counted, K>;
  typename P::motor a, b;
  typename P::vec4 p;
  KappaInputs()
      : a(typename P::vec4(0.5, 0.1, 0.2, 0.3), typename P::vec4(0.4, 0.5, 0.6, 0.7)),
        b(typename P::vec4(0.7, 0.6, 0.5, 0.4), typename P::vec4(0.3, 0.2, 0.1, 0.9)),
        p(0.1, 0.2, 0.3, 0.9) {}
};
}  // namespace detail

inline std::vector<Kernel> curvedKernels() {
  static const detail::KappaInputs<1> s;
  static const detail::KappaInputs<-1> h;
  static const detail::KappaInputs<0> e;
  auto& PS = pgaK<Counted, 1>;
  auto& PH = pgaK<Counted, -1>;
  auto& PE = pgaK<Counted, 0>;
  const auto same = [](int m, int a) { return Claim{m, a, "pga.glsl"}; };
  return {
      {"pga-kappa", "E:gp_mm_k", "kappa = 0: motor * motor (= gp_mm)", same(48, 40),
       [&PE] { PE.gp_mm_k(e.a, e.b); }},
      {"pga-kappa", "E:sw_mp_k", "kappa = 0: M p ~M (= sw_mp)", same(21, 18),
       [&PE] { PE.sw_mp_k(e.a, typename detail::KappaInputs<0>::P::vec3(0.1, 0.2, 0.3)); }},
      {"pga-kappa", "S3:gp_mm_k", "S3 motor * motor (PGA layout)", std::nullopt,
       [&PS] { PS.gp_mm_k(s.a, s.b); }},
      {"pga-kappa", "S3:sw_mp_k", "S3 M p ~M, p = (x, y, z, w)", std::nullopt,
       [&PS] { PS.sw_mp_k(s.a, s.p); }},
      {"pga-kappa", "S3:normalize_m_k", "S3 M / |M|", std::nullopt, [&PS] { PS.normalize_m_k(s.a); }},
      {"pga-kappa", "S3:gp_pair", "S3 motor * motor as quaternion pairs", std::nullopt,
       [&PS] { PS.gp_pair(s.a, s.b); }},
      {"pga-kappa", "S3:sw_pair", "S3 R X L (quaternion pair sandwich)", std::nullopt,
       [&PS] { PS.sw_pair(s.a, s.p); }},
      {"pga-kappa", "S3:normalize_pair", "S3 pair renormalisation", std::nullopt,
       [&PS] { PS.normalize_pair(s.a); }},
      {"pga-kappa", "S3:pair_from_motor", "PGA layout -> quaternion pair", std::nullopt,
       [&PS] { PS.pair_from_motor(s.a); }},
      {"pga-kappa", "H3:gp_mm_k", "H3 motor * motor", std::nullopt, [&PH] { PH.gp_mm_k(h.a, h.b); }},
      {"pga-kappa", "H3:sw_mp_k", "H3 M p ~M, p = (x, y, z, w)", std::nullopt,
       [&PH] { PH.sw_mp_k(h.a, h.p); }},
      {"pga-kappa", "H3:normalize_m_k", "H3 M / |M| (second order)", std::nullopt,
       [&PH] { PH.normalize_m_k(h.a); }},
  };
}

}  // namespace mb::ops
