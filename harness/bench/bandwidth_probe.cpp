#include "harness/bench/bandwidth_probe.h"

#include <emmintrin.h>  // SSE2 (every x86-64): _mm_stream_pd
#include <unistd.h>

#include <cstdint>
#include <algorithm>
#include <ctime>
#include <fstream>
#include <memory>
#include <string>

#include "harness/bench/bench_common.h"

namespace mb::bench {
namespace {

size_t lastLevelCacheBytes() {
  // sysfs first: glibc's sysconf(_SC_LEVEL3_CACHE_SIZE) reports 320 MiB on some virtual AMD
  // EPYC machines whose L3 is 32 MiB.
  size_t best = 0;
  for (int i = 0; i < 8; ++i) {
    std::ifstream in("/sys/devices/system/cpu/cpu0/cache/index" + std::to_string(i) + "/size");
    size_t v = 0;
    char unit = 0;
    if (!(in >> v)) continue;
    in >> unit;
    v *= unit == 'K' ? 1024 : unit == 'M' ? 1024 * 1024 : 1;
    best = std::max(best, v);
  }
  if (!best) {
    const long l3 = sysconf(_SC_LEVEL3_CACHE_SIZE), l2 = sysconf(_SC_LEVEL2_CACHE_SIZE);
    best = size_t(l3 > 0 ? l3 : l2 > 0 ? l2 : 32l << 20);
  }
  return best;
}

struct Arrays {
  size_t n = 0;
  std::unique_ptr<double[]> a, b, c;
  explicit Arrays(size_t bytes) : n(bytes / sizeof(double)), a(new double[n]), b(new double[n]), c(new double[n]) {
    // Touch every page before timing (first-touch page faults are not bandwidth).
    for (size_t i = 0; i < n; ++i) a[i] = 1.0, b[i] = 2.0, c[i] = 0.5;
  }
};

// The loops stay in separate non-inlined functions so the compiler cannot fuse or drop passes.
[[gnu::noinline]] void copy(double* __restrict c, const double* __restrict a, size_t n) {
  for (size_t i = 0; i < n; ++i) c[i] = a[i];
}
// c = a with non-temporal stores (16 bytes each), then a store fence.
[[gnu::noinline]] void copyStreaming(double* __restrict c, const double* __restrict a, size_t n) {
  size_t i = 0;
  for (; i < n && (reinterpret_cast<uintptr_t>(c + i) & 15); ++i) c[i] = a[i];
  for (; i + 2 <= n; i += 2) _mm_stream_pd(c + i, _mm_loadu_pd(a + i));
  for (; i < n; ++i) c[i] = a[i];
  _mm_sfence();
}
[[gnu::noinline]] void triad(double* __restrict a, const double* __restrict b,
                             const double* __restrict c, double s, size_t n) {
  for (size_t i = 0; i < n; ++i) a[i] = b[i] + s * c[i];
}

// CPU time of the process, as Google Benchmark times the kernels (their rates are per CPU
// second), so that the fraction compares like with like on a loaded machine.
double cpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

template <class F> double seconds(F f) {
  const double t0 = cpuSeconds();
  f();
  return cpuSeconds() - t0;
}

}  // namespace

size_t streamArrayBytes() {
  // STREAM's rule: each array at least four times the largest cache; bounded for memory.
  return std::clamp(size_t(4) * lastLevelCacheBytes(), size_t(64) << 20, size_t(512) << 20);
}

namespace {
Arrays& sharedArrays() {
  static Arrays arrays(streamArrayBytes());
  return arrays;
}
}  // namespace

Bandwidth measureBandwidth(size_t arrayBytes, int passes) {
  std::unique_ptr<Arrays> own;
  if (arrayBytes != streamArrayBytes()) own = std::make_unique<Arrays>(arrayBytes);
  Arrays& arr = own ? *own : sharedArrays();
  Bandwidth bw;
  bw.arrayBytes = arr.n * sizeof(double);
  double bestCopy = 1e30, bestTriad = 1e30, bestStreaming = 1e30;
  for (int p = 0; p < passes; ++p) {
    bestCopy = std::min(bestCopy, seconds([&] { copy(arr.c.get(), arr.a.get(), arr.n); }));
    bestStreaming = std::min(bestStreaming, seconds([&] { copyStreaming(arr.c.get(), arr.a.get(), arr.n); }));
    bestTriad = std::min(bestTriad, seconds([&] { triad(arr.a.get(), arr.b.get(), arr.c.get(), 3.0, arr.n); }));
  }
  bw.copyBytesPerSecond = double(2 * bw.arrayBytes) / bestCopy;
  bw.triadBytesPerSecond = double(3 * bw.arrayBytes) / bestTriad;
  bw.copyStreamingBytesPerSecond = double(2 * bw.arrayBytes) / bestStreaming;
  return bw;
}

const Bandwidth& referenceBandwidth() {
  static const Bandwidth bw = measureBandwidth();
  return bw;
}

void registerBandwidthBenchmarks() {
  registerKernel("stream/copy", [](benchmark::State& state) {
    Arrays& arr = sharedArrays();
    for (auto _ : state) {
      copy(arr.c.get(), arr.a.get(), arr.n);
      benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(2 * arr.n * sizeof(double)));
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(arr.n));
    state.counters["array_bytes"] = double(arr.n * sizeof(double));
  });
  registerKernel("stream/copy_nt", [](benchmark::State& state) {
    Arrays& arr = sharedArrays();
    for (auto _ : state) {
      copyStreaming(arr.c.get(), arr.a.get(), arr.n);
      benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(2 * arr.n * sizeof(double)));
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(arr.n));
    state.counters["array_bytes"] = double(arr.n * sizeof(double));
  });
  registerKernel("stream/triad", [](benchmark::State& state) {
    Arrays& arr = sharedArrays();
    for (auto _ : state) {
      triad(arr.a.get(), arr.b.get(), arr.c.get(), 3.0, arr.n);
      benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(3 * arr.n * sizeof(double)));
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(arr.n));
    state.counters["array_bytes"] = double(arr.n * sizeof(double));
  });
}

}  // namespace mb::bench
