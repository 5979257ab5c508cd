// report_bench's kernelPairs with the simd sides: the fastest implementation of each
// kind is named, whatever its source, and the motor is stated against the fastest matrix one.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "harness/bench/report_bench.h"

namespace {

using json = nlohmann::json;

json run(const std::string& name, double ips) { return {{"name", name}, {"run_type", "iteration"}, {"items_per_second", ips}}; }

TEST(SimdBenchPairs, FastestOfEachKindIsNamedAndCompared) {
  const json bench = {{"benchmarks",
                       {run("vertex_frame/in_cache/matrix", 10), run("vertex_frame/in_cache/motor", 12),
                        run("vertex_frame/in_cache/glm", 40), run("vertex_frame/in_cache/simd_matrix", 30),
                        run("vertex_frame/in_cache/simd_motor", 36), run("compose/matrix", 5),
                        run("compose/motor", 6), run("compose/simd_affine", 50), run("compose/simd_motor", 25)}}};
  const json pairs = mb::bench::kernelPairs(bench)["pairs"];
  ASSERT_EQ(pairs.size(), 2u) << pairs.dump(2);
  const json& v = pairs[0];
  EXPECT_EQ(v["kernel"], "vertex_frame");
  EXPECT_EQ(v["fastest_matrix"], "glm");  // GLM beats the SIMD matrix here
  EXPECT_EQ(v["fastest_motor"], "simd_motor");
  EXPECT_DOUBLE_EQ(v["ratio_motor_fastest_matrix"].get<double>(), 36.0 / 40.0);
  EXPECT_DOUBLE_EQ(v["ratio_motor_matrix"].get<double>(), 12.0 / 10.0);
  EXPECT_DOUBLE_EQ(v["ratio_simd_motor_matrix"].get<double>(), 36.0 / 30.0);
  const json& c = pairs[1];
  EXPECT_EQ(c["fastest_matrix"], "simd_affine");
  EXPECT_DOUBLE_EQ(c["ratio_motor_fastest_matrix"].get<double>(), 25.0 / 50.0);
  EXPECT_TRUE(c["ratio_simd_motor_matrix"].is_null());  // no simd_matrix side
}

// A CPU figure names its CPU and the SIMD target it ran on, read from the bench JSON
// (context and the SIMD sides' labels), never from the machine the report runs on.
TEST(SimdBenchPairs, EachPairNamesItsCpuAndSimdTarget) {
  json simd = run("skinned_vertex/out_of_cache/simd_motor", 3);
  simd["label"] = "AVX2";
  const json bench = {{"context", {{"cpu_model", "Test CPU 9000"}, {"num_cpus", 16}}},
                      {"benchmarks", {run("skinned_vertex/out_of_cache/glm", 2), simd, run("anim_blend/glm", 1),
                                      run("anim_blend/motor", 1)}}};
  const json pairs = mb::bench::kernelPairs(bench)["pairs"];
  ASSERT_EQ(pairs.size(), 2u) << pairs.dump(2);
  EXPECT_EQ(pairs[0]["machine"]["simdTarget"], "AVX2");
  EXPECT_EQ(mb::bench::pairMachineText(pairs[0]), "Test CPU 9000 (16 logical cores, Highway AVX2)");
  EXPECT_TRUE(pairs[1]["machine"]["simdTarget"].is_null());  // no SIMD side: no target to name
  EXPECT_EQ(mb::bench::pairMachineText(pairs[1]), "Test CPU 9000 (16 logical cores)");
  EXPECT_EQ(mb::bench::pairMachineText(json{{"pair", "compose"}}), "an unrecorded CPU");
}

}  // namespace
