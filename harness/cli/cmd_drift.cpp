// motorbench drift [--steps N] [--json FILE]: numerical drift of a curved-space camera
// accumulated over N small steps in float (pipelines/curved/curved_drift.h), S3 and H3, matrix
// (4x4 products) vs motor (S3: quaternion pairs, H3: motors), without renormalisation and
// renormalised after every step with each side's cheapest method; op counts of one step and
// one renormalisation, counted by execution.
#include <chrono>
#include <cstdio>
#include <optional>
#include <fstream>

#include <nlohmann/json.hpp>

#include "harness/cli/command.h"
#include "harness/options/args.h"
#include "harness/render/render_frame.h"
#include "pipelines/curved/curved_drift.h"

namespace mb {
namespace {

nlohmann::json opsJson(const OpCounts& c) {
  return {{"mul", c.mul}, {"add", c.add}, {"div", c.div}, {"sqrt", c.sqrt}, {"other", c.other},
          {"other_calls", c.otherCalls()}};
}

std::string opsText(const OpCounts& c) {
  std::string s = std::to_string(c.mul) + " mul, " + std::to_string(c.add) + " add";
  if (c.div) s += ", " + std::to_string(c.div) + " div";
  if (c.sqrt) s += ", " + std::to_string(c.sqrt) + " sqrt";
  if (c.other) s += ", " + c.otherCalls();
  return s;
}

int runDrift(const std::vector<std::string>& argv) {
  auto fail = [](const std::string& message) { return commandError("drift", message); };
  Args args(argv, {{"steps", "json"}, {}, {}});
  if (!args.error().empty()) return fail(args.error());
  if (!args.positional().empty()) return fail("unexpected argument '" + args.positional()[0] + "'");
  const std::optional<double> steps = double(args.integer("steps", 1000000, 1, 1000000000));
  nlohmann::json spaces = nlohmann::json::array();
  std::printf("Camera drift after %.0f steps (turn 2e-3 rad + move 1e-3 per step, float):\n"
              "distance from the group: matrix max|M^T eta M - eta|, motor max(|M~M - 1|) "
              "(S3 pair: max ||L|^2 - 1|, ||R|^2 - 1|)\n\n", *steps);
  std::printf("%-4s %-7s %-13s %-13s %-34s %s\n", "", "side", "raw", "renormalised", "one step",
              "one renormalisation");
  for (int k : {1, -1}) {
    const curved::DriftResult r = curved::measureDrift(k, int64_t(*steps));
    const char* space = k > 0 ? "S3" : "H3";
    for (auto [side, d] : {std::pair{"matrix", &r.matrix}, std::pair{"motor", &r.motor}}) {
      std::printf("%-4s %-7s %-13.3g %-13.3g %-34s %s\n", space, side, d->raw, d->renormalised,
                  opsText(d->stepOps).c_str(), opsText(d->renormOps).c_str());
    }
    auto side = [](const curved::DriftSide& d, const char* renorm) {
      return nlohmann::json{{"raw", d.raw}, {"renormalised", d.renormalised},
                            {"stepOps", opsJson(d.stepOps)}, {"renormOps", opsJson(d.renormOps)},
                            {"renormalisation", renorm}};
    };
    spaces.push_back({{"space", space},
                      {"kappa", k},
                      {"matrix", side(r.matrix, "Gram-Schmidt of the columns in the space's form")},
                      {"motor", side(r.motor, k > 0 ? "normalize_pair" : "normalize_m_k")}});
  }
  if (const auto path = args.get("json")) {
    nlohmann::json j = {{"tool", "motorbench drift"},
                        {"steps", int64_t(*steps)},
                        {"step", "turn 2e-3 rad (x-z plane) then move 1e-3 forward, composed in double, rounded to float once"},
                        {"spaces", spaces}};
    std::ofstream out(*path);
    if (!out || !(out << j.dump(2) << "\n")) return fail("cannot write " + *path);
  }
  return 0;
}

}  // namespace
}  // namespace mb

MB_COMMAND(drift, "drift", "[--steps N] [--json FILE]",
           "curved-space camera drift: matrix vs motor after N float steps, raw and renormalised",
           mb::runDrift);
