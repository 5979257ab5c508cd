// compose, point, direction: the building blocks. Matrix side: matrix_transform.glsl's
// matrixCompose / matrixTransformPoint / matrixTransformDirection (full mat4, the Sample
// Viewer's); motor side: pga.glsl's gp_mm / sw_mp / sw_md; glm: GLM's mat4 operators.
#include <glm/glm.hpp>

#include "harness/bench/bench_common.h"
#include "harness/bench/bench_kernels.h"

namespace mb::bench {
namespace {

struct Vec3f {
  float x, y, z;
};

// Every pass is [[gnu::flatten]]: the shader functions are inlined into the loops on every
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

// One pass composing every pair a[i] b[i] into out[i] with `op`.
template <class T, class Op>
[[gnu::flatten]] void composePass(benchmark::State& state, const std::vector<T>& a,
                                  const std::vector<T>& b, std::vector<T>& out, Op op) {
  for (auto _ : state) {
    for (size_t i = 0; i < kComposePairs; ++i) out[i] = op(a[i], b[i]);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  setThroughput(state, kComposePairs, kComposePairs * 3 * sizeof(T), Size::InCache);
}

void composeMatrix(benchmark::State& state) {
  ComposeData& d = composeData();
  MS S;
  composePass(state, d.ma, d.mb, d.mo, [&S](const MS::mat4& a, const MS::mat4& b) { return S.matrixCompose(a, b); });
}

void composeMotor(benchmark::State& state) {
  ComposeData& d = composeData();
  PS P;
  composePass(state, d.pa, d.pb, d.po, [&P](const PS::motor& a, const PS::motor& b) { return P.gp_mm(a, b); });
}

void composeGlm(benchmark::State& state) {
  ComposeData& d = composeData();
  composePass(state, d.ga, d.gb, d.go, [](const glm::mat4& a, const glm::mat4& b) { return a * b; });
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

// Both kinds and all sides share them.
Vec3Arrays& vec3Arrays(Size s) { return perSize<Vec3Arrays>(s, vertexCount(s, kVec3Bytes, kVec3Bytes)); }

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

// One pass over the vec3 arrays of size `s`: out[i] = op(in[i]), `op` taking and returning
// float x, y, z through the side's own types.
template <class Op> [[gnu::flatten]] void vec3Pass(benchmark::State& state, Size s, Op op) {
  Vec3Arrays& a = vec3Arrays(s);
  const size_t n = a.in.size();
  for (auto _ : state) {
    for (size_t i = 0; i < n; ++i) a.out[i] = op(a.in[i]);
    benchmark::DoNotOptimize(a.out.data());
    benchmark::ClobberMemory();
  }
  setThroughput(state, n, n * kVec3Bytes, s);
}

// `K` selects point (w = 1) or direction (w = 0). The per-draw transform is a local of each
// function (kept in registers, as a uniform on a GPU).
template <Kind K> void vec3Matrix(benchmark::State& state, Size s) {
  const MS::mat4 m = PerDraw().m;
  MS S;
  vec3Pass(state, s, [&](const Vec3f& p) {
    const MS::vec3 v(p.x, p.y, p.z);
    const MS::vec4 r = K == Kind::Point ? S.matrixTransformPoint(m, v) : S.matrixTransformDirection(m, v);
    return Vec3f{r.x, r.y, r.z};
  });
}

template <Kind K> void vec3Motor(benchmark::State& state, Size s) {
  const PS::motor m = PerDraw().motor;
  PS P;
  vec3Pass(state, s, [&](const Vec3f& p) {
    const PS::vec3 v(p.x, p.y, p.z);
    const PS::vec3 r = K == Kind::Point ? P.sw_mp(m, v) : P.sw_md(m, v);
    return Vec3f{r.x, r.y, r.z};
  });
}

template <Kind K> void vec3Glm(benchmark::State& state, Size s) {
  const glm::mat4 m = PerDraw().g;
  const float w = K == Kind::Point ? 1.0f : 0.0f;
  vec3Pass(state, s, [&](const Vec3f& p) {
    const glm::vec4 r = m * glm::vec4(p.x, p.y, p.z, w);
    return Vec3f{r.x, r.y, r.z};
  });
}

}  // namespace

void registerTransformBenchmarks() {
  registerKernel("compose/matrix", composeMatrix);
  registerKernel("compose/motor", composeMotor);
  registerKernel("compose/glm", composeGlm);
  for (Size s : {Size::InCache, Size::OutOfCache}) {
    const std::string p = std::string("point/") + sizeName(s) + "/";
    registerKernel(p + kMatrix, [s](benchmark::State& st) { vec3Matrix<Kind::Point>(st, s); });
    registerKernel(p + kMotor, [s](benchmark::State& st) { vec3Motor<Kind::Point>(st, s); });
    registerKernel(p + kGlm, [s](benchmark::State& st) { vec3Glm<Kind::Point>(st, s); });
  }
  for (Size s : {Size::InCache, Size::OutOfCache}) {
    const std::string p = std::string("direction/") + sizeName(s) + "/";
    registerKernel(p + kMatrix, [s](benchmark::State& st) { vec3Matrix<Kind::Direction>(st, s); });
    registerKernel(p + kMotor, [s](benchmark::State& st) { vec3Motor<Kind::Direction>(st, s); });
    registerKernel(p + kGlm, [s](benchmark::State& st) { vec3Glm<Kind::Direction>(st, s); });
  }
}

}  // namespace mb::bench
