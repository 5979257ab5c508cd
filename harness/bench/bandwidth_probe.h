// A STREAM-style memory-bandwidth probe (McCalpin's copy and triad on double arrays, each
// array several times the last-level cache) in the motorbench binary, so that out-of-cache
// kernels can be reported as a fraction of what this machine moves from one core. Bytes are
// counted as STREAM does: copy c[i] = a[i] moves 16 bytes per element, triad
// a[i] = b[i] + s * c[i] 24 (write-allocate traffic not counted, like the kernels' bytes).
#pragma once
#include <cstddef>

namespace mb::bench {

struct Bandwidth {
  double copyBytesPerSecond = 0, triadBytesPerSecond = 0;
  // Copy with non-temporal (streaming) stores, which skip the write-allocate read: the form the
  // SIMD kernels use for large outputs (kernels/simd), so the reference is what they could reach.
  double copyStreamingBytesPerSecond = 0;
  size_t arrayBytes = 0;  // per array (three arrays)
  // The reference for "fraction of bandwidth": the best of the three.
  double best() const {
    const double b = copyBytesPerSecond > triadBytesPerSecond ? copyBytesPerSecond : triadBytesPerSecond;
    return b > copyStreamingBytesPerSecond ? b : copyStreamingBytesPerSecond;
  }
};

// The out-of-cache kernels' counter: bytes/s over the probe's copy (bench_common.h).
inline const char* const kCopyFraction = "copy_fraction";

// Array size: four times the last-level cache (sysconf), at least 64 MiB.
size_t streamArrayBytes();

// Runs copy, streaming copy and triad `passes` times each over three arrays of `arrayBytes`;
// best pass of each.
Bandwidth measureBandwidth(size_t arrayBytes = streamArrayBytes(), int passes = 5);

// measureBandwidth() once per process, on first use (single-threaded, like the kernels).
const Bandwidth& referenceBandwidth();

// "stream/copy", "stream/copy_nt" and "stream/triad" as Google Benchmark kernels (bytes/s in the
// JSON).
void registerBandwidthBenchmarks();

}  // namespace mb::bench
