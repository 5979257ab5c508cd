// palette: the skin palette out[j] = world[node[j]] * inverseBind[j] for every joint, each
// joint's node world transform read through its index (the pipelines' per-frame skin update).
// Matrix: matrixCompose (matrix_transform.glsl, mat4); motor: gp_mm (pga.glsl); glm: GLM's mat4
// product; simd_matrix: kernels/simd's paletteAffine (mat4x3 operands: the same product for
// affine transforms), simd_motor: paletteMotor, both on planar copies of the same transforms.
#include <glm/glm.hpp>

#include "harness/bench/bench_common.h"
#include "harness/bench/bench_kernels.h"
#include "kernels/simd/simd_kernels.h"

namespace mb::bench {
namespace {

// A skeleton of kJoints joints whose nodes are spread over kNodes world transforms (in cache:
// about 16 KiB of mat4 worlds).
constexpr size_t kNodes = 256, kJoints = 128;

struct PaletteData {
  std::vector<int32_t> node;
  std::vector<MS::mat4> world, inverseBind, out;
  std::vector<PS::motor> worldM, inverseBindM, outM;
  std::vector<glm::mat4> worldG, inverseBindG, outG;
  // Planar copies: worlds kNodes per plane, inverse binds and outputs kJoints per plane.
  std::vector<float> world12, inverseBind12, world8, inverseBind8, outPlanes;
  PaletteData()
      : out(kJoints), outM(kJoints), outG(kJoints), world12(12 * kNodes), inverseBind12(12 * kJoints),
        world8(8 * kNodes), inverseBind8(8 * kJoints), outPlanes(12 * kJoints) {
    Rng r;
    auto add = [](const Transform& t, std::vector<MS::mat4>& m, std::vector<PS::motor>& p, std::vector<glm::mat4>& g,
                  std::vector<float>& p12, std::vector<float>& p8, size_t count) {
      const size_t i = m.size();
      m.push_back(toShim(t.matrix)), p.push_back(t.motor);
      glm::mat4 x;
      for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 4; ++k) x[c][k] = t.matrix[c * 4 + k];
      g.push_back(x);
      for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 3; ++k) p12[size_t(c * 3 + k) * count + i] = t.matrix[c * 4 + k];
      for (int k = 0; k < 4; ++k) p8[size_t(k) * count + i] = t.motor[0][k], p8[size_t(4 + k) * count + i] = t.motor[1][k];
    };
    for (size_t i = 0; i < kNodes; ++i) add(randomTransform(r), world, worldM, worldG, world12, world8, kNodes);
    for (size_t j = 0; j < kJoints; ++j) {
      add(randomTransform(r), inverseBind, inverseBindM, inverseBindG, inverseBind12, inverseBind8, kJoints);
      node.push_back(int32_t(r.index(int(kNodes))));
    }
  }
};

PaletteData& paletteData() {
  static PaletteData d;
  return d;
}

// One pass over every joint with `joint(d, j)`; `bytes` per joint read and written.
template <class F> [[gnu::flatten]] void palettePass(benchmark::State& state, size_t bytes, F joint) {
  PaletteData& d = paletteData();
  for (auto _ : state) {
    for (size_t j = 0; j < kJoints; ++j) joint(d, j);
    benchmark::ClobberMemory();
  }
  setThroughput(state, kJoints, kJoints * bytes, Size::InCache);
}

void paletteMatrix(benchmark::State& state) {
  MS S;
  palettePass(state, 3 * sizeof(MS::mat4), [&S](PaletteData& d, size_t j) {
    d.out[j] = S.matrixCompose(d.world[size_t(d.node[j])], d.inverseBind[j]);
  });
}

void paletteMotor(benchmark::State& state) {
  PS P;
  palettePass(state, 3 * sizeof(PS::motor), [&P](PaletteData& d, size_t j) {
    d.outM[j] = P.gp_mm(d.worldM[size_t(d.node[j])], d.inverseBindM[j]);
  });
}

void paletteGlm(benchmark::State& state) {
  palettePass(state, 3 * sizeof(glm::mat4), [](PaletteData& d, size_t j) {
    d.outG[j] = d.worldG[size_t(d.node[j])] * d.inverseBindG[j];
  });
}

template <class K> void paletteSimd(benchmark::State& state, size_t floats, K kernel) {
  PaletteData& d = paletteData();
  for (auto _ : state) {
    kernel(d);
    benchmark::DoNotOptimize(d.outPlanes.data());
    benchmark::ClobberMemory();
  }
  setSimdLabel(state);
  setThroughput(state, kJoints, kJoints * 3 * floats * sizeof(float), Size::InCache);
}

void paletteSimdAffine(benchmark::State& state) {
  paletteSimd(state, 12, [](PaletteData& d) {
    simd::paletteAffine({d.world12.data(), kNodes}, d.node.data(), {d.inverseBind12.data(), kJoints},
                        {d.outPlanes.data(), kJoints}, kJoints);
  });
}

void paletteSimdMotor(benchmark::State& state) {
  paletteSimd(state, 8, [](PaletteData& d) {
    simd::paletteMotor({d.world8.data(), kNodes}, d.node.data(), {d.inverseBind8.data(), kJoints},
                       {d.outPlanes.data(), kJoints}, kJoints);
  });
}

}  // namespace

void registerPaletteBenchmarks() {
  registerKernel(std::string("palette/") + kMatrix, paletteMatrix);
  registerKernel(std::string("palette/") + kMotor, paletteMotor);
  registerKernel(std::string("palette/") + kGlm, paletteGlm);
  registerKernel(std::string("palette/") + kSimdMatrix, paletteSimdAffine);
  registerKernel(std::string("palette/") + kSimdMotor, paletteSimdMotor);
}

}  // namespace mb::bench
