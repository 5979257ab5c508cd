// Shared pieces of the `motorbench bench` kernels (harness/bench/bench_*.cpp): naming, sizes, data
// generation, counters. Every kernel family registers its matrix, motor and glm variants
// under one name with the side last ("point/in_cache/matrix", "point/in_cache/motor",
// "point/in_cache/glm"), so that pairs sort and read side by side.
//
// Fairness rules the kernels follow:
//  - matrix and motor both execute the shader source compiled through the shim with float
//    (harness/bench/bench_shaders.h), built with the same flags: SIMD on both or neither;
//  - "glm" is GLM's own operators on the matrix side, an extra labelled baseline;
//  - "simd_matrix" / "simd_motor" are kernels/simd's hand-vectorised forms of the same math,
//    the same care on both sides (kernels/simd/README.md);
//  - per-vertex kernels process the same number of vertices on each side (items/s compare
//    directly) and count the bytes each side actually reads and writes (bytes/s).
#pragma once
#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <new>
#include <random>
#include <string>
#include <vector>

#include "harness/bench/bench_shaders.h"

namespace mb::bench {

using MS = MatrixShader<float>;
using PS = MotorShader<float>;

// The sides of every kernel pair, in registration order.
inline const char* const kMatrix = "matrix";
inline const char* const kMotor = "motor";
inline const char* const kGlm = "glm";
// kernels/simd (Highway, runtime dispatch): the matrix and motor math hand-vectorised over
// structure-of-arrays batches; simd_affine: the mat4x3 form where it differs from simd_matrix.
inline const char* const kSimdMatrix = "simd_matrix";
inline const char* const kSimdAffine = "simd_affine";
inline const char* const kSimdMotor = "simd_motor";
// The 4-lane motor product the motor pipelines' CPU update runs (pipelines/motor/gp_motors.h),
// one product at a time as GLM's mat4 product is on the matrix side (compose).
inline const char* const kLanesMotor = "lanes_motor";

// Which side of a pair a name is: a matrix implementation (matrix, glm, simd_matrix,
// simd_affine), a motor one (motor, simd_motor, lanes_motor), or neither ("").
const char* sideKind(const std::string& side);

// Working-set classes of the per-vertex kernels.
enum class Size { InCache, OutOfCache };
inline const char* sizeName(Size s) { return s == Size::InCache ? "in_cache" : "out_of_cache"; }

// In cache: about 16 KiB for the larger side. Out of cache: at least 256 MiB for the smaller
// side (far beyond this machine's last-level cache), so both sides stream from memory.
inline constexpr size_t kInCacheBytes = 16u << 10;
inline constexpr size_t kOutOfCacheBytes = 256u << 20;

// Vertices per pass: the same count for both sides of a pair, from the bytes per vertex each
// side moves (largest for in-cache, smallest for out-of-cache), rounded up to 64.
inline size_t vertexCount(Size s, size_t smallBytesPerItem, size_t largeBytesPerItem) {
  const size_t n = s == Size::InCache ? kInCacheBytes / largeBytesPerItem
                                      : (kOutOfCacheBytes + smallBytesPerItem - 1) / smallBytesPerItem;
  return (n + 63) / 64 * 64;
}

// The arrays of type T for size class `s`, built with `n` elements on first use and kept for
// the process (the big ones are allocated once, whatever the repetitions).
template <class T> T& perSize(Size s, size_t n) {
  if (s == Size::InCache) {
    static T small(n);
    return small;
  }
  static T big(n);
  return big;
}

// 64-byte aligned storage for the planar batches of the simd sides (kernels/simd streams its
// stores only to aligned planes).
template <class T> struct Aligned64 {
  using value_type = T;
  Aligned64() = default;
  template <class U> Aligned64(const Aligned64<U>&) {}  // NOLINT: rebinding
  T* allocate(size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), std::align_val_t(64))); }
  void deallocate(T* p, size_t) { ::operator delete(p, std::align_val_t(64)); }
  template <class U> bool operator==(const Aligned64<U>&) const { return true; }
};
template <class T> using AlignedVector = std::vector<T, Aligned64<T>>;

// Planar (structure-of-arrays) batches of n items: the distance between two component planes,
// in floats. Rounded up to 1024 floats and then shifted by one cache line, so that planes do
// not start at the same 4 KiB offset (with a power-of-two distance every plane's item i falls
// in the same cache set and the ~20 streams of a vertex kernel evict each other).
inline size_t planeStride(size_t n) { return (n + 1023) / 1024 * 1024 + 16; }

// Registers `fn` as benchmark "name" (time in ns, items/s and bytes/s set by the kernel), with
// the machine's load sampled before and after each run as these counters (1-minute load
// average and runnable threads, harness/timing/disturbance.h; -1 where unreadable).
inline const char* const kLoadBefore = "load_avg1_before";
inline const char* const kRunnableBefore = "runnable_before";
inline const char* const kLoadAfter = "load_avg1_after";
inline const char* const kRunnableAfter = "runnable_after";
void registerKernel(const std::string& name, std::function<void(benchmark::State&)> fn);

// Sets items/s and bytes/s for `items` items and `bytes` bytes per iteration; for out-of-cache
// kernels also "bw_fraction" (bytes/s over the bandwidth probe's best) and "probe_GBps", and
// kCopyFraction (bytes/s over the probe's STREAM copy) and "copy_GBps". Both fractions are rate
// counters: their value is the plain fraction (kCopyFraction: bandwidth_probe.h).
void setThroughput(benchmark::State& state, size_t items, size_t bytes, Size size);

// Labels the run with the Highway target the simd kernels dispatch to ("AVX3", "AVX2", ...).
void setSimdLabel(benchmark::State& state);

// Times one call of `pass` (a SIMD kernel over the whole batch, writing `out`) per iteration,
// then labels the run with the SIMD target and sets its throughput (setThroughput).
template <class F>
void timeSimdPass(benchmark::State& state, const void* out, size_t items, size_t bytes, Size size, F pass) {
  for (auto _ : state) {
    pass();
    benchmark::DoNotOptimize(out);
    benchmark::ClobberMemory();
  }
  setSimdLabel(state);
  setThroughput(state, items, bytes, size);
}

// Deterministic data.
struct Rng {
  std::mt19937 gen{12345};
  float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(gen); }
  int index(int n) { return std::uniform_int_distribution<int>(0, n - 1)(gen); }
};

// A unit quaternion as a glTF (x, y, z, w) and its rotor [w, -x, -y, -z].
struct Quat {
  float x, y, z, w;
};
Quat randomQuat(Rng& r);
inline PS::vec4 rotorOf(const Quat& q) { return PS::vec4(q.w, -q.x, -q.y, -q.z); }
// Rotation matrix columns of a unit quaternion (used to build consistent matrix/motor inputs).
void quatColumns(const Quat& q, float c0[3], float c1[3], float c2[3]);

// A rigid transform both ways: the motor T R and the column-major 4x4 matrix of the same
// motion (with uniform scale `s` applied before it); normal matrix = rotation / s, with
// [3][3] = 1 (no mirror).
struct Transform {
  PS::motor motor;
  float scale = 1.0f;
  float matrix[16], normal[16];
};
Transform randomTransform(Rng& r, float scale = 1.0f);

inline MS::mat4 toShim(const float* m16) {
  MS::mat4 m;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m[c][r] = m16[c * 4 + r];
  return m;
}

}  // namespace mb::bench
