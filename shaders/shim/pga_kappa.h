// shaders/shim/pga_kappa.h: shaders/pga_kappa.glsl compiled as C++, one class per curvature:
//   mb::PgaK<S, 0>  Euclidean (e0^2 = 0: the kappa functions are pga.glsl's)
//   mb::PgaK<S, 1>  elliptic / spherical S3 (e0^2 = +1)
//   mb::PgaK<S, -1> hyperbolic H3 (e0^2 = -1)
// Each class also holds pga.glsl's functions (the module includes it). Instances:
//   mb::pgaK<double, -1>.gp_mm_k(a, b)
#pragma once
#include <type_traits>

#include "shaders/shim/glsl.h"

namespace mb {

#define MB_KAPPA 0
#define MB_GLSL_CLASS PgaKappaEuclidean
#include "shaders/shim/glsl_begin.h"
#include "shaders/curved_transform.glsl"
#include "shaders/shim/glsl_end.h"
#undef MB_KAPPA

#define MB_KAPPA 1
#define MB_GLSL_CLASS PgaKappaElliptic
#include "shaders/shim/glsl_begin.h"
#include "shaders/curved_transform.glsl"
#include "shaders/shim/glsl_end.h"
#undef MB_KAPPA

#define MB_KAPPA -1
#define MB_GLSL_CLASS PgaKappaHyperbolic
#include "shaders/shim/glsl_begin.h"
#include "shaders/curved_transform.glsl"
#include "shaders/shim/glsl_end.h"
#undef MB_KAPPA

template <class S, int K>
using PgaK = std::conditional_t<
    K == 0, PgaKappaEuclidean<S>,
    std::conditional_t<(K > 0), PgaKappaElliptic<S>, PgaKappaHyperbolic<S>>>;

template <class S, int K> inline PgaK<S, K> pgaK{};

}  // namespace mb
