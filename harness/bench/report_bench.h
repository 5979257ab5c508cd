// Kernel throughput for the report and the claims: `motorbench bench` (Google Benchmark, the
// matrix/motor/glm kernel pairs of harness/bench/bench_*.cpp) is run as a child process into a JSON
// file, or a JSON written earlier (e.g. by scripts/reproduce.sh) is read; the pairs are then
// reduced to motor/matrix throughput ratios in and out of cache.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "pipelines/result.h"

namespace mb::report {

// Runs `motorbench bench --out outJson --benchmark_min_time=minTime` (console output to
// `logPath`); `filter` (a --benchmark_filter regex) may be empty.
Status runBench(const std::string& outJson, const std::string& logPath, double minTime,
                const std::string& filter = "");

Result<nlohmann::json> readBenchJson(const std::string& path);

// Google Benchmark JSON -> {"context": {...}, "pairs": [...], "probe": [...]}. Names are
// "<kernel>[/<size>]/<side>" with side matrix|motor|glm; one figure per benchmark (the median
// aggregate when repeated). Each pair: kernel, size (in_cache | out_of_cache | null), per side
// items_per_second, bytes_per_second, bw_fraction (out of cache: bytes/s over the STREAM
// probe), and ratio_motor_matrix / ratio_glm_matrix of items/s (> 1: faster than matrix).
nlohmann::json kernelPairs(const nlohmann::json& bench);

}  // namespace mb::report
