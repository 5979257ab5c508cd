// `motorbench bench` end to end: the kernels run and write what they promise (JSON with
// items_per_second, the machine and the SIMD target, the bandwidth fraction of an out-of-cache
// kernel printed as a plain number, no escape codes when colour is off) and bad arguments are
// refused. Never asserts timings.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/support/cli_test_support.h"

namespace {

namespace fs = std::filesystem;
using mb::cli_test::exe;
using mb::cli_test::readJson;
using mb::cli_test::runCommand;
using mb::cli_test::scratchFile;

TEST(CliBench, OneCheapKernelWritesJsonWithItemsPerSecond) {
  const fs::path out = scratchFile("bench.json");
  std::string log;
  const int rc = runCommand(exe() + "bench --benchmark_filter='^compose/' --benchmark_min_time=0.01 "
                             "--out '" + out.string() + "'", &log);
  ASSERT_EQ(rc, 0) << log;
  const nlohmann::json j = readJson(out);
  ASSERT_FALSE(j.is_discarded()) << "no JSON written: " << log;
  ASSERT_TRUE(j.contains("benchmarks"));
  std::set<std::string> names;
  for (const auto& b : j["benchmarks"]) {
    names.insert(b["name"].get<std::string>());
    EXPECT_TRUE(b.contains("items_per_second")) << b.dump();
    EXPECT_GT(b["items_per_second"].get<double>(), 0.0);
  }
  // The pair side by side under one name, plus the GLM baseline and the SIMD kernels.
  for (const char* side : {"matrix", "motor", "glm", "simd_matrix", "simd_affine", "simd_motor"})
    EXPECT_TRUE(names.count(std::string("compose/") + side)) << side;
  for (const auto& b : j["benchmarks"])  // the simd sides name the Highway target they ran on
    if (b["name"].get<std::string>().find("simd_") != std::string::npos) EXPECT_FALSE(b.value("label", "").empty()) << b.dump();
  EXPECT_NE(log.find("motor/matrix"), std::string::npos) << log;
  EXPECT_NE(log.find("best motor / fastest matrix"), std::string::npos) << log;
  // The machine above the summary and in the JSON's context: /proc/cpuinfo's model
  // name, the logical cores, the Highway target the simd sides' labels name.
  std::string model;
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; model.empty() && std::getline(cpuinfo, line);)
    if (line.rfind("model name", 0) == 0) model = line.substr(line.find_first_not_of(' ', line.find(':') + 1));
  const nlohmann::json& ctx = j["context"];
  if (!model.empty()) EXPECT_EQ(ctx.value("cpu_model", ""), model);
  EXPECT_EQ(ctx.value("logical_cores", ""), std::to_string(std::thread::hardware_concurrency()));
  for (const auto& b : j["benchmarks"])
    if (b["name"] == "compose/simd_motor") EXPECT_EQ(ctx.value("simd_target", ""), b.value("label", "")) << b.dump();
  EXPECT_NE(log.find("Measured on CPU: " + ctx.value("cpu_model", "?") + ", " + ctx.value("logical_cores", "?") +
                     " logical cores; SIMD kernels: Highway " + ctx.value("simd_target", "?")),
            std::string::npos)
      << log;
  fs::remove(out);
}

// --benchmark_color=false reaches the console reporter: no escape codes (the
// reporter motorbench passes must obey the flag, not keep colour whatever it says).
TEST(CliBench, ColorFalseWritesNoEscapeCodes) {
  std::string log;
  ASSERT_EQ(runCommand(exe() + "bench --benchmark_filter='^compose/motor$' --benchmark_min_time=0.01 "
                               "--benchmark_color=false", &log), 0) << log;
  EXPECT_NE(log.find("compose/motor"), std::string::npos) << log;
  EXPECT_EQ(log.find('\x1b'), std::string::npos) << log;
}

TEST(CliBench, OutOfCacheKernelReportsBandwidthFraction) {
  const fs::path out = scratchFile("bw.json");
  std::string log;
  const int rc = runCommand(exe() + "bench --benchmark_filter='^direction/out_of_cache/motor$' "
                             "--benchmark_min_time=0.01 --out '" + out.string() + "'", &log);
  ASSERT_EQ(rc, 0) << log;
  const nlohmann::json j = readJson(out);
  ASSERT_FALSE(j.is_discarded()) << log;
  ASSERT_EQ(j["benchmarks"].size(), 1u) << j.dump();
  const auto& b = j["benchmarks"][0];
  EXPECT_TRUE(b.contains("bytes_per_second"));
  ASSERT_TRUE(b.contains("bw_fraction"));
  EXPECT_GT(b["bw_fraction"].get<double>(), 0.0);
  EXPECT_GE(b["working_set_bytes"].get<double>(), 256.0 * 1024 * 1024);
  // The console prints the fraction as a plain number, not as a rate ("0.32", not "0.32/s"):
  // the bw_fraction column's cell of the kernel's row.
  std::vector<std::string> header, row;
  std::istringstream lines(log);
  auto words = [](const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> w;
    for (std::string x; in >> x;) w.push_back(x);
    return w;
  };
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("Benchmark", 0) == 0) header = words(line);
    if (line.rfind("direction/out_of_cache/motor", 0) == 0) row = words(line);
  }
  // Header: Benchmark Time CPU Iterations <counters...>; row: name, time, unit, cpu, unit,
  // iterations, <counters...>.
  const auto col = std::find(header.begin(), header.end(), "bw_fraction");
  ASSERT_NE(col, header.end()) << log;
  const size_t cell = size_t(col - header.begin()) - 4 + 6;
  ASSERT_LT(cell, row.size()) << log;
  size_t used = 0;
  const double shown = std::stod(row[cell], &used);
  EXPECT_EQ(used, row[cell].size()) << "bw_fraction printed as '" << row[cell] << "'";
  EXPECT_NEAR(shown, b["bw_fraction"].get<double>(), 0.01);
  fs::remove(out);
}

TEST(CliBench, RejectsUnknownArgumentsAndEmptyFilters) {
  std::string log;
  EXPECT_EQ(runCommand(exe() + "bench --frobnicate", &log), 2) << log;
  log.clear();
  EXPECT_EQ(runCommand(exe() + "bench --out", &log), 2) << log;
  log.clear();
  EXPECT_EQ(runCommand(exe() + "bench --benchmark_filter=no_such_kernel", &log), 2) << log;
}

}  // namespace
