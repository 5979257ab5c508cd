// What `motorbench check` found, per golden image, and the people/machine forms of it:
// one console line per image, summary.html (expected / actual / diff side by side for every
// failure and warning) and check.json.
#pragma once
#include <string>

#include <nlohmann/json.hpp>
#include <vector>

#include "harness/check/junit.h"
#include "harness/render/flip.h"
#include "harness/render/image_metrics.h"
#include "pipelines/result.h"

namespace mb::check {

struct CheckItem {
  // Changed: a user's file whose content hash differs from the one its goldens were recorded
  // from (content_hash.h); its images are not judged, and the run fails (exit 1).
  enum class Outcome { Pass, Warn, Fail, Error, Changed };
  static constexpr int kOutcomes = 5;
  std::string file, scene, pipeline, pose;
  Outcome outcome = Outcome::Pass;
  std::string level;   // "exact" or "portable" (golden.h's rule)
  bool compared = false;
  ImageMetrics metrics;
  std::string reason;  // why it warned, failed or errored; "" on a clean pass
  // Files written into the output folder, relative to it ("" when not written).
  std::string expected, actual, diff, flipMap;
  FlipResult flip;  // LDR-FLIP of the actual frame against the golden (summary; no map kept)
  std::string source;  // the scene as the user named it: a file's relative path, a built-in's name
  double seconds = 0;  // render and comparison
};

// A user's file whose goldens were recorded from other bytes.
struct ChangedSource {
  std::string scene, path, recorded, now;  // golden scene name, relative path, sha256 then and now
  int images = 0;                          // its goldens, not judged
};

struct CheckRun {
  std::string goldenDir, shaderDir, glRenderer, glVersion;
  std::vector<std::string> notes;  // run-wide warnings (renderer differs, stale entries...)
  std::vector<CheckItem> items;
  std::vector<ChangedSource> changed;
  nlohmann::json shard;  // {"index", "count", "inputs": every scene of the selection}
};

const char* outcomeName(CheckItem::Outcome o);
std::string consoleLine(const CheckItem& item);
// "CHANGED  props/Fox.glb: changed since its goldens were recorded (...); run check --update ...".
std::string changedLine(const ChangedSource& changed);
// The summary line: "check: 27 images: 25 passed, 1 warned, 1 failed, 0 errors" (and the files
// changed, when any).
std::string summaryLine(const CheckRun& run);
// 0 pass (warnings allowed), 1 a threshold exceeded or a file changed, 2 an error.
int exitCode(const CheckRun& run);
// One JUnit case per image: classname the scene as named (file path or built-in), name
// "<pose>.<pipeline>"; FAIL and CHANGED are failures, ERROR errors, WARN passes.
std::vector<JunitCase> junitCases(const CheckRun& run);
// Writes summary.html and check.json into `dir`; errors name the file.
Status writeCheckReport(const std::string& dir, const CheckRun& run);

}  // namespace mb::check
