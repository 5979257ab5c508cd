// Where a report or claims run was measured: CPU, cores, OS, compiler, LP_NUM_THREADS (llvmpipe's
// rasteriser threads) and the GL renderer, so figures are never quoted without their machine.
#pragma once
#include <nlohmann/json.hpp>

namespace mb::report {

// CPU model (/proc/cpuinfo), logical cores, kernel (uname), compiler, build type, UTC time,
// LP_NUM_THREADS (null when unset). GL fields are added by the caller from a rendered frame.
nlohmann::json machineJson();

}  // namespace mb::report
