// `motorbench bench`, `motorbench time` and the per-vertex section of `motorbench ops`, end to
// end. Never asserts timings: only that the commands run, write what they promise
// (JSON with items_per_second, a printed ratio) and reject bad input.
#include <gtest/gtest.h>

#include <unistd.h>

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
using mb::cli_test::readJson;
using mb::cli_test::runCommand;

std::string exe() { return mb::cli_test::motorbench(); }

fs::path scratchFile(const std::string& name) {
  return fs::temp_directory_path() / ("motorbench_cli_bench_" + std::to_string(::getpid()) + "_" + name);
}

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

TEST(CliTime, TexturedBoxPrintsARatio) {
  const fs::path json = scratchFile("time.json");
  std::string log;
  const int rc = runCommand(
      exe() + "time textured_box --frames 3 --warmup 1 --json '" + json.string() + "'", &log);
  ASSERT_EQ(rc, 0) << log;
  EXPECT_NE(log.find("motor/matrix"), std::string::npos) << log;
  EXPECT_NE(log.find("GL_RENDERER"), std::string::npos) << log;
  const nlohmann::json j = readJson(json);
  ASSERT_FALSE(j.is_discarded()) << log;
  ASSERT_TRUE(j.contains("machine"));
  ASSERT_TRUE(j.contains("results"));
  bool ratio = false;
  for (const auto& r : j["results"])
    if (r.contains("ratio_motor_over_matrix") && r["ratio_motor_over_matrix"].is_number()) ratio = true;
  EXPECT_TRUE(ratio) << j.dump(2);
  fs::remove(json);
}

TEST(CliTime, EachSceneInItsOwnWorkerAndABadSceneDoesNotStopTheOthers) {
  const fs::path json = scratchFile("time_two.json");
  std::string log;
  const int rc = runCommand(exe() + "time no_such_scene_or_file.glb textured_box normal_torus --frames 2 "
                             "--warmup 0 --size 32x32 --json '" + json.string() + "'", &log);
  EXPECT_EQ(rc, 2) << log;
  EXPECT_NE(log.find("no_such_scene_or_file.glb"), std::string::npos) << log;
  EXPECT_NE(log.find("\ntextured_box "), std::string::npos) << log;
  EXPECT_NE(log.find("\nnormal_torus "), std::string::npos) << log;
  const nlohmann::json j = readJson(json);
  ASSERT_FALSE(j.is_discarded()) << log;
  ASSERT_EQ(j["results"].size(), 3u) << j.dump(2);
  EXPECT_EQ(j["results"][0]["scene"], "no_such_scene_or_file.glb");
  EXPECT_TRUE(j["results"][0].contains("error"));
  EXPECT_EQ(j["results"][1]["scene"], "textured_box");
  EXPECT_EQ(j["results"][2]["scene"], "normal_torus");
  for (size_t i : {1u, 2u}) {
    EXPECT_FALSE(j["results"][i].contains("error")) << j["results"][i].dump(2);
    EXPECT_EQ(j["results"][i]["width"], 32) << j["results"][i].dump(2);
  }
  fs::remove(json);
}

// The tiny-viewport configuration runs only where it is vertex-bound (>= 10 drawn vertices per
// pixel): at 8x8 (640 vertices needed) the crowd draws 108,800 (256 instances x 425) and the
// torus 2,178, the textured box 24.
TEST(CliTime, VertexBoundConfigurationOnlyForScenesDrawingManyVerticesPerPixel) {
  const fs::path json = scratchFile("time_vbound.json");
  std::string log;
  const int rc = runCommand(exe() + "time textured_box normal_torus crowd --frames 2 --warmup 0 --size 32x32 --tiny 8x8 "
                             "--json '" + json.string() + "'", &log);
  ASSERT_EQ(rc, 0) << log;
  const nlohmann::json j = readJson(json);
  ASSERT_FALSE(j.is_discarded()) << log;
  std::vector<std::string> rows;
  for (const auto& r : j["results"]) rows.push_back(r.value("scene", "?") + "/" + r.value("config", "?"));
  EXPECT_EQ(rows, (std::vector<std::string>{"textured_box/normal", "normal_torus/normal", "normal_torus/vertex-bound",
                                      "crowd/normal", "crowd/vertex-bound"}))
      << j.dump(2);
  fs::remove(json);
}

TEST(CliTime, RejectsBadInput) {
  std::string log;
  EXPECT_EQ(runCommand(exe() + "time no_such_scene_or_file.glb --frames 2", &log), 2) << log;
  log.clear();
  EXPECT_EQ(runCommand(exe() + "time textured_box --frames 0", &log), 2) << log;
  log.clear();
  EXPECT_EQ(runCommand(exe() + "time textured_box --size 0x5", &log), 2) << log;
}

TEST(CliOps, PerVertexSectionHasBothWaysForEveryPipeline) {
  const fs::path json = scratchFile("ops.json");
  std::string log;
  ASSERT_EQ(runCommand(exe() + "ops --json '" + json.string() + "'", &log), 0) << log;
  EXPECT_NE(log.find("Ops per vertex"), std::string::npos) << log;
  // ops says where it is (a silent run of a minute looks hung; checked here to run the whole of ops once).
  for (const char* step : {"ops: 1/4 steps done (kernels counted", "ops: 2/4 steps done (per-vertex",
                           "ops: 3/4 steps done (per-pipeline", "ops: 4/4 steps done ("})
    EXPECT_NE(log.find(step), std::string::npos) << step << "\n" << log;
  const nlohmann::json j = readJson(json);
  ASSERT_FALSE(j.is_discarded()) << log;
  ASSERT_TRUE(j.contains("per_vertex")) << j.dump();
  const auto& pv = j["per_vertex"];
  const bool tools = pv["tools_problem"].get<std::string>().empty();
  std::set<std::string> seen;
  for (const auto& k : pv["kernels"]) {
    seen.insert(k["pipeline"].get<std::string>() + "/" + k["kernel"].get<std::string>());
    EXPECT_GT(k["counted"]["mul"].get<int>(), 0) << k.dump();
    if (tools) {
      EXPECT_TRUE(k["spirv"].is_object()) << k.dump();
      // Counted and SPIR-V agree, or the difference is explained.
      EXPECT_TRUE(k["agree"].get<bool>() || !k["why"].get<std::string>().empty()) << k.dump();
    }
  }
  for (const char* p : {"matrix", "motor"})
    for (const char* k : {"rigid vertex with frame", "skinned vertex (4 joints)", "world to clip"})
      EXPECT_TRUE(seen.count(std::string(p) + "/" + k)) << p << " " << k;
  EXPECT_TRUE(seen.count("matrix-affine/rigid vertex with frame"));
  for (const auto& v : pv["variants"]) {
    if (tools) {
      EXPECT_TRUE(v["spirv"].is_object()) << v.dump();
    }
  }
  fs::remove(json);
}

}  // namespace
