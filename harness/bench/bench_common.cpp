#include "harness/bench/bench_common.h"

#include <cmath>

#include "harness/bench/bandwidth_probe.h"
#include "harness/timing/disturbance.h"
#include "kernels/simd/simd_targets.h"

namespace mb::bench {

void registerKernel(const std::string& name, std::function<void(benchmark::State&)> fn) {
  benchmark::RegisterBenchmark(name.c_str(), [fn](benchmark::State& s) {
    // The machine's load around the run (harness/timing/disturbance.h): with the run's CPU and
    // real time, report_bench judges whether the figure was disturbed.
    const timing::LoadSample before = timing::sampleLoad();
    fn(s);
    const timing::LoadSample after = timing::sampleLoad();
    s.counters[kLoadBefore] = before.average1, s.counters[kRunnableBefore] = before.runnable;
    s.counters[kLoadAfter] = after.average1, s.counters[kRunnableAfter] = after.runnable;
  })->Unit(benchmark::kMicrosecond);
}

const char* sideKind(const std::string& side) {
  if (side == kMatrix || side == kGlm || side == kSimdMatrix || side == kSimdAffine) return "matrix";
  if (side == kMotor || side == kSimdMotor || side == kLanesMotor) return "motor";
  return "";
}

void setSimdLabel(benchmark::State& state) { state.SetLabel(simd::currentTarget().name); }

void setThroughput(benchmark::State& state, size_t items, size_t bytes, Size size) {
  const auto iters = int64_t(state.iterations());
  state.SetItemsProcessed(iters * int64_t(items));
  if (bytes) {
    state.SetBytesProcessed(iters * int64_t(bytes));
    state.counters["working_set_bytes"] = double(bytes);
  }
  if (size == Size::OutOfCache && bytes) {
    // Rate counters divide by the measured time: (bytes / probe) per second = fraction (the
    // console shows it without a rate suffix: harness/cli/cmd_bench.cpp).
    const double probe = referenceBandwidth().best(), copy = referenceBandwidth().copyBytesPerSecond;
    state.counters["bw_fraction"] =
        benchmark::Counter(double(bytes) / probe, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["probe_GBps"] = probe / 1e9;
    // STREAM copy alone (the yardstick of a streaming kernel: >= 0.7 of it out of cache), same
    // process and arrays.
    state.counters[kCopyFraction] =
        benchmark::Counter(double(bytes) / copy, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["copy_GBps"] = copy / 1e9;
  }
}

Quat randomQuat(Rng& r) {
  // Marsaglia: uniform on the 3-sphere.
  float x, y, z, w, s1, s2;
  do { x = r.uniform(-1, 1), y = r.uniform(-1, 1), s1 = x * x + y * y; } while (s1 >= 1.0f);
  do { z = r.uniform(-1, 1), w = r.uniform(-1, 1), s2 = z * z + w * w; } while (s2 >= 1.0f || s2 == 0.0f);
  const float k = std::sqrt((1.0f - s1) / s2);
  return {x, y, z * k, w * k};
}

void quatColumns(const Quat& q, float c0[3], float c1[3], float c2[3]) {
  const float x = q.x, y = q.y, z = q.z, w = q.w;
  c0[0] = 1 - 2 * (y * y + z * z), c0[1] = 2 * (x * y + z * w), c0[2] = 2 * (x * z - y * w);
  c1[0] = 2 * (x * y - z * w), c1[1] = 1 - 2 * (x * x + z * z), c1[2] = 2 * (y * z + x * w);
  c2[0] = 2 * (x * z + y * w), c2[1] = 2 * (y * z - x * w), c2[2] = 1 - 2 * (x * x + y * y);
}

Transform randomTransform(Rng& r, float scale) {
  const Quat q = randomQuat(r);
  const float t[3] = {r.uniform(-5, 5), r.uniform(-5, 5), r.uniform(-5, 5)};
  Transform out;
  out.scale = scale;
  PS P;
  const PS::motor R(rotorOf(q), PS::vec4(0.0f));
  const PS::motor T(PS::vec4(1.0f, 0.0f, 0.0f, 0.0f), PS::vec4(-0.5f * t[0], -0.5f * t[1], -0.5f * t[2], 0.0f));
  out.motor = P.gp_tr(T, R);
  float c[3][3];
  quatColumns(q, c[0], c[1], c[2]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      out.matrix[i * 4 + j] = c[i][j] * scale;
      out.normal[i * 4 + j] = c[i][j] / scale;
    }
  for (int i = 0; i < 3; ++i) {
    out.matrix[i * 4 + 3] = 0.0f, out.normal[i * 4 + 3] = 0.0f;
    out.matrix[12 + i] = t[i], out.normal[12 + i] = 0.0f;
  }
  out.matrix[15] = 1.0f, out.normal[15] = 1.0f;
  return out;
}

}  // namespace mb::bench
