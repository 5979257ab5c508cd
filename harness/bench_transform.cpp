// compose, point, direction: the building blocks. Matrix side: matrix_transform.glsl's
// matrixCompose / matrixTransformPoint / matrixTransformDirection (full mat4, the Sample
// Viewer's); motor side: pga.glsl's gp_mm / sw_mp / sw_md; glm: GLM's mat4 operators.
#include <glm/glm.hpp>

#include "harness/bench_common.h"
#include "harness/bench_kernels.h"

namespace mb::bench {
namespace {

struct Vec3f {
  float x, y, z;
};

// Every kernel is [[gnu::flatten]]: the shader functions are inlined into the loops on every
// side alike (see bench_vertex.cpp).

// ---- compose: N pairs in cache -------------------------------------------------------------

constexpr size_t kComposePairs = 256;

struct ComposeData {
  std::vector<MS::mat4> ma, mb, mo;
  std::vector<PS::motor> pa, pb, po;
  std::vector<glm::mat4> ga, gb, go;
  ComposeData() {
    Rng r;
    for (size_t i = 0; i < kComposePairs; ++i) {
      const Transform a = randomTransform(r), b = randomTransform(r);
      ma.push_back(toShim(a.matrix)), mb.push_back(toShim(b.matrix));
      pa.push_back(a.motor), pb.push_back(b.motor);
      glm::mat4 x, y;
      for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 4; ++k) x[c][k] = a.matrix[c * 4 + k], y[c][k] = b.matrix[c * 4 + k];
      ga.push_back(x), gb.push_back(y);
    }
    mo.resize(kComposePairs), po.resize(kComposePairs), go.resize(kComposePairs);
  }
};

ComposeData& composeData() {
  static ComposeData d;
  return d;
}

[[gnu::flatten]] void composeMatrix(benchmark::State& state) {
  ComposeData& d = composeData();
  MS S;
  for (auto _ : state) {
    for (size_t i = 0; i < kComposePairs; ++i) d.mo[i] = S.matrixCompose(d.ma[i], d.mb[i]);
    benchmark::DoNotOptimize(d.mo.data());
    benchmark::ClobberMemory();
  }
  setThroughput(state, kComposePairs, kComposePairs * 3 * sizeof(MS::mat4), Size::InCache);
}

[[gnu::flatten]] void composeMotor(benchmark::State& state) {
  ComposeData& d = composeData();
  PS P;
  for (auto _ : state) {
    for (size_t i = 0; i < kComposePairs; ++i) d.po[i] = P.gp_mm(d.pa[i], d.pb[i]);
    benchmark::DoNotOptimize(d.po.data());
    benchmark::ClobberMemory();
  }
  setThroughput(state, kComposePairs, kComposePairs * 3 * sizeof(PS::motor), Size::InCache);
}

[[gnu::flatten]] void composeGlm(benchmark::State& state) {
  ComposeData& d = composeData();
  for (auto _ : state) {
    for (size_t i = 0; i < kComposePairs; ++i) d.go[i] = d.ga[i] * d.gb[i];
    benchmark::DoNotOptimize(d.go.data());
    benchmark::ClobberMemory();
  }
  setThroughput(state, kComposePairs, kComposePairs * 3 * sizeof(glm::mat4), Size::InCache);
}

// ---- point / direction: one per-draw transform, N vec3 in, N vec3 out ----------------------

constexpr size_t kVec3Bytes = 2 * sizeof(Vec3f);  // read + write per item

struct Vec3Arrays {
  std::vector<Vec3f> in, out;
  explicit Vec3Arrays(size_t n) : in(n), out(n) {
    Rng r;
    for (Vec3f& v : in) v = {r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
  }
};

// Allocated once per size, on first use (both kinds and all sides share them).
Vec3Arrays& vec3Arrays(Size s) {
  const size_t n = vertexCount(s, kVec3Bytes, kVec3Bytes);
  if (s == Size::InCache) {
    static Vec3Arrays small(n);
    return small;
  }
  static Vec3Arrays big(n);
  return big;
}

struct PerDraw {
  MS::mat4 m;
  PS::motor motor;
  glm::mat4 g;
  PerDraw() {
    Rng r;
    const Transform t = randomTransform(r);
    m = toShim(t.matrix), motor = t.motor;
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 4; ++k) g[c][k] = t.matrix[c * 4 + k];
  }
};

enum class Kind { Point, Direction };

// One function per side; `kind` selects point (w = 1) or direction (w = 0).
template <Kind K> [[gnu::flatten]] void vec3Matrix(benchmark::State& state, Size s) {
  Vec3Arrays& a = vec3Arrays(s);
  const PerDraw draw;
  MS S;
  const size_t n = a.in.size();
  for (auto _ : state) {
    for (size_t i = 0; i < n; ++i) {
      const MS::vec3 v(a.in[i].x, a.in[i].y, a.in[i].z);
      const MS::vec4 r = K == Kind::Point ? S.matrixTransformPoint(draw.m, v)
                                          : S.matrixTransformDirection(draw.m, v);
      a.out[i] = {r.x, r.y, r.z};
    }
    benchmark::DoNotOptimize(a.out.data());
    benchmark::ClobberMemory();
  }
  setThroughput(state, n, n * kVec3Bytes, s);
}

template <Kind K> [[gnu::flatten]] void vec3Motor(benchmark::State& state, Size s) {
  Vec3Arrays& a = vec3Arrays(s);
  const PerDraw draw;
  PS P;
  const size_t n = a.in.size();
  for (auto _ : state) {
    for (size_t i = 0; i < n; ++i) {
      const PS::vec3 v(a.in[i].x, a.in[i].y, a.in[i].z);
      const PS::vec3 r = K == Kind::Point ? P.sw_mp(draw.motor, v) : P.sw_md(draw.motor, v);
      a.out[i] = {r.x, r.y, r.z};
    }
    benchmark::DoNotOptimize(a.out.data());
    benchmark::ClobberMemory();
  }
  setThroughput(state, n, n * kVec3Bytes, s);
}

template <Kind K> [[gnu::flatten]] void vec3Glm(benchmark::State& state, Size s) {
  Vec3Arrays& a = vec3Arrays(s);
  const PerDraw draw;
  const size_t n = a.in.size();
  const float w = K == Kind::Point ? 1.0f : 0.0f;
  for (auto _ : state) {
    for (size_t i = 0; i < n; ++i) {
      const glm::vec4 r = draw.g * glm::vec4(a.in[i].x, a.in[i].y, a.in[i].z, w);
      a.out[i] = {r.x, r.y, r.z};
    }
    benchmark::DoNotOptimize(a.out.data());
    benchmark::ClobberMemory();
  }
  setThroughput(state, n, n * kVec3Bytes, s);
}

}  // namespace

void registerTransformBenchmarks() {
  registerKernel("compose/matrix", composeMatrix);
  registerKernel("compose/motor", composeMotor);
  registerKernel("compose/glm", composeGlm);
  for (Size s : {Size::InCache, Size::OutOfCache}) {
    const std::string sz = sizeName(s);
    registerKernel("point/" + sz + "/matrix", [s](benchmark::State& st) { vec3Matrix<Kind::Point>(st, s); });
    registerKernel("point/" + sz + "/motor", [s](benchmark::State& st) { vec3Motor<Kind::Point>(st, s); });
    registerKernel("point/" + sz + "/glm", [s](benchmark::State& st) { vec3Glm<Kind::Point>(st, s); });
  }
  for (Size s : {Size::InCache, Size::OutOfCache}) {
    const std::string sz = sizeName(s);
    registerKernel("direction/" + sz + "/matrix", [s](benchmark::State& st) { vec3Matrix<Kind::Direction>(st, s); });
    registerKernel("direction/" + sz + "/motor", [s](benchmark::State& st) { vec3Motor<Kind::Direction>(st, s); });
    registerKernel("direction/" + sz + "/glm", [s](benchmark::State& st) { vec3Glm<Kind::Direction>(st, s); });
  }
}

}  // namespace mb::bench
