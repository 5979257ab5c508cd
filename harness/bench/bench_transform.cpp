// compose, point, direction: the building blocks. Matrix side: matrix_transform.glsl's
// matrixCompose / matrixTransformPoint / matrixTransformDirection (full mat4, the Sample
// Viewer's); motor side: pga.glsl's gp_mm / sw_mp / sw_md; glm: GLM's mat4 operators.
// simd_*: kernels/simd on planar copies of the same data: point / direction rows 0..2 of the
// affine mat4 vs sw_mp / sw_md; compose mat4 (matrixCompose), affine (mat4x3, the same product
// on affine operands) and gp_mm.
#include <glm/glm.hpp>

#include "pipelines/motor/gp_motors.h"
#include "harness/bench/bench_common.h"
#include "harness/bench/bench_kernels.h"
#include "kernels/simd/simd_kernels.h"

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

void composeLanesMotor(benchmark::State& state) {
  ComposeData& d = composeData();
  composePass(state, d.pa, d.pb, d.po, [](const PS::motor& a, const PS::motor& b) { return motor::gpMotors(a, b); });
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


// ---- simd sides --------------------------------------------------------------------------

// Planar copies of the compose pairs: mat4 (16 planes), mat4x3 (12), motor (8).
struct ComposePlanes {
  std::vector<float> a16, b16, a12, b12, a8, b8, out;
  ComposePlanes() : a16(16 * kComposePairs), b16(16 * kComposePairs), a12(12 * kComposePairs),
                    b12(12 * kComposePairs), a8(8 * kComposePairs), b8(8 * kComposePairs), out(16 * kComposePairs) {
    const ComposeData& d = composeData();
    const size_t n = kComposePairs;
    for (size_t i = 0; i < n; ++i)
      for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) a16[size_t(c * 4 + r) * n + i] = d.ma[i][c][r], b16[size_t(c * 4 + r) * n + i] = d.mb[i][c][r];
        for (int r = 0; r < 3; ++r) a12[size_t(c * 3 + r) * n + i] = d.ma[i][c][r], b12[size_t(c * 3 + r) * n + i] = d.mb[i][c][r];
        if (c < 2)
          for (int r = 0; r < 4; ++r) a8[size_t(c * 4 + r) * n + i] = d.pa[i][c][r], b8[size_t(c * 4 + r) * n + i] = d.pb[i][c][r];
      }
  }
};

template <class K> void composeSimd(benchmark::State& state, size_t floats, K kernel) {
  static ComposePlanes p;
  timeSimdPass(state, p.out.data(), kComposePairs, kComposePairs * 3 * floats * sizeof(float), Size::InCache,
               [&] { kernel(p); });
}

void composeSimdMat4(benchmark::State& state) {
  composeSimd(state, 16, [](ComposePlanes& p) {
    simd::composeMat4({p.a16.data(), kComposePairs}, {p.b16.data(), kComposePairs}, {p.out.data(), kComposePairs}, kComposePairs);
  });
}
void composeSimdAffine(benchmark::State& state) {
  composeSimd(state, 12, [](ComposePlanes& p) {
    simd::composeAffine({p.a12.data(), kComposePairs}, {p.b12.data(), kComposePairs}, {p.out.data(), kComposePairs}, kComposePairs);
  });
}
void composeSimdMotor(benchmark::State& state) {
  composeSimd(state, 8, [](ComposePlanes& p) {
    simd::composeMotor({p.a8.data(), kComposePairs}, {p.b8.data(), kComposePairs}, {p.out.data(), kComposePairs}, kComposePairs);
  });
}

// Planar copies of the vec3 arrays (3 planes in, 3 out).
struct Vec3Planes {
  size_t n, stride;
  AlignedVector<float> in, out;
  explicit Vec3Planes(const Vec3Arrays& a) : n(a.in.size()), stride(planeStride(n)), in(3 * stride), out(3 * stride) {
    for (size_t i = 0; i < n; ++i) in[i] = a.in[i].x, in[stride + i] = a.in[i].y, in[2 * stride + i] = a.in[i].z;
  }
};

Vec3Planes& vec3Planes(Size s) {
  if (s == Size::InCache) {
    static Vec3Planes small(vec3Arrays(s));
    return small;
  }
  static Vec3Planes big(vec3Arrays(s));
  return big;
}

template <Kind K> void vec3Simd(benchmark::State& state, Size s, bool motor) {
  const PerDraw pd;
  float m16[16], m8[8];
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m16[c * 4 + r] = pd.m[c][r];
  for (int k = 0; k < 4; ++k) m8[k] = pd.motor[0][k], m8[4 + k] = pd.motor[1][k];
  Vec3Planes& p = vec3Planes(s);
  const simd::ConstPlanes in{p.in.data(), p.stride};
  const simd::Planes out{p.out.data(), p.stride};
  timeSimdPass(state, p.out.data(), p.n, p.n * kVec3Bytes, s, [&] {
    if (K == Kind::Point) motor ? simd::pointsMotor(m8, in, out, p.n) : simd::pointsMatrix(m16, in, out, p.n);
    else motor ? simd::directionsMotor(m8, in, out, p.n) : simd::directionsMatrix(m16, in, out, p.n);
  });
}

}  // namespace

void registerTransformBenchmarks() {
  registerKernel("compose/matrix", composeMatrix);
  registerKernel("compose/motor", composeMotor);
  registerKernel("compose/glm", composeGlm);
  registerKernel(std::string("compose/") + kLanesMotor, composeLanesMotor);
  registerKernel(std::string("compose/") + kSimdMatrix, composeSimdMat4);
  registerKernel(std::string("compose/") + kSimdAffine, composeSimdAffine);
  registerKernel(std::string("compose/") + kSimdMotor, composeSimdMotor);
  for (Size s : {Size::InCache, Size::OutOfCache}) {
    const std::string p = std::string("point/") + sizeName(s) + "/";
    registerKernel(p + kMatrix, [s](benchmark::State& st) { vec3Matrix<Kind::Point>(st, s); });
    registerKernel(p + kMotor, [s](benchmark::State& st) { vec3Motor<Kind::Point>(st, s); });
    registerKernel(p + kGlm, [s](benchmark::State& st) { vec3Glm<Kind::Point>(st, s); });
    registerKernel(p + kSimdMatrix, [s](benchmark::State& st) { vec3Simd<Kind::Point>(st, s, false); });
    registerKernel(p + kSimdMotor, [s](benchmark::State& st) { vec3Simd<Kind::Point>(st, s, true); });
  }
  for (Size s : {Size::InCache, Size::OutOfCache}) {
    const std::string p = std::string("direction/") + sizeName(s) + "/";
    registerKernel(p + kMatrix, [s](benchmark::State& st) { vec3Matrix<Kind::Direction>(st, s); });
    registerKernel(p + kMotor, [s](benchmark::State& st) { vec3Motor<Kind::Direction>(st, s); });
    registerKernel(p + kGlm, [s](benchmark::State& st) { vec3Glm<Kind::Direction>(st, s); });
    registerKernel(p + kSimdMatrix, [s](benchmark::State& st) { vec3Simd<Kind::Direction>(st, s, false); });
    registerKernel(p + kSimdMotor, [s](benchmark::State& st) { vec3Simd<Kind::Direction>(st, s, true); });
  }
}

}  // namespace mb::bench
