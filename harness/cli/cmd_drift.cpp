// motorbench drift [--steps N] [--json FILE]: numerical drift of a curved-space camera
// accumulated over N small steps in float (pipelines/curved/curved_drift.h), S3 and H3, matrix
// (4x4 products) vs motor (S3: quaternion pairs, H3: motors), without renormalisation and
// renormalised after every step with each side's cheapest method; op counts of one step and
// one renormalisation, counted by execution.
#include <cstdio>
#include <optional>

#include <nlohmann/json.hpp>

#include "harness/cli/command.h"
#include "harness/cli/output_paths.h"
#include "harness/options/args.h"
#include "harness/render/frame_options.h"
#include "harness/report/report_drift.h"

namespace mb {
namespace {

std::string opsText(const nlohmann::json& c) {
  std::string s = std::to_string(c.value("mul", 0)) + " mul, " + std::to_string(c.value("add", 0)) + " add";
  if (c.value("div", 0)) s += ", " + std::to_string(c.value("div", 0)) + " div";
  if (c.value("sqrt", 0)) s += ", " + std::to_string(c.value("sqrt", 0)) + " sqrt";
  if (c.value("other", 0)) s += ", " + c.value("other_calls", std::string());
  return s;
}

int runDrift(const std::vector<std::string>& argv) {
  auto fail = [](const std::string& message) { return commandError("drift", message); };
  options::Args args(argv, {{"steps", "json"}, {}, {}});
  if (!args.error().empty()) return fail(args.error());
  if (!args.positional().empty()) return fail("unexpected argument '" + args.positional()[0] + "'");
  const std::optional<double> steps = double(args.integer("steps", 1000000, 1, 1000000000));
  if (const auto path = args.get("json"))  // refused (or its folder made) before the steps
    if (Status ok = prepareOutputFile("--json", *path); !ok) return fail(ok.error());
  const nlohmann::json j = report::driftJson(int64_t(*steps));
  std::printf("Camera drift after %.0f steps (turn 2e-3 rad + move 1e-3 per step, float):\n"
              "distance from the group: matrix max|M^T eta M - eta|, motor max(|M~M - 1|) "
              "(S3 pair: max ||L|^2 - 1|, ||R|^2 - 1|)\n\n", *steps);
  std::printf("%-4s %-7s %-13s %-13s %-34s %s\n", "", "side", "raw", "renormalised", "one step",
              "one renormalisation");
  for (const nlohmann::json& sp : j["spaces"])
    for (const char* side : {"matrix", "motor"}) {
      const nlohmann::json& d = sp[side];
      std::printf("%-4s %-7s %-13.3g %-13.3g %-34s %s\n", sp["space"].get<std::string>().c_str(), side,
                  d["raw"].get<double>(), d["renormalised"].get<double>(), opsText(d["stepOps"]).c_str(),
                  opsText(d["renormOps"]).c_str());
    }
  if (const auto path = args.get("json")) {
    nlohmann::json out = j;
    out["tool"] = "motorbench drift";
    if (Status w = writeTextFile(*path, out.dump(2) + "\n"); !w) return fail(w.error());
  }
  return 0;
}

}  // namespace
}  // namespace mb

MB_COMMAND(drift, "drift", "[--steps N] [--json FILE]",
           "curved-space camera drift: matrix vs motor after N float steps, raw and renormalised",
           mb::runDrift);
MB_COMMAND_HELP(drift, "drift",
               "  --steps N          camera steps (default 1000000)\n"
               "  --json FILE        the result as JSON\n",
                "motorbench drift --steps 10000", false);
