// Helpers shared by the PGA, ops and pipeline tests: seeded random motors built from GLM quaternions and
// translations (GLM in double precision is the independent reference), conversions, and an
// error tracker that reports the worst error relative to its float-precision tolerance.
#pragma once
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "shaders/shim/pga.h"

namespace mbtest {

template <class S> using P = mb::Pga<S>;
template <class S> using Motor = typename P<S>::motor;
template <class S> using Vec3 = typename P<S>::vec3;

inline constexpr int kCases = 100000;

// Machine epsilon of the scalar type: the unit of every tolerance.
template <class S> constexpr double eps() { return std::numeric_limits<S>::epsilon(); }

inline double uniform(std::mt19937& g, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(g);
}
inline glm::dvec3 randomVec(std::mt19937& g, double lo, double hi) {
  return {uniform(g, lo, hi), uniform(g, lo, hi), uniform(g, lo, hi)};
}
// Uniform on the unit sphere S^3 (normalised Gaussian 4-vector).
inline glm::dquat randomQuat(std::mt19937& g) {
  std::normal_distribution<double> n;
  glm::dquat q(n(g), n(g), n(g), n(g));
  return glm::normalize(q);
}
inline glm::dvec3 randomUnit(std::mt19937& g) {
  std::normal_distribution<double> n;
  return glm::normalize(glm::dvec3(n(g), n(g), n(g)));
}

template <class S> Vec3<S> vec3Of(const glm::dvec3& v) { return Vec3<S>(S(v.x), S(v.y), S(v.z)); }
template <class S> glm::dvec3 toD(const Vec3<S>& v) { return {double(v.x), double(v.y), double(v.z)}; }

// glTF mappings, written out independently of the toolbox: quaternion (x,y,z,w) -> rotor
// [w,-x,-y,-z], translation t -> [1,0,0,0,-t/2,0].
template <class S> Motor<S> rotorOf(const glm::dquat& q) {
  using V4 = typename P<S>::vec4;
  return Motor<S>(V4(S(q.w), S(-q.x), S(-q.y), S(-q.z)), V4(S(0)));
}
template <class S> Motor<S> translatorOf(const glm::dvec3& t) {
  using V4 = typename P<S>::vec4;
  return Motor<S>(V4(S(1), S(0), S(0), S(0)), V4(S(-0.5 * t.x), S(-0.5 * t.y), S(-0.5 * t.z), S(0)));
}
// Node motor T R in precision S (composed in double, rounded once).
template <class S> Motor<S> trsMotor(const glm::dquat& q, const glm::dvec3& t) {
  return Motor<S>(mb::pga<double>.gp_tr(translatorOf<double>(t), rotorOf<double>(q)));
}
inline glm::dmat4 trsMatrix(const glm::dquat& q, const glm::dvec3& t) {
  return glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(q);
}

// The 4x4 matrix of a normalised motor, from its sandwiches of the basis (in precision S).
template <class S> glm::dmat4 matrixOf(const Motor<S>& M) {
  P<S>& p = mb::pga<S>;
  return glm::dmat4(glm::dvec4(2.0 * toD<S>(p.sw_mx(M)), 0.0), glm::dvec4(2.0 * toD<S>(p.sw_my(M)), 0.0),
                    glm::dvec4(2.0 * toD<S>(p.sw_mz(M)), 0.0), glm::dvec4(toD<S>(p.sw_mo(M)), 1.0));
}

template <class S, int C, int R> double maxDiff(const glsl::mat<S, C, R>& a, const glsl::mat<S, C, R>& b) {
  double m = 0;
  for (int i = 0; i < C; ++i)
    for (int j = 0; j < R; ++j) m = std::max(m, std::abs(double(a[i][j]) - double(b[i][j])));
  return m;
}
template <class S, int C, int R> double maxAbs(const glsl::mat<S, C, R>& a) {
  double m = 0;
  for (int i = 0; i < C; ++i)
    for (int j = 0; j < R; ++j) m = std::max(m, std::abs(double(a[i][j])));
  return m;
}
inline double maxDiff(const glm::dmat4& a, const glm::dmat4& b) {
  double m = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) m = std::max(m, std::abs(a[i][j] - b[i][j]));
  return m;
}
inline double maxDiff(const glm::dvec3& a, const glm::dvec3& b) {
  return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}
// |a - b| up to the sign of b (motors M and -M are the same transformation).
template <class S> double diffUpToSign(const Motor<S>& a, const Motor<S>& b) {
  return std::min(maxDiff(a, b), maxDiff(a, Motor<S>(-b)));
}

// Worst error / tolerance over many cases; EXPECT ratio() <= 1.
struct Tracker {
  double worst = 0;
  int worstCase = -1;
  std::string what;
  void check(double err, double tol, int caseIndex) {
    const double r = std::isfinite(err) ? err / tol : std::numeric_limits<double>::infinity();
    if (r > worst || worstCase < 0) worst = r, worstCase = caseIndex;
  }
  double ratio() const { return worst; }
  // MB_TEST_VERBOSE=1 prints every tracker's worst ratio (how tight each tolerance is).
  ~Tracker() {
    if (std::getenv("MB_TEST_VERBOSE") && worstCase >= 0) std::printf("  [tolerance use] %s\n", report().c_str());
  }
  std::string report() const {
    return "worst error = " + std::to_string(worst) + " x tolerance at case " + std::to_string(worstCase);
  }
};

}  // namespace mbtest
