// Quaternions enter the motor pipeline "conversion free": a glTF rotation (x, y, z, w) is the
// rotor [w, -x, -y, -z]. Checked bit for bit on the loader's own function,
// companion::rotorFromQuat.
#pragma once
#include <nlohmann/json.hpp>

namespace mb::accuracy {

// The samples the figures check: 16 axis-aligned and signed-zero quaternions, then this many
// random unit quaternions (a fixed seed).
inline constexpr int kRandomQuaternions = 100000;

struct QuatRotorCheck {
  int samples = 0, mismatches = 0;
};
// companion::rotorFromQuat on the 16 special quaternions plus `samples` random unit ones, each
// output compared bit for bit with (w, -x, -y, -z) and a zero dual half.
QuatRotorCheck checkRotorFromQuat(int samples);

// The figures conversion.quat_to_rotor.* into `figures`.
void putConversionFigures(const QuatRotorCheck& check, nlohmann::json& figures);

}  // namespace mb::accuracy
