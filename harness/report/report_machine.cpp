#include "harness/report/report_machine.h"

#include <sys/utsname.h>

#include <chrono>
#include <ctime>
#include <string>

#include "harness/bench/cpu_machine.h"
#include "harness/render/render_frame.h"
#include "harness/timing/frame_timing.h"

namespace mb::report {
namespace {

std::string utcNow() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

}  // namespace

nlohmann::json machineJson() {
  utsname u{};
  uname(&u);
#ifdef NDEBUG
  const char* build = "optimised (NDEBUG)";
#else
  const char* build = "debug (assertions on)";
#endif
  nlohmann::json j = {{"os", std::string(u.sysname) + " " + u.release + " " + u.machine},
                      {"compiler", std::string("gcc-compatible ") + __VERSION__},
                      {"build", build},
                      {"date", utcNow()},
                      {"simdTarget", bench::cpuMachine().simdTarget}};
  // CPU, cores, GL and LP_NUM_THREADS as `motorbench time` records them (frame_timing.h).
  auto m = timing::machineInfo();
  if (!m) {
    j["cpu"] = "unknown";
    j["gl"] = {{"error", m.error()}};
    return j;
  }
  j["cpu"] = m->cpuModel;
  j["logicalCores"] = m->cores;
  j["lpNumThreads"] = m->lpNumThreads == "unset" ? nlohmann::json(nullptr) : nlohmann::json(m->lpNumThreads);
  j["gl"] = toJson(m->gl);  // renderer, version, vendor, backend, realGpu, kind, device
  return j;
}

}  // namespace mb::report
