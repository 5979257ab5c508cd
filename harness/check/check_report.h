// What `motorbench check` found, per golden image, and the people/machine forms of it:
// one console line per image, summary.html (expected / actual / diff side by side for every
// failure and warning) and check.json.
#pragma once
#include <string>

#include <nlohmann/json.hpp>
#include <vector>

#include "harness/render/flip.h"
#include "harness/render/image_metrics.h"
#include "pipelines/result.h"

namespace mb {

struct CheckItem {
  enum class Outcome { Pass, Warn, Fail, Error };
  std::string file, scene, pipeline, pose;
  Outcome outcome = Outcome::Pass;
  std::string level;   // "exact" or "portable" (golden.h's rule)
  bool compared = false;
  ImageMetrics metrics;
  std::string reason;  // why it warned, failed or errored; "" on a clean pass
  // Files written into the output folder, relative to it ("" when not written).
  std::string expected, actual, diff, flipMap;
  FlipResult flip;  // LDR-FLIP of the actual frame against the golden (summary; no map kept)
};

struct CheckRun {
  std::string goldenDir, shaderDir, glRenderer, glVersion;
  std::vector<std::string> notes;  // run-wide warnings (renderer differs, stale entries...)
  std::vector<CheckItem> items;
  nlohmann::json shard;  // {"index", "count", "inputs": every scene of the selection}
};

const char* outcomeName(CheckItem::Outcome o);
std::string consoleLine(const CheckItem& item);
// Writes summary.html and check.json into `dir`; errors name the file.
Status writeCheckReport(const std::string& dir, const CheckRun& run);

}  // namespace mb
