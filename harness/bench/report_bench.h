// Kernel throughput for the report and the claims: `motorbench bench` (Google Benchmark, the
// matrix/motor/glm kernel pairs of harness/bench/bench_*.cpp) is run as a child process into a JSON
// file, or a JSON written earlier (e.g. by scripts/reproduce.sh) is read; the pairs are then
// reduced to motor/matrix throughput ratios in and out of cache.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "pipelines/result.h"

namespace mb::bench {

// Runs `motorbench bench --out outJson --benchmark_min_time=minTime` (console output to
// `logPath`); `filter` (a --benchmark_filter regex) may be empty.
Status runBench(const std::string& outJson, const std::string& logPath, double minTime,
                const std::string& filter = "");

Result<nlohmann::json> readBenchJson(const std::string& path);

// Google Benchmark JSON -> {"context": {...}, "pairs": [...], "probe": [...]}. Names are
// "<kernel>[/<size>]/<side>" with side matrix|motor|glm|simd_matrix|simd_affine|simd_motor; one
// figure per benchmark (the median aggregate when repeated). Each pair: kernel, size (in_cache |
// out_of_cache | null), per side items_per_second, bytes_per_second, bw_fraction (out of
// cache: bytes/s over the STREAM probe's best), copy_fraction (over its copy), label (simd: the
// Highway target); ratios of items/s
// (> 1: the first faster): ratio_motor_matrix and ratio_glm_matrix (to the shim matrix),
// ratio_simd_motor_matrix (simd_motor / simd_matrix), and fastest_matrix / fastest_motor (the
// side with the most items/s of each kind) with ratio_motor_fastest_matrix (fastest motor /
// fastest matrix).
// Each pair also carries "machine" (a CPU figure names its CPU and SIMD target):
// {"cpu", "logicalCores"} from the bench JSON's context and "simdTarget", the Highway target the
// pair's SIMD sides ran on (their label; null for a pair without SIMD sides).
nlohmann::json kernelPairs(const nlohmann::json& bench);

// "AMD EPYC (2 logical cores, Highway AVX3)" for a pair of kernelPairs, for text beside a CPU
// figure or verdict; "an unrecorded CPU" for a pair without "machine" (a report written before).
std::string pairMachineText(const nlohmann::json& pair);

}  // namespace mb::bench
