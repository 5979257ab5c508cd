// `motorbench bench [--out FILE] [--benchmark_*...]`: the matrix / motor / glm kernel pairs of
// harness/bench/bench_*.cpp and the STREAM probe on Google Benchmark. --benchmark_* flags pass
// through; --out FILE writes Google Benchmark's JSON (--benchmark_out=FILE, format json).
// Without --benchmark_min_time the default is kDefaultMinTime seconds per benchmark, which
// keeps `--benchmark_repetitions=5` of the whole set within a few minutes on two cores.
// After the run, a summary prints motor/matrix (and glm/matrix) throughput ratios per pair.
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "harness/bench/bandwidth_probe.h"
#include "harness/bench/bench_kernels.h"
#include "harness/cli/command.h"

namespace mb {
namespace {

constexpr const char* kDefaultMinTime = "0.2";

// The console options Google Benchmark would give its own reporter: a reporter passed to
// RunSpecifiedBenchmarks is constructed by us and would otherwise keep ConsoleReporter's
// default (colour on), ignoring --benchmark_color (results/bench.txt had escape codes).
// Colour: --benchmark_color=true|yes|1|on, or auto (the default) on a terminal; tabular
// counters always (the layout bench.txt has always had).
benchmark::ConsoleReporter::OutputOptions consoleOptions(const std::vector<std::string>& flags) {
  std::string color = "auto";
  for (const std::string& f : flags) {
    if (f.rfind("--benchmark_color=", 0) == 0) color = f.substr(18);
    else if (f == "--benchmark_color") color = "true";
  }
  bool on = color == "true" || color == "yes" || color == "1" || color == "on";
  if (color == "auto") {
    const char* term = std::getenv("TERM");
    on = isatty(STDOUT_FILENO) && term && std::string(term) != "dumb";
  }
  return on ? benchmark::ConsoleReporter::OO_ColorTabular : benchmark::ConsoleReporter::OO_Tabular;
}

// The console reporter plus a record of every result for the ratio summary.
class SummaryReporter : public benchmark::ConsoleReporter {
public:
  using benchmark::ConsoleReporter::ConsoleReporter;
  struct Result {
    double itemsPerSecond = 0, bwFraction = -1;
  };
  void ReportRuns(const std::vector<Run>& runs) override {
    // bw_fraction is a Google Benchmark rate counter (bytes per iteration / probe bandwidth,
    // divided by the time per iteration): its value is the plain fraction, but the console
    // would print it with a "/s" suffix. Shown without the rate flag; the JSON file reporter
    // gets the runs unchanged (it prints values without units).
    std::vector<Run> shown = runs;
    for (Run& r : shown) {
      auto it = r.counters.find("bw_fraction");
      if (it != r.counters.end()) it->second.flags = benchmark::Counter::kDefaults;
    }
    benchmark::ConsoleReporter::ReportRuns(shown);
    for (const Run& r : runs) {
      if (r.error_occurred) continue;
      // One figure per benchmark: the median aggregate when there are repetitions.
      const bool aggregate = r.run_type == Run::RT_Aggregate;
      if (aggregate && r.aggregate_name != "median") continue;
      if (!aggregate && r.repetitions > 1) continue;
      Result res;
      auto it = r.counters.find("items_per_second");
      if (it != r.counters.end()) res.itemsPerSecond = it->second.value;
      it = r.counters.find("bw_fraction");
      if (it != r.counters.end()) res.bwFraction = it->second.value;
      results[r.run_name.function_name] = res;
    }
  }
  std::map<std::string, Result> results;
};

// withProbe: print the bandwidth probe (only measured when an out-of-cache kernel ran).
void printSummary(const SummaryReporter& rep, bool withProbe) {
  // Pairs: names "<kernel>[/<size>]/<side>"; the prefix identifies the pair.
  std::map<std::string, std::map<std::string, SummaryReporter::Result>> pairs;
  std::vector<std::string> order;
  for (const auto& [name, res] : rep.results) {
    const size_t slash = name.rfind('/');
    if (slash == std::string::npos) continue;
    const std::string prefix = name.substr(0, slash), side = name.substr(slash + 1);
    if (side != "matrix" && side != "motor" && side != "glm") continue;
    if (!pairs.count(prefix)) order.push_back(prefix);
    pairs[prefix][side] = res;
  }
  if (pairs.empty()) return;
  std::printf("\nThroughput ratios (items/s; > 1 means faster than matrix; the median of the "
              "repetitions where repeated):\n");
  std::printf("%-28s %14s %14s %14s %12s %10s %9s %9s\n", "kernel", "matrix items/s",
              "motor items/s", "glm items/s", "motor/matrix", "glm/matrix", "bw matrix",
              "bw motor");
  auto num = [](double v) {
    char b[32];
    std::snprintf(b, sizeof b, v > 0 ? "%.4g" : "-", v);
    return std::string(b);
  };
  for (const std::string& p : order) {
    auto& sides = pairs[p];
    const double m = sides.count("matrix") ? sides["matrix"].itemsPerSecond : 0;
    const double mo = sides.count("motor") ? sides["motor"].itemsPerSecond : 0;
    const double g = sides.count("glm") ? sides["glm"].itemsPerSecond : 0;
    auto frac = [&](const char* side) {
      if (!sides.count(side) || sides[side].bwFraction < 0) return std::string("-");
      char b[32];
      std::snprintf(b, sizeof b, "%.2f", sides[side].bwFraction);
      return std::string(b);
    };
    std::printf("%-28s %14s %14s %14s %12s %10s %9s %9s\n", p.c_str(), num(m).c_str(),
                num(mo).c_str(), num(g).c_str(), m > 0 && mo > 0 ? num(mo / m).c_str() : "-",
                m > 0 && g > 0 ? num(g / m).c_str() : "-", frac("matrix").c_str(),
                frac("motor").c_str());
  }
  std::printf("matrix and motor: the shader source (matrix_transform.glsl, pga.glsl, "
              "motor_transform.glsl) compiled through the shim with float, same flags; glm: "
              "GLM's own mat4 operators. load_frames: matrix converts nothing at load (a copy of "
              "normal + tangent), motor encodes tangent rotors, glm does the same with "
              "glm::quat_cast.\n");
  if (!withProbe) return;
  const bench::Bandwidth& bw = bench::referenceBandwidth();
  std::printf("bandwidth probe (one core, %zu MiB arrays): copy %.2f GB/s, triad %.2f GB/s; "
              "bw = out-of-cache bytes/s over the better of the two\n",
              bw.arrayBytes >> 20, bw.copyBytesPerSecond / 1e9, bw.triadBytesPerSecond / 1e9);
}

int runBench(const std::vector<std::string>& args) {
  std::vector<std::string> flags = {"motorbench bench"};
  bool minTime = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--out" || a.rfind("--out=", 0) == 0) {
      std::string file = a == "--out" ? (i + 1 < args.size() ? args[++i] : "") : a.substr(6);
      if (file.empty()) {
        std::fprintf(stderr, "motorbench bench: error: --out needs a file name\n");
        return 2;
      }
      flags.push_back("--benchmark_out=" + file);
      flags.push_back("--benchmark_out_format=json");
    } else if (a.rfind("--benchmark_", 0) == 0) {
      minTime = minTime || a.rfind("--benchmark_min_time", 0) == 0;
      flags.push_back(a);
    } else if (a == "--help" || a == "-h") {
      std::printf("usage: motorbench bench [--out FILE] [--benchmark_filter=REGEX] "
                  "[--benchmark_repetitions=N] [--benchmark_min_time=S] [--benchmark_list_tests] "
                  "[--benchmark_*...]\n");
      return 0;
    } else {
      std::fprintf(stderr, "motorbench bench: error: unknown argument '%s' (expected --out FILE "
                           "or --benchmark_* flags)\n", a.c_str());
      return 2;
    }
  }
  if (!minTime) flags.push_back(std::string("--benchmark_min_time=") + kDefaultMinTime);

  std::vector<char*> argv;
  for (std::string& f : flags) argv.push_back(f.data());
  argv.push_back(nullptr);
  int argc = int(argv.size()) - 1;
  benchmark::Initialize(&argc, argv.data());
  if (benchmark::ReportUnrecognizedArguments(argc, argv.data())) return 2;

  bench::registerBandwidthBenchmarks();
  bench::registerTransformBenchmarks();
  bench::registerVertexBenchmarks();
  bench::registerHierarchyBenchmarks();
  bench::registerAnimationBenchmarks();
  bench::registerTangentBenchmarks();

  SummaryReporter reporter(consoleOptions(flags));
  const size_t ran = benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  if (ran == 0) {
    std::fprintf(stderr, "motorbench bench: no benchmark matched the filter\n");
    return 2;
  }
  bool outOfCache = false;
  for (const auto& [name, res] : reporter.results) outOfCache = outOfCache || res.bwFraction >= 0;
  printSummary(reporter, outOfCache);
  return 0;
}

}  // namespace
}  // namespace mb

MB_COMMAND(bench, "bench", "[--out FILE] [--benchmark_filter=REGEX] [--benchmark_*...]",
           "Google Benchmark: matrix vs motor (vs glm) kernels in and out of cache, STREAM probe",
           mb::runBench);
