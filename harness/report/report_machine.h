// Where a report or claims run was measured: CPU, cores, OS, compiler, LP_NUM_THREADS (llvmpipe's
// rasteriser threads) and the GL renderer, so figures are never quoted without their machine.
#pragma once
#include <nlohmann/json.hpp>

namespace mb::report {

// CPU model, logical cores, LP_NUM_THREADS (null when unset) and "gl" (render_frame.h's
// toJson(gl::ContextInfo): renderer, version, vendor, backend, realGpu, kind, device) from
// frame_timing.h's machineInfo() (creates the shared GL context; "gl" holds {"error"} when that
// fails), plus kernel (uname), compiler, build type, UTC time and "simdTarget" (the Highway
// target kernels/simd dispatches to here).
nlohmann::json machineJson();

}  // namespace mb::report
