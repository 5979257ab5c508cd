#include "harness/bench/compose_timing.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <functional>

#include <glm/glm.hpp>

#include "harness/bench/bench_common.h"
#include "harness/bench/affine_compose.h"

namespace mb::bench {
namespace {

using Clock = std::chrono::steady_clock;
// In cache on every side; not a multiple of 64, so that the arrays of a side (48 or 64 bytes an
// element) do not start at the same offset within a 4 KiB page: with 256, a store to out[i] and
// the loads of a[i + 1], b[i + 1] alias in the low 12 address bits and the affine side ran 4x slower.
constexpr size_t kPairs = 251;

// The same random rigid transforms (uniform scale 1) in each side's own type.
// An affine transform as 12 plain floats, column-major (linear part, then translation): the
// hand-written C++ an engine would use; the shim's vec3 columns compile to slower code.
struct Affine12 {
  float m[12];
};

Affine12 composePlain(const Affine12& a, const Affine12& b) {
  Affine12 r;
  for (int c = 0; c < 4; ++c)
    for (int k = 0; k < 3; ++k)
      r.m[3 * c + k] = a.m[k] * b.m[3 * c] + a.m[3 + k] * b.m[3 * c + 1] + a.m[6 + k] * b.m[3 * c + 2] + (c == 3 ? a.m[9 + k] : 0.0f);
  return r;
}

struct Data {
  std::vector<PS::motor> motorA, motorB, motorOut;
  std::vector<MS::mat4> mat4A, mat4B, mat4Out;
  std::vector<MS::mat4x3> affA, affB, affOut;
  std::vector<glm::mat4> glmA, glmB, glmOut;
  std::vector<glm::mat4x3> gaffA, gaffB, gaffOut;
  std::vector<Affine12> plainA, plainB, plainOut;
  Data() {
    Rng r;
    auto add = [&](std::vector<PS::motor>& m, std::vector<MS::mat4>& x, std::vector<MS::mat4x3>& a,
                   std::vector<glm::mat4>& g, std::vector<glm::mat4x3>& ga) {
      const Transform t = randomTransform(r);
      m.push_back(t.motor);
      x.push_back(toShim(t.matrix));
      MS::mat4x3 s;
      glm::mat4 gm;
      for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 4; ++k) {
          gm[c][k] = t.matrix[c * 4 + k];
          if (k < 3) s[c][k] = t.matrix[c * 4 + k];
        }
      a.push_back(s), g.push_back(gm), ga.push_back(glm::mat4x3(gm));
    };
    for (size_t i = 0; i < kPairs; ++i) add(motorA, mat4A, affA, glmA, gaffA), add(motorB, mat4B, affB, glmB, gaffB);
    motorOut.resize(kPairs), mat4Out.resize(kPairs), affOut.resize(kPairs), glmOut.resize(kPairs), gaffOut.resize(kPairs);
    auto plain = [](const MS::mat4x3& x) {
      Affine12 p;
      for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 3; ++k) p.m[3 * c + k] = x[c][k];
      return p;
    };
    for (size_t i = 0; i < kPairs; ++i) plainA.push_back(plain(affA[i])), plainB.push_back(plain(affB[i]));
    plainOut.resize(kPairs);
  }
};

template <class T, class Op>
[[gnu::flatten]] void pass(const std::vector<T>& a, const std::vector<T>& b, std::vector<T>& out, Op op, int repeats) {
  for (int r = 0; r < repeats; ++r) {
    for (size_t i = 0; i < kPairs; ++i) out[i] = op(a[i], b[i]);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

}  // namespace

ComposeTiming timeCompositions(int rounds, double blockMs) {
  static Data d;
  static PS P;
  static MS S;
  using Side = std::pair<std::string, std::function<void(int)>>;
  const std::vector<Side> sides = {
      {"motor", [](int n) { pass(d.motorA, d.motorB, d.motorOut, [](const PS::motor& a, const PS::motor& b) { return P.gp_mm(a, b); }, n); }},
      {"mat4", [](int n) { pass(d.mat4A, d.mat4B, d.mat4Out, [](const MS::mat4& a, const MS::mat4& b) { return S.matrixCompose(a, b); }, n); }},
      {"affine", [](int n) { pass(d.affA, d.affB, d.affOut, [](const MS::mat4x3& a, const MS::mat4x3& b) { return affineCompose<float>(a, b); }, n); }},
      {"glm_mat4", [](int n) { pass(d.glmA, d.glmB, d.glmOut, [](const glm::mat4& a, const glm::mat4& b) { return a * b; }, n); }},
      {"glm_affine", [](int n) {
         pass(d.gaffA, d.gaffB, d.gaffOut, [](const glm::mat4x3& a, const glm::mat4x3& b) {
           const glm::mat3 A(a);
           const glm::mat3 L = A * glm::mat3(b);
           return glm::mat4x3(L[0], L[1], L[2], A * b[3] + a[3]);
         }, n);
       }},
      {"affine_plain", [](int n) { pass(d.plainA, d.plainB, d.plainOut, composePlain, n); }},
  };
  ComposeTiming out;
  out.rounds = std::max(1, rounds), out.pairs = int(kPairs);
  // Calibrate on the motor side: repeats so that one block lasts about blockMs.
  int repeats = 1;
  for (;;) {
    const auto t0 = Clock::now();
    sides[0].second(repeats);
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    if (ms >= blockMs || repeats >= (1 << 20)) break;
    repeats *= 2;
  }
  out.repeats = repeats;
  std::vector<std::vector<double>> ns(sides.size());
  for (int r = 0; r < out.rounds; ++r)
    for (size_t k = 0; k < sides.size(); ++k) {
      const size_t s = (k + size_t(r)) % sides.size();  // rotating order
      const auto t0 = Clock::now();
      sides[s].second(repeats);
      ns[s].push_back(std::chrono::duration<double, std::nano>(Clock::now() - t0).count() / (double(repeats) * kPairs));
    }
  for (size_t s = 0; s < sides.size(); ++s) {
    out.sides.push_back(sides[s].first);
    out.nsPerCompose[sides[s].first] = median(ns[s]);
    std::vector<double> ratio;
    for (int r = 0; r < out.rounds; ++r) ratio.push_back(ns[s][size_t(r)] / ns[0][size_t(r)]);
    out.ratioToMotor[sides[s].first] = median(ratio);
  }
  return out;
}

}  // namespace mb::bench
