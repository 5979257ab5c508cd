// palette: the skin palette out[j] = world[node[j]] * inverseBind[j] for every joint, each
// joint's node world transform read through its index (the pipelines' per-frame skin update).
// Matrix: matrixCompose (matrix_transform.glsl, mat4); motor: gp_mm (pga.glsl); glm: GLM's mat4
// product; simd_matrix: kernels/simd's paletteAffine (an affine inverse bind: the same product),
// simd_motor: paletteMotor, both on the operands as the pipelines hold them: the worlds AoS as
// the SIMD hierarchy kernels write them (affine 16 floats per node, motor 12: its 8 and the
// scale), the inverse binds AoS (mat4 16 floats as glTF stores them, motor 8), out AoS.
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
  // The SIMD sides' copies (AoS): affine worlds and inverse binds 16 floats, motor worlds
  // kHierarchyMotorFloats (motor, scale 1, unused), motor inverse binds 8; outputs 16 / 8.
  std::vector<float> world16, inverseBind16, worldMotor, inverseBind8, outFloats;
  PaletteData() : out(kJoints), outM(kJoints), outG(kJoints), outFloats(16 * kJoints) {
    Rng r;
    auto add = [](const Transform& t, std::vector<MS::mat4>& m, std::vector<PS::motor>& p, std::vector<glm::mat4>& g,
                  std::vector<float>& f16, std::vector<float>& fm, size_t motorFloats) {
      m.push_back(toShim(t.matrix)), p.push_back(t.motor);
      glm::mat4 x;
      for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 4; ++k) x[c][k] = t.matrix[c * 4 + k];
      g.push_back(x);
      f16.insert(f16.end(), t.matrix, t.matrix + 16);
      const size_t at = fm.size();
      fm.resize(at + motorFloats, 0.0f);
      for (int k = 0; k < 4; ++k) fm[at + size_t(k)] = t.motor[0][k], fm[at + 4 + size_t(k)] = t.motor[1][k];
      if (motorFloats > 8) fm[at + 8] = 1.0f;  // the hierarchy's world scale
    };
    for (size_t i = 0; i < kNodes; ++i)
      add(randomTransform(r), world, worldM, worldG, world16, worldMotor, simd::kHierarchyMotorFloats);
    for (size_t j = 0; j < kJoints; ++j) {
      add(randomTransform(r), inverseBind, inverseBindM, inverseBindG, inverseBind16, inverseBind8, 8);
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

// `floats`: per joint, world + inverse bind + out (the world's bytes read, the scale's included).
template <class K> void paletteSimd(benchmark::State& state, size_t floats, K kernel) {
  PaletteData& d = paletteData();
  for (auto _ : state) {
    kernel(d);
    benchmark::DoNotOptimize(d.outFloats.data());
    benchmark::ClobberMemory();
  }
  setSimdLabel(state);
  setThroughput(state, kJoints, kJoints * floats * sizeof(float), Size::InCache);
}

void paletteSimdAffine(benchmark::State& state) {
  paletteSimd(state, 3 * 16, [](PaletteData& d) {
    simd::paletteAffine(d.world16.data(), d.node.data(), d.inverseBind16.data(), d.outFloats.data(), kJoints);
  });
}

void paletteSimdMotor(benchmark::State& state) {
  paletteSimd(state, simd::kHierarchyMotorFloats + 8 + 8, [](PaletteData& d) {
    simd::paletteMotor(d.worldMotor.data(), d.node.data(), d.inverseBind8.data(), d.outFloats.data(), kJoints);
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
