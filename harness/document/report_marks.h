// What report.md / report.html mark as not measured or not right: the scenes that
// failed with their reasons, the frames whose drawn pixels say the two pipelines drew different
// shapes (report.json frames[].drawnCheck, compare's check), and the motor family's exact
// fallbacks per pipeline. Laid out from report.json only, as the rest of the document.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/document/report_model.h"

namespace mb::document {

// "id (failed): reason" for every scene not "ok" (failed or partial), in report order.
std::vector<std::string> failedSceneLines(const nlohmann::json& report);
// The status cell of the scenes table: "ok", or "failed: <reason>".
std::string statusText(const nlohmann::json& scene);

// The frame's drawn-pixel check of pipeline `p` against the baseline: "" when it passed or was
// not recorded, else "FAILED: <reason>".
std::string drawnMark(const nlohmann::json& frame, const std::string& p);
// Whether the frame's difference of `p` may be labelled the skinning methods' difference:
// `sceneLevel` (the scene is skinned and the methods differ) and the frame's check allows it
// (a report.json without drawnCheck: `sceneLevel`).
bool methodDifferenceAllowed(const nlohmann::json& frame, const std::string& p, bool sceneLevel);
// Frames of scene `s` whose drawn-pixel check of `p` failed.
int drawnFailures(const nlohmann::json& s, const std::string& p);

// A table of the exact fallbacks (linear and skin fallback draws, joints, vertices) of each of
// `pipes` in scene `s`; nothing when every count is 0.
void exactFallbackTable(Document& d, const nlohmann::json& s, const std::vector<std::string>& pipes);

}  // namespace mb::document
