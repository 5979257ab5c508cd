// harness/ops/op_kernels.h: the rows of `motorbench ops`: every kernel of shaders/pga.glsl and the
// matrix equivalents, each executed on mb::Counted through the GLSL shim, with the claim it is
// compared against. Header-only (tests count the same table). Extend by appending Kernels.
#pragma once
#include <vector>

#include "harness/ops/op_count.h"
#include "shaders/shim/counted.h"
#include "shaders/shim/pga.h"
#include "harness/ops/op_kernels_curved.h"

namespace mb::ops {

namespace detail {

using PD = Pga<double>;
using PC = Pga<Counted>;

// Fixed, generic inputs (no zero coefficients, so no branch or product is skipped), built in
// double and converted: a normalised general motor T R, a rotor, a translator, a point.
struct Inputs {
  PC::motor m, m2, r, r2, t, t2, unnormalised;
  PC::vec3 p, d, v1, v2;
  PC::line B;
  Inputs() {
    PD& P = pga<double>;
    auto rotor = [&](double w, double x, double y, double z) {
      return P.normalize_m(PD::motor(PD::vec4(w, -x, -y, -z), PD::vec4(0.0)));
    };
    auto trans = [](double x, double y, double z) {
      return PD::motor(PD::vec4(1.0, 0.0, 0.0, 0.0), PD::vec4(-0.5 * x, -0.5 * y, -0.5 * z, 0.0));
    };
    const PD::motor R1 = rotor(0.8, 0.3, -0.4, 0.2), R2 = rotor(0.1, -0.7, 0.5, 0.4);
    const PD::motor T1 = trans(1.5, -2.0, 0.75), T2 = trans(-0.25, 3.0, 1.25);
    r = PC::motor(R1), r2 = PC::motor(R2), t = PC::motor(T1), t2 = PC::motor(T2);
    m = PC::motor(P.gp_tr(T1, R1)), m2 = PC::motor(P.gp_tr(T2, R2));
    unnormalised = PC::motor(P.gp_tr(T1, R1) * 1.7 + PD::motor(PD::vec4(0.0), PD::vec4(0.0, 0.0, 0.0, 0.3)));
    p = PC::vec3(0.5, -1.25, 2.0), d = PC::vec3(0.6, 0.0, 0.8) + PC::vec3(0.0, 0.1, 0.0);
    v1 = PC::vec3(0.2, 0.9, -0.3), v2 = PC::vec3(-0.5, 0.4, 0.7);
    B = PC::line(PC::vec3(0.4, -0.3, 0.5), PC::vec3(1.0, 2.0, -0.5));
  }
};

}  // namespace detail

inline std::vector<Kernel> pgaKernels() {
  using detail::PC;
  static const detail::Inputs in;
  PC& P = pga<Counted>;
  const auto paper = [](int m, int a) { return Claim{m, a, "paper"}; };
  const auto refsrc = [](int m, int a) { return Claim{m, a, "ref-src"}; };
  const auto paperX = [](int m, int a) { return Claim{m, a, "paper(x)"}; };
  return {
      {"pga", "gp_mm", "motor * motor", paper(48, 40), [&P] { P.gp_mm(in.m, in.m2); }},
      {"pga", "gp_rr", "rotor * rotor", paper(16, 12), [&P] { P.gp_rr(in.r, in.r2); }},
      {"pga", "gp_tt", "translator * translator", paper(0, 3), [&P] { P.gp_tt(in.t, in.t2); }},
      {"pga", "gp_rt", "rotor * translator", paper(12, 8), [&P] { P.gp_rt(in.r, in.t); }},
      {"pga", "gp_tr", "translator * rotor", paper(12, 8), [&P] { P.gp_tr(in.t, in.r); }},
      {"pga", "gp_rm", "rotor * motor", paper(32, 24), [&P] { P.gp_rm(in.r, in.m); }},
      {"pga", "gp_mr", "motor * rotor", paper(32, 24), [&P] { P.gp_mr(in.m, in.r); }},
      {"pga", "gp_tm", "translator * motor", paper(12, 12), [&P] { P.gp_tm(in.t, in.m); }},
      {"pga", "gp_mt", "motor * translator", paper(12, 12), [&P] { P.gp_mt(in.m, in.t); }},
      {"pga", "gp_vv", "vector * vector (planes through origin)", std::nullopt,
       [&P] { P.gp_vv(in.v1, in.v2); }},
      {"pga", "sw_mp_naive", "M p ~M, two full products", paper(33, 29),
       [&P] { P.sw_mp_naive(in.m, in.p); }},
      {"pga", "sw_mp", "M p ~M using M~M = 1", paper(21, 18), [&P] { P.sw_mp(in.m, in.p); }},
      {"pga", "sw_md", "M d ~M (direction)", paper(18, 12), [&P] { P.sw_md(in.m, in.d); }},
      {"pga", "sw_mx", "M e032 ~M / 2 (x axis)", paper(6, 4), [&P] { P.sw_mx(in.m); }},
      {"pga", "sw_my", "M e013 ~M / 2 (y axis)", paperX(6, 4), [&P] { P.sw_my(in.m); }},
      {"pga", "sw_mz", "M e021 ~M / 2 (z axis)", paperX(6, 4), [&P] { P.sw_mz(in.m); }},
      {"pga", "sw_mo", "M e123 ~M (origin)", refsrc(15, 9), [&P] { P.sw_mo(in.m); }},
      {"pga", "extractNormalTangent", "normal + tangent / 2 from a frame rotor", paper(9, 8),
       [&P] { P.extractNormalTangent(in.r); }},
      {"pga", "reverse_m", "~M", refsrc(0, 0), [&P] { P.reverse_m(in.m); }},
      {"pga", "normalize_m", "M / |M| (Study number)", paper(21, 5),
       [&P] { P.normalize_m(in.unnormalised); }},
      {"pga", "sqrt_m", "sqrt(M) = normalize(1 + M)", paper(21, 6), [&P] { P.sqrt_m(in.m); }},
      {"pga", "exp_b", "exp(line) -> motor", paper(17, 8), [&P] { P.exp_b(in.B); }},
      {"pga", "log_m", "log(motor) -> line", paper(14, 5), [&P] { P.log_m(in.m); }},
      {"pga", "exp_r", "rotor from angle + line", refsrc(3, 0), [&P] { P.exp_r(0.7, in.B); }},
      {"pga", "exp_t", "translator from distance + line", refsrc(3, 0), [&P] { P.exp_t(0.7, in.B); }},
      {"pga", "project", "perspective projection (incl. per-draw constants)", std::nullopt,
       [&P] { P.project(0.04, 400.0, 0.45, 1.5, in.p); }},
  };
}

inline std::vector<Kernel> matrixKernels() {
  using detail::PC;
  static const PC::mat4 A(PC::vec4(0.9, 0.1, -0.4, 0.0), PC::vec4(-0.2, 0.95, 0.3, 0.0),
                          PC::vec4(0.4, -0.3, 0.85, 0.0), PC::vec4(1.5, -2.0, 0.75, 1.0));
  static const PC::mat4 B = A * A;
  static const PC::mat3 R(A);
  static const PC::mat3x4 affineRows(PC::vec4(0.9, -0.2, 0.4, 1.5), PC::vec4(0.1, 0.95, -0.3, -2.0),
                                     PC::vec4(-0.4, 0.3, 0.85, 0.75));
  static const PC::vec4 v(0.5, -1.25, 2.0, 1.0);
  static const PC::vec3 v3(0.5, -1.25, 2.0);
  const auto paper = [](int m, int a) { return Claim{m, a, "paper"}; };
  return {
      {"matrix", "mat4*mat4", "4x4 composition", paper(64, 48), [] { (void)(A * B); }},
      {"matrix", "mat3*mat3", "3x3 composition (rotations)", std::nullopt, [] { (void)(R * R); }},
      {"matrix", "mat4*vec4", "full 4x4 transform", paper(16, 12), [] { (void)(A * v); }},
      {"matrix", "mat3*vec3", "3x3 transform (normal matrix)", std::nullopt, [] { (void)(R * v3); }},
      {"matrix", "vec4*mat3x4", "affine 3x4 (rows as columns) * point", std::nullopt,
       [] { (void)(v * affineRows); }},
  };
}

// Every row of `motorbench ops`, in print order.
inline std::vector<Kernel> allKernels() {
  std::vector<Kernel> k = pgaKernels();
  for (Kernel& m : matrixKernels()) k.push_back(std::move(m));
  for (Kernel& c : curvedKernels()) k.push_back(std::move(c));
  return k;
}

}  // namespace mb::ops
