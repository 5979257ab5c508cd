#include "harness/bench/report_bench.h"

#include <cstdio>
#include <fstream>
#include <map>

#include "harness/bench/bandwidth_probe.h"
#include "harness/bench/bench_common.h"
#include "harness/bench/fastest_sides.h"
#include "harness/process/report_workers.h"
#include "harness/timing/disturbance.h"

namespace mb::bench {
namespace {

using json = nlohmann::json;

bool isSide(const std::string& s) { return *bench::sideKind(s) != 0; }

// Seconds per unit of Google Benchmark's time_unit.
double unitSeconds(const std::string& unit) {
  return unit == "s" ? 1.0 : unit == "ms" ? 1e-3 : unit == "us" ? 1e-6 : 1e-9;
}

// The figure's disturbance (harness/timing/disturbance.h) from its CPU and real time per
// iteration and the load counters registerKernel samples; a figure without them (a JSON
// written without the load counters) is not judged (null).
json disturbanceOf(const json& b, unsigned cores) {
  if (!b.contains(bench::kRunnableBefore) || !b.contains("cpu_time")) return nullptr;
  auto load = [&](const char* avg, const char* runnable) {
    return timing::LoadSample{b.value(avg, -1.0), int(b.value(runnable, -1.0))};
  };
  const double unit = unitSeconds(b.value("time_unit", "ns"));
  return timing::toJson(timing::judgeDisturbance(b.value("cpu_time", 0.0) * unit, b.value("real_time", 0.0) * unit,
                                                 load(bench::kLoadBefore, bench::kRunnableBefore),
                                                 load(bench::kLoadAfter, bench::kRunnableAfter), cores));
}

json sideFigures(const json& b, unsigned cores) {
  json s = {{"items_per_second", b.value("items_per_second", 0.0)},
            {"bytes_per_second", b.value("bytes_per_second", 0.0)},
            {"real_time", b.value("real_time", 0.0)}, {"cpu_time", b.value("cpu_time", 0.0)},
            {"time_unit", b.value("time_unit", "ns")}, {"disturbance", disturbanceOf(b, cores)}};
  if (b.contains("bw_fraction")) s["bw_fraction"] = b["bw_fraction"];
  if (b.contains("probe_GBps")) s["probe_GBps"] = b["probe_GBps"];
  for (const char* key : {bench::kCopyFraction, "copy_GBps"})
    if (b.contains(key)) s[key] = b[key];
  if (b.contains("label")) s["label"] = b["label"];
  if (b.contains("repetitions")) s["repetitions"] = b["repetitions"];  // the median's sample count
  return s;
}

}  // namespace

Status runBench(const std::string& outJson, const std::string& logPath, double minTime,
                const std::string& filter) {
  char mt[64];
  std::snprintf(mt, sizeof mt, "--benchmark_min_time=%g", minTime);
  std::vector<std::string> args = {"bench", "--out", outJson, mt};
  if (!filter.empty()) args.push_back("--benchmark_filter=" + filter);
  // Both streams to the log: Google Benchmark prints its machine context on stderr.
  const std::string how = process::runProgram(process::selfExecutable(), args, logPath, true, 1800);
  if (!how.empty()) return Status::fail("motorbench bench " + how + " (log: " + logPath + ")");
  return Status();
}

Result<json> readBenchJson(const std::string& path) {
  std::ifstream in(path);
  if (!in) return Result<json>::fail(path + ": cannot open");
  json j = json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.contains("benchmarks") || !j["benchmarks"].is_array())
    return Result<json>::fail(path + ": not a Google Benchmark JSON file (no \"benchmarks\" array)");
  return j;
}

json kernelPairs(const json& bench) {
  const json context = bench.value("context", json::object());
  const unsigned cores = unsigned(context.value("num_cpus", 0));
  // name -> figures; a median aggregate replaces the individual repetitions.
  std::map<std::string, json> figures;
  std::map<std::string, bool> fromMedian;
  std::vector<std::string> order;
  for (const json& b : bench.value("benchmarks", json::array())) {
    if (b.value("error_occurred", false)) continue;
    const std::string runType = b.value("run_type", "iteration");
    const std::string name = b.value("run_name", b.value("name", ""));
    if (runType == "aggregate" && b.value("aggregate_name", "") != "median") continue;
    if (runType != "aggregate" && fromMedian[name]) continue;
    if (!figures.count(name)) order.push_back(name);
    figures[name] = b;
    fromMedian[name] = runType == "aggregate";
  }
  json pairs = json::array(), probe = json::array();
  std::map<std::string, size_t> pairIndex;
  for (const std::string& name : order) {
    const json& b = figures[name];
    const size_t slash = name.rfind('/');
    const std::string side = slash == std::string::npos ? "" : name.substr(slash + 1);
    if (!isSide(side)) {
      probe.push_back({{"name", name}, {"bytes_per_second", b.value("bytes_per_second", 0.0)},
                       {"items_per_second", b.value("items_per_second", 0.0)},
                       {"disturbance", disturbanceOf(b, cores)}});
      continue;
    }
    const std::string prefix = name.substr(0, slash);
    if (!pairIndex.count(prefix)) {
      const size_t s2 = prefix.rfind('/');
      const std::string tail = s2 == std::string::npos ? "" : prefix.substr(s2 + 1);
      const bool sized = tail == "in_cache" || tail == "out_of_cache";
      pairIndex[prefix] = pairs.size();
      pairs.push_back({{"pair", prefix}, {"kernel", sized ? prefix.substr(0, s2) : prefix},
                       {"size", sized ? json(tail) : json(nullptr)}});
    }
    pairs[pairIndex[prefix]][side] = sideFigures(b, cores);
  }
  for (json& p : pairs) {
    auto ips = [&](const std::string& side) {
      return p.contains(side) ? p[side].value("items_per_second", 0.0) : 0.0;
    };
    const double m = ips("matrix"), mo = ips("motor"), g = ips("glm");
    p["ratio_motor_matrix"] = m > 0 && mo > 0 ? json(mo / m) : json(nullptr);
    p["ratio_glm_matrix"] = m > 0 && g > 0 ? json(g / m) : json(nullptr);
    const double sm = ips(bench::kSimdMatrix), smo = ips(bench::kSimdMotor);
    p["ratio_simd_motor_matrix"] = sm > 0 && smo > 0 ? json(smo / sm) : json(nullptr);
    // The fastest implementation on each side, whatever its source. A pair with a disturbed side
    // keeps its ratios (printed with the mark) but is not a verdict input:
    // fastestSides' costRatio is -1 for it, and "disturbed" names the sides and reasons.
    const bench::FastestSides f = bench::fastestSides(p);
    p["disturbed"] = !f.disturbed.empty();
    p["disturbedSides"] = f.disturbed;
    p["fastest_matrix"] = f.matrixSide.empty() ? json(nullptr) : json(f.matrixSide);
    p["fastest_motor"] = f.motorSide.empty() ? json(nullptr) : json(f.motorSide);
    p["ratio_motor_fastest_matrix"] = f.motor > 0 && f.matrix > 0 ? json(f.motor / f.matrix) : json(nullptr);
    json target = nullptr;
    for (const char* side : {bench::kSimdMatrix, bench::kSimdAffine, bench::kSimdMotor})
      if (p.contains(side) && p[side].contains("label")) target = p[side]["label"];
    p["machine"] = {{"cpu", context.value("cpu_model", json(nullptr))},
                    {"logicalCores", context.value("num_cpus", json(nullptr))}, {"simdTarget", target}};
    p["machine_text"] = pairMachineText(p);
  }
  return {{"context", context}, {"pairs", pairs}, {"probe", probe}};
}

std::string pairMachineText(const json& pair) {
  const json m = pair.value("machine", json::object());
  if (!m.value("cpu", json()).is_string()) return "an unrecorded CPU";
  std::string s = m["cpu"].get<std::string>() + " (";
  s += m.value("logicalCores", json()).is_number() ? std::to_string(m["logicalCores"].get<int>()) + " logical cores"
                                                   : std::string("cores not recorded");
  if (m.value("simdTarget", json()).is_string()) s += ", Highway " + m["simdTarget"].get<std::string>();
  return s + ")";
}

}  // namespace mb::bench
