#include "harness/report_machine.h"

#include <sys/utsname.h>

#include <chrono>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <string>
#include <thread>

namespace mb::report {
namespace {

std::string cpuModel() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) {
      const size_t colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  return "unknown";
}

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
  const char* lp = std::getenv("LP_NUM_THREADS");
#ifdef NDEBUG
  const char* build = "optimised (NDEBUG)";
#else
  const char* build = "debug (assertions on)";
#endif
  return {{"cpu", cpuModel()},
          {"logicalCores", std::thread::hardware_concurrency()},
          {"os", std::string(u.sysname) + " " + u.release + " " + u.machine},
          {"compiler", std::string("gcc-compatible ") + __VERSION__},
          {"build", build},
          {"lpNumThreads", lp ? nlohmann::json(lp) : nlohmann::json(nullptr)},
          {"date", utcNow()}};
}

}  // namespace mb::report
