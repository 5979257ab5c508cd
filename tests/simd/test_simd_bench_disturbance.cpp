// report_bench's kernelPairs judges each bench figure's disturbance from the run's CPU
// and real time and the load counters registerKernel samples: a pair with a disturbed side keeps
// its measured ratios but is not a verdict input (fastestSides' costRatio is -1).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "harness/bench/bench_common.h"
#include "harness/bench/fastest_sides.h"
#include "harness/bench/report_bench.h"

namespace {

using json = nlohmann::json;

// A Google Benchmark run as its JSON reporter writes it, with the load counters.
json run(const std::string& name, double ips, double cpuUs, double realUs, int runnable) {
  return {{"name", name},         {"run_type", "iteration"}, {"items_per_second", ips},
          {"cpu_time", cpuUs},    {"real_time", realUs},     {"time_unit", "us"},
          {mb::bench::kLoadBefore, 0.5}, {mb::bench::kLoadAfter, 0.6},
          {mb::bench::kRunnableBefore, runnable}, {mb::bench::kRunnableAfter, runnable}};
}

TEST(SimdBenchDisturbance, SharedCoresMarkThePairAndTakeItOutOfTheVerdicts) {
  const json bench = {{"context", {{"num_cpus", 2}}},
                      {"benchmarks",
                       {run("compose/matrix", 10, 100, 101, 1), run("compose/motor", 12, 100, 102, 1),
                        // 15 us of CPU in 53 us: another process had the core.
                        run("hierarchy/glm", 20, 15, 53, 1), run("hierarchy/motor", 30, 50, 50, 1),
                        // Enough CPU, but five runnable threads on two cores before and after.
                        run("point/in_cache/matrix", 40, 10, 10, 5), run("point/in_cache/motor", 50, 10, 10, 1)}}};
  const json pairs = mb::bench::kernelPairs(bench)["pairs"];
  ASSERT_EQ(pairs.size(), 3u) << pairs.dump(2);

  const json& quiet = pairs[0];
  EXPECT_EQ(quiet["disturbed"], false);
  EXPECT_EQ(quiet["matrix"]["disturbance"]["disturbed"], false);
  EXPECT_NEAR(quiet["matrix"]["disturbance"]["cpuOverReal"].get<double>(), 100.0 / 101.0, 1e-12);
  EXPECT_NEAR(quiet["matrix"]["disturbance"]["realSeconds"].get<double>(), 101e-6, 1e-15);
  EXPECT_DOUBLE_EQ(mb::bench::fastestSides(quiet).costRatio(), 10.0 / 12.0);

  const json& shared = pairs[1];
  EXPECT_EQ(shared["disturbed"], true);
  ASSERT_TRUE(shared["disturbedSides"].contains("glm")) << shared.dump(2);
  EXPECT_FALSE(shared["disturbedSides"].contains("motor"));
  EXPECT_NE(shared["disturbedSides"]["glm"].get<std::string>().find("CPU/real 0.28"), std::string::npos);
  EXPECT_DOUBLE_EQ(shared["ratio_motor_fastest_matrix"].get<double>(), 30.0 / 20.0);  // printed, marked
  EXPECT_EQ(mb::bench::fastestSides(shared).costRatio(), -1.0);                      // not a verdict input

  const json& busy = pairs[2];
  EXPECT_EQ(busy["disturbed"], true);
  EXPECT_NE(busy["disturbedSides"]["matrix"].get<std::string>().find("5 and 5 runnable threads"), std::string::npos);
}

TEST(SimdBenchDisturbance, FiguresWithoutLoadCountersAreNotJudged) {
  // A bench JSON without load counters: no judgement, the ratios unchanged.
  const json bench = {{"benchmarks",
                       {{{"name", "compose/matrix"}, {"items_per_second", 10.0}, {"cpu_time", 1.0}, {"real_time", 9.0}},
                        {{"name", "compose/motor"}, {"items_per_second", 20.0}, {"cpu_time", 1.0}, {"real_time", 1.0}}}}};
  const json p = mb::bench::kernelPairs(bench)["pairs"][0];
  EXPECT_TRUE(p["matrix"]["disturbance"].is_null());
  EXPECT_EQ(p["disturbed"], false);
  EXPECT_DOUBLE_EQ(mb::bench::fastestSides(p).costRatio(), 0.5);
}

}  // namespace
