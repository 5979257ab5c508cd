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
#include <deque>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "harness/bench/bandwidth_probe.h"
#include "harness/bench/bench_kernels.h"
#include "harness/bench/cpu_machine.h"
#include "harness/bench/report_bench.h"
#include "harness/cli/command.h"
#include "harness/cli/output_paths.h"
#include "harness/figures/number_text.h"
#include "harness/process/progress.h"
#include "harness/timing/disturbance.h"

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

// The console reporter plus a record of every result (as Google Benchmark's JSON reporter
// writes it) for the summary, which report_bench's kernelPairs reduces.
class SummaryReporter : public benchmark::ConsoleReporter {
public:
  using benchmark::ConsoleReporter::ConsoleReporter;
  void ReportRuns(const std::vector<Run>& runs) override {
    // bw_fraction is a Google Benchmark rate counter (bytes per iteration / probe bandwidth,
    // divided by the time per iteration): its value is the plain fraction, but the console
    // would print it with a "/s" suffix. Shown without the rate flag; the JSON file reporter
    // gets the runs unchanged (it prints values without units).
    std::vector<Run> shown = runs;
    for (Run& r : shown)
      for (const char* fraction : {"bw_fraction", bench::kCopyFraction}) {
        auto it = r.counters.find(fraction);
        if (it != r.counters.end()) it->second.flags = benchmark::Counter::kDefaults;
      }
    benchmark::ConsoleReporter::ReportRuns(shown);
    // One benchmark done when its runs (not the aggregates that follow them) are reported.
    if (progress && !runs.empty() && runs[0].run_type != Run::RT_Aggregate) progress->done(runs[0].run_name.str());
    for (const Run& r : runs) {
      if (r.error_occurred) continue;
      nlohmann::json b = {{"name", r.benchmark_name()}, {"run_name", r.run_name.str()},
                          {"run_type", r.run_type == Run::RT_Aggregate ? "aggregate" : "iteration"},
                          {"aggregate_name", r.aggregate_name}, {"label", r.report_label},
                          {"real_time", r.GetAdjustedRealTime()}, {"cpu_time", r.GetAdjustedCPUTime()},
                          {"time_unit", benchmark::GetTimeUnitString(r.time_unit)}};
      for (const auto& [key, c] : r.counters) b[key] = c.value;
      if (b.value("label", "").empty()) b.erase("label");
      benchmarks.push_back(b);
      outOfCache = outOfCache || r.counters.count("bw_fraction");
    }
  }
  nlohmann::json benchmarks = nlohmann::json::array();
  bool outOfCache = false;
  std::unique_ptr<process::Progress> progress;  // stderr lines with an ETA (none in list mode)
};

// How many benchmarks `flags` select: Google Benchmark's list mode writes their names to the
// reporter's stream (captured here) and returns the count. Re-initialises the flags as given.
size_t countSelected(const std::vector<std::string>& flags) {
  // Google Benchmark keeps argv[0] (the executable name it prints): the copies must outlive the run.
  static std::deque<std::vector<std::string>> alive;
  auto initialize = [&](const char* listFlag) {
    std::vector<std::string>& copy = alive.emplace_back(flags);
    copy.push_back(listFlag);
    std::vector<char*> argv;
    for (std::string& f : copy) argv.push_back(f.data());
    argv.push_back(nullptr);
    int argc = int(argv.size()) - 1;
    benchmark::Initialize(&argc, argv.data());
  };
  initialize("--benchmark_list_tests=true");
  std::ostringstream names;
  benchmark::ConsoleReporter lister;
  lister.SetOutputStream(&names);
  lister.SetErrorStream(&names);
  const size_t n = benchmark::RunSpecifiedBenchmarks(&lister);
  initialize("--benchmark_list_tests=false");
  return n;
}

// Which figures were taken while other work shared the cores (harness/timing/disturbance.h):
// their pairs are marked DISTURBED above and are not verdict inputs for report or claims.
void printDisturbed(const nlohmann::json& pairs) {
  size_t figures = 0, disturbed = 0;
  std::string first;
  for (const nlohmann::json& p : pairs)
    for (const auto& [side, fig] : p.items()) {
      if (!fig.is_object() || !fig.contains("disturbance") || !fig["disturbance"].is_object()) continue;
      ++figures;
      if (!fig["disturbance"].value("disturbed", false)) continue;
      if (!disturbed++) first = p.value("pair", "") + "/" + side + ": " + fig["disturbance"].value("reason", "");
    }
  if (disturbed)
    std::printf("DISTURBED: %zu of %zu timed figures were taken while other work shared the cores (CPU/real < %.2f "
                "or more runnable threads than cores before and after); their pairs are not verdict inputs. "
                "First: %s\n", disturbed, figures, timing::kMinCpuOverReal, first.c_str());
  else if (figures)
    std::printf("Undisturbed: all %zu timed figures had CPU/real >= %.2f and no more runnable threads than cores.\n",
                figures, timing::kMinCpuOverReal);
}

// The five implementations per pair (and simd_affine, lanes_motor where measured), motor against the
// shim matrix and against the fastest matrix implementation; out of cache, the fraction of the
// probe's bandwidth each side moves. withProbe: print the probe (measured when an out-of-cache
// kernel ran).
void printSummary(const SummaryReporter& rep, bool withProbe) {
  const nlohmann::json pairs = bench::kernelPairs({{"benchmarks", rep.benchmarks}})["pairs"];
  if (pairs.empty()) return;
  std::printf("\nMeasured on %s (CPU ratios hold for this CPU).\n", bench::cpuMachineLine(bench::cpuMachine()).c_str());
  const char* sides[] = {"matrix", "motor", "glm", "simd_matrix", "simd_motor", "simd_affine", "lanes_motor"};
  auto ips = [](const nlohmann::json& p, const char* side) {
    return p.contains(side) ? figures::positiveOrDash(p[side].value("items_per_second", nlohmann::json())) : std::string("-");
  };
  std::printf("Throughput (items/s; the median of the repetitions where repeated). matrix, motor: the "
              "shader source through the shim; glm: GLM's operators; simd_*: kernels/simd (Highway, "
              "target in the label); lanes_motor: the 4-lane motor product of the motor pipelines' update "
              "(pipelines/motor/gp_motors.h); motor/matrix: the shim pair; best motor / fastest matrix: each kind's "
              "fastest implementation, named (> 1: the motor is faster):\n");
  std::printf("%-28s %11s %11s %11s %11s %11s %11s %11s %9s %28s\n", "kernel", "matrix", "motor", "glm",
              "simd_matrix", "simd_motor", "simd_affine", "lanes_motor", "motor/mat", "best motor / fastest matrix");
  for (const nlohmann::json& p : pairs) {
    std::printf("%-28s", p.value("pair", "").c_str());
    for (const char* s : sides) std::printf(" %11s", ips(p, s).c_str());
    std::string best = "-";
    if (p["ratio_motor_fastest_matrix"].is_number())
      best = figures::positiveOrDash(p["ratio_motor_fastest_matrix"], "%.3g") + " (" + p["fastest_motor"].get<std::string>() + " / " +
             p["fastest_matrix"].get<std::string>() + ")";
    std::printf(" %9s %28s%s\n", figures::positiveOrDash(p["ratio_motor_matrix"], "%.3g").c_str(), best.c_str(),
                p.value("disturbed", false) ? "  DISTURBED" : "");
  }
  printDisturbed(pairs);
  std::printf("load_frames: matrix converts nothing at load (a copy of normal + tangent), motor encodes "
              "tangent rotors, glm does the same with glm::quat_cast.\n");
  if (!withProbe) return;
  std::printf("\nOut of cache: bytes/s, bw = bytes/s over the bandwidth probe's best and copy = over its STREAM copy "
              "(fractions):\n");
  std::printf("%-28s %-6s", "kernel", "target");
  for (const char* s : sides) std::printf(" %23s", s);
  std::printf("\n");
  for (const nlohmann::json& p : pairs) {
    if (p.value("size", nlohmann::json()) != "out_of_cache") continue;
    // The Highway target of the simd sides (the scalar sides run what the compiler chose).
    std::string target = "-";
    for (const char* s : {"simd_matrix", "simd_motor", "simd_affine"})
      if (p.contains(s) && p[s].contains("label")) target = p[s]["label"].get<std::string>();
    std::printf("%-28s %-6s", p.value("pair", "").c_str(), target.c_str());
    for (const char* s : sides) {
      std::string cell = "-";
      if (p.contains(s))
        cell = figures::positiveOrDash(p[s].value("bytes_per_second", nlohmann::json())) + "B/s " +
               figures::positiveOrDash(p[s].value("bw_fraction", nlohmann::json()), "%.2f") + " " +
               figures::positiveOrDash(p[s].value(bench::kCopyFraction, nlohmann::json()), "%.2f");
      std::printf(" %23s", cell.c_str());
    }
    std::printf("\n");
  }
  const bench::Bandwidth& bw = bench::referenceBandwidth();
  std::printf("bandwidth probe (one core, %zu MiB arrays): copy %.2f GB/s, copy with streaming stores "
              "%.2f GB/s, triad %.2f GB/s; bw = out-of-cache bytes/s over the best of the three, copy = over copy\n",
              bw.arrayBytes >> 20, bw.copyBytesPerSecond / 1e9, bw.copyStreamingBytesPerSecond / 1e9,
              bw.triadBytesPerSecond / 1e9);
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
      // Google Benchmark exits 1 without a word when it cannot open the file: its folder is made
      // and checked here, before any benchmark runs.
      if (Status ok = prepareOutputFile("--out", file); !ok) {
        std::fprintf(stderr, "motorbench bench: error: %s\n", ok.error().c_str());
        return 2;
      }
      flags.push_back("--benchmark_out=" + file);
      flags.push_back("--benchmark_out_format=json");
    } else if (a.rfind("--benchmark_", 0) == 0) {
      minTime = minTime || a.rfind("--benchmark_min_time", 0) == 0;
      flags.push_back(a);
    } else if (a == "--simd-target" || a.rfind("--simd-target=", 0) == 0) {
      const std::string name = a == "--simd-target" ? (i + 1 < args.size() ? args[++i] : "") : a.substr(14);
      if (const std::string error = bench::forceSimdTarget(name); !error.empty()) {
        std::fprintf(stderr, "motorbench bench: error: %s\n", error.c_str());
        return 2;
      }
    } else if (a == "--help" || a == "-h") {
      std::printf("usage: motorbench bench [--out FILE] [--simd-target NAME] [--benchmark_filter=REGEX] "
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

  // The CPU the run measures, in the JSON's context (a report reading it later names it).
  const bench::CpuMachine machine = bench::cpuMachine();
  benchmark::AddCustomContext("cpu_model", machine.cpu);
  benchmark::AddCustomContext("logical_cores", std::to_string(machine.logicalCores));
  benchmark::AddCustomContext("simd_target", machine.simdTarget);

  bench::registerBandwidthBenchmarks();
  bench::registerTransformBenchmarks();
  bench::registerVertexBenchmarks();
  bench::registerHierarchyBenchmarks();
  bench::registerPaletteBenchmarks();
  bench::registerAnimationBenchmarks();
  bench::registerTangentBenchmarks();

  SummaryReporter reporter(consoleOptions(flags));
  bool listOnly = false;
  for (const std::string& f : flags) listOnly = listOnly || f == "--benchmark_list_tests" || f == "--benchmark_list_tests=true";
  if (!listOnly) reporter.progress = std::make_unique<process::Progress>("bench", "benchmarks run", countSelected(flags), false);
  const size_t ran = benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  if (ran == 0) {
    std::fprintf(stderr, "motorbench bench: no benchmark matched the filter\n");
    return 2;
  }
  printSummary(reporter, reporter.outOfCache);
  return 0;
}

}  // namespace
}  // namespace mb

MB_COMMAND(bench, "bench", "[--out FILE] [--benchmark_filter=REGEX] [--benchmark_*...]",
           "Google Benchmark: matrix vs motor (vs glm) kernels in and out of cache, STREAM probe",
           mb::runBench);
MB_COMMAND_HELP(bench, "bench",
               "  --out FILE               Google Benchmark JSON (report --bench-json reads it; missing folders are created)\n"
               "  --benchmark_filter=REGEX  only the kernels matching (e.g. ^compose/)\n"
               "  --benchmark_*             any other Google Benchmark option (min time, repetitions, colour)\n",
                "motorbench bench --benchmark_filter=^compose/ --out out/bench.json", false);
