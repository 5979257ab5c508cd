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

// In cache: a skeleton of 128 joints whose nodes are spread over 256 world transforms (about
// 16 KiB of mat4 worlds). Out of cache: 2^19 joints over 2^20 nodes (GLM's worlds 64 MiB, its
// inverse binds and outputs 32 MiB each; the motor side's smallest stream 16 MiB), far beyond
// the last-level cache, the worlds read in random order as the joints' nodes fall.
size_t paletteJoints(Size s) { return s == Size::InCache ? 128 : size_t(1) << 19; }

struct PaletteData {
  std::vector<int32_t> node;
  std::vector<MS::mat4> world, inverseBind, out;
  std::vector<PS::motor> worldM, inverseBindM, outM;
  std::vector<glm::mat4> worldG, inverseBindG, outG;
  // The SIMD sides' copies (AoS): affine worlds and inverse binds 16 floats, motor worlds
  // kHierarchyMotorFloats (motor, scale 1, unused), motor inverse binds 8; outputs 16 / 8.
  std::vector<float> world16, inverseBind16, worldMotor, inverseBind8, outFloats;
  size_t joints;
  // `jointCount` joints over twice as many nodes.
  explicit PaletteData(size_t jointCount)
      : out(jointCount), outM(jointCount), outG(jointCount), outFloats(16 * jointCount), joints(jointCount) {
    const size_t nodes = 2 * joints;
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
    for (size_t i = 0; i < nodes; ++i)
      add(randomTransform(r), world, worldM, worldG, world16, worldMotor, simd::kHierarchyMotorFloats);
    for (size_t j = 0; j < joints; ++j) {
      add(randomTransform(r), inverseBind, inverseBindM, inverseBindG, inverseBind16, inverseBind8, 8);
      node.push_back(int32_t(r.index(int(nodes))));
    }
  }
};

PaletteData& paletteData(Size s) { return perSize<PaletteData>(s, paletteJoints(s)); }

// One pass over every joint with `joint(d, j)`; `bytes` per joint read and written.
template <class F> [[gnu::flatten]] void palettePass(benchmark::State& state, Size s, size_t bytes, F joint) {
  PaletteData& d = paletteData(s);
  for (auto _ : state) {
    for (size_t j = 0; j < d.joints; ++j) joint(d, j);
    benchmark::ClobberMemory();
  }
  setThroughput(state, d.joints, d.joints * bytes, s);
}

void paletteMatrix(benchmark::State& state, Size s) {
  MS S;
  palettePass(state, s, 3 * sizeof(MS::mat4), [&S](PaletteData& d, size_t j) {
    d.out[j] = S.matrixCompose(d.world[size_t(d.node[j])], d.inverseBind[j]);
  });
}

void paletteMotor(benchmark::State& state, Size s) {
  PS P;
  palettePass(state, s, 3 * sizeof(PS::motor), [&P](PaletteData& d, size_t j) {
    d.outM[j] = P.gp_mm(d.worldM[size_t(d.node[j])], d.inverseBindM[j]);
  });
}

void paletteGlm(benchmark::State& state, Size s) {
  palettePass(state, s, 3 * sizeof(glm::mat4), [](PaletteData& d, size_t j) {
    d.outG[j] = d.worldG[size_t(d.node[j])] * d.inverseBindG[j];
  });
}

// `floats`: per joint, world + inverse bind + out (the world's bytes read, the scale's included).
template <class K> void paletteSimd(benchmark::State& state, Size s, size_t floats, K kernel) {
  PaletteData& d = paletteData(s);
  timeSimdPass(state, d.outFloats.data(), d.joints, d.joints * floats * sizeof(float), s, [&] { kernel(d); });
}

void paletteSimdAffine(benchmark::State& state, Size s) {
  paletteSimd(state, s, 3 * 16, [](PaletteData& d) {
    simd::paletteAffine(d.world16.data(), d.node.data(), d.inverseBind16.data(), d.outFloats.data(), d.joints);
  });
}

void paletteSimdMotor(benchmark::State& state, Size s) {
  paletteSimd(state, s, simd::kHierarchyMotorFloats + 8 + 8, [](PaletteData& d) {
    simd::paletteMotor(d.worldMotor.data(), d.node.data(), d.inverseBind8.data(), d.outFloats.data(), d.joints);
  });
}

}  // namespace

// In cache as "palette/<side>", out of cache as "palette/out_of_cache/<side>".
void registerPaletteBenchmarks() {
  using Fn = void (*)(benchmark::State&, Size);
  const std::pair<const char*, Fn> sides[] = {
      {kMatrix, paletteMatrix}, {kMotor, paletteMotor}, {kGlm, paletteGlm}, {kSimdMatrix, paletteSimdAffine}, {kSimdMotor, paletteSimdMotor}};
  for (Size s : {Size::InCache, Size::OutOfCache})
    for (const auto& [side, fn] : sides)
      registerKernel(std::string(s == Size::InCache ? "palette/" : "palette/out_of_cache/") + side,
                     [s, fn = fn](benchmark::State& st) { fn(st, s); });
}

}  // namespace mb::bench
