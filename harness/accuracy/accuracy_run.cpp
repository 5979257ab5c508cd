#include "harness/accuracy/accuracy_run.h"

#include "harness/accuracy/blending.h"
#include "harness/accuracy/conversion.h"
#include "harness/accuracy/drift.h"
#include "harness/accuracy/handedness.h"
#include "harness/accuracy/skinning.h"
#include "harness/report/report_drift.h"
#include "pipelines/scene/builtin_scenes.h"

namespace mb::accuracy {

using json = nlohmann::json;

json newDocument(const std::string& scope) {
  return {{"schema", kAccuracySchema}, {"tool", "motorbench accuracy"}, {"scope", scope},
          {"figures", json::object()}, {"details", json::object()}};
}

std::vector<Step> builtinSteps(int64_t driftSteps) {
  return {
      {"handedness rule", [](json& d) { putHandednessFigures(measureHandedness(builtinSceneNames()), d["figures"], d["details"]); }},
      {"motor blend vs slerp", [](json& d) { putBlendFigures(measureBlending(builtinSceneNames()), d["figures"], d["details"]); }},
      {"candy wrapper skinning", [](json& d) { putCandyWrapperFigures(measureCandyWrapper(), d["figures"], d["details"]); }},
      {"quaternion to rotor", [](json& d) { putConversionFigures(checkRotorFromQuat(kRandomQuaternions), d["figures"]); }},
      {"curved camera drift",
       [driftSteps](json& d) { putDriftFigures(report::driftJson(driftSteps), d["figures"], d["details"]); }},
  };
}

Status addSkinnedFileFigures(const std::string& dir, json& doc) {
  auto volumes = measureSkinnedFileVolumes(dir);
  if (!volumes) return Status::fail(volumes.error());
  putSkinnedFileFigures(*volumes, doc["figures"], doc["details"]);
  return {};
}

}  // namespace mb::accuracy
