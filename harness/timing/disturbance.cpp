#include "harness/timing/disturbance.h"

#include <cstdio>
#include <ctime>
#include <fstream>
#include <thread>

namespace mb::timing {

LoadSample sampleLoad() {
  // "0.52 0.58 0.59 2/345 12345": three load averages, runnable/total scheduling entities, last pid.
  LoadSample s;
  std::ifstream in("/proc/loadavg");
  double a1 = 0, a5 = 0, a15 = 0;
  int running = 0, total = 0;
  char slash = 0;
  if (in >> a1 >> a5 >> a15 >> running >> slash >> total && slash == '/') s.average1 = a1, s.runnable = running;
  return s;
}

Disturbance judgeDisturbance(double cpuSeconds, double realSeconds, LoadSample before, LoadSample after,
                             unsigned logicalCores) {
  Disturbance d;
  d.cpuSeconds = cpuSeconds, d.realSeconds = realSeconds, d.before = before, d.after = after;
  d.logicalCores = logicalCores ? logicalCores : std::thread::hardware_concurrency();
  char b[160];
  if (realSeconds > 0 && d.cpuOverReal() < kMinCpuOverReal) {
    std::snprintf(b, sizeof b, "cores shared: CPU/real %.2f < %.2f", d.cpuOverReal(), kMinCpuOverReal);
    d.reason = b;
  }
  if (d.logicalCores && before.runnable > int(d.logicalCores) && after.runnable > int(d.logicalCores)) {
    std::snprintf(b, sizeof b, "machine busy: %d and %d runnable threads before and after > %u cores", before.runnable,
                  after.runnable, d.logicalCores);
    d.reason += (d.reason.empty() ? "" : "; ") + std::string(b);
  }
  d.disturbed = !d.reason.empty();
  return d;
}

double cpuSecondsNow(CpuClock clock) {
  timespec ts{};
  clock_gettime(clock == CpuClock::Thread ? CLOCK_THREAD_CPUTIME_ID : CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

DisturbanceWatch::DisturbanceWatch(CpuClock clock)
    : clock_(clock), real0_(std::chrono::steady_clock::now()), cpu0_(cpuSecondsNow(clock)), load0_(sampleLoad()) {}

Disturbance DisturbanceWatch::finish() const {
  const double cpu = cpuSecondsNow(clock_) - cpu0_;
  const double real = std::chrono::duration<double>(std::chrono::steady_clock::now() - real0_).count();
  return judgeDisturbance(cpu, real, load0_, sampleLoad());
}

nlohmann::json toJson(const LoadSample& s) {
  return {{"average1", s.average1 >= 0 ? nlohmann::json(s.average1) : nlohmann::json()},
          {"runnable", s.runnable >= 0 ? nlohmann::json(s.runnable) : nlohmann::json()}};
}

nlohmann::json toJson(const Disturbance& d) {
  return {{"disturbed", d.disturbed},
          {"reason", d.disturbed ? nlohmann::json(d.reason) : nlohmann::json()},
          {"cpuOverReal", d.realSeconds > 0 ? nlohmann::json(d.cpuOverReal()) : nlohmann::json()},
          {"cpuSeconds", d.cpuSeconds},
          {"realSeconds", d.realSeconds},
          {"loadBefore", toJson(d.before)},
          {"loadAfter", toJson(d.after)},
          {"logicalCores", d.logicalCores}};
}

std::string disturbanceMark(const Disturbance& d) { return d.disturbed ? " [disturbed: " + d.reason + "]" : ""; }

}  // namespace mb::timing
