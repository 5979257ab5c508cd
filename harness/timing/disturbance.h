// Whether a timed figure was taken while other work shared the cores. Every timed
// figure (bench kernels, `motorbench time`, the report's and the claims' timings) records, over
// the interval it measured, the CPU time its own threads got, the real time that passed and the
// machine's load before and after; judgeDisturbance marks it `disturbed` with the reason, and a
// disturbed figure is printed with the mark and is not a verdict input.
//
// The two signs, either one marks the figure:
//  - CPU / real < kMinCpuOverReal: the measuring thread(s) got less than 90 % of the time that
//    passed (one core's worth: a single-threaded kernel, or a render whose threads always keep
//    one core busy). A run on shared cores shows it at once (seen: 53 ms real for 15 ms CPU).
//  - more runnable threads than the machine has cores, at both the sample before and the sample
//    after (/proc/loadavg's run queue, our own thread included): someone waited for a core.
//    The 1-minute load averages are recorded beside it but not judged: they lag a minute behind
//    (a build that ended 30 s ago would still mark a quiet figure).
#pragma once
#include <chrono>
#include <string>

#include <nlohmann/json.hpp>

namespace mb::timing {

inline constexpr double kMinCpuOverReal = 0.9;

// The machine's load at one instant (/proc/loadavg; -1 where unreadable).
struct LoadSample {
  double average1 = -1;  // 1-minute load average
  int runnable = -1;     // threads running or waiting for a core now, the reader included
};
LoadSample sampleLoad();

struct Disturbance {
  double cpuSeconds = 0, realSeconds = 0;
  LoadSample before, after;
  unsigned logicalCores = 0;
  bool disturbed = false;
  std::string reason;  // why disturbed ("" when not): every sign that fired, "; "-separated
  double cpuOverReal() const { return realSeconds > 0 ? cpuSeconds / realSeconds : 0.0; }
};

// The judgement (a pure function: tests feed it hand-made samples). `logicalCores` 0: the
// machine's (std::thread::hardware_concurrency).
Disturbance judgeDisturbance(double cpuSeconds, double realSeconds, LoadSample before, LoadSample after,
                             unsigned logicalCores = 0);

// Which CPU clock a watch reads: the calling thread's (a single-threaded kernel) or the whole
// process's (a render with driver threads).
enum class CpuClock { Thread, Process };
double cpuSecondsNow(CpuClock clock);

// Starts the clocks and samples the load on construction; finish() judges the interval.
class DisturbanceWatch {
public:
  explicit DisturbanceWatch(CpuClock clock = CpuClock::Thread);
  Disturbance finish() const;

private:
  CpuClock clock_;
  std::chrono::steady_clock::time_point real0_;
  double cpu0_ = 0;
  LoadSample load0_;
};

// {"disturbed", "reason" (null when not), "cpuOverReal", "cpuSeconds", "realSeconds",
//  "loadBefore"/"loadAfter": {"average1", "runnable"}, "logicalCores"}.
nlohmann::json toJson(const Disturbance& d);
// " [disturbed: <reason>]" or "" (appended to a printed figure).
std::string disturbanceMark(const Disturbance& d);
nlohmann::json toJson(const LoadSample& s);

}  // namespace mb::timing
