// Helpers the report layout's files share (report_layout*.cpp): which pipelines a report or a
// scene has, safe member access and the cell texts every section prints the same way.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace mb::document::layout {

using json = nlohmann::json;

// The run's pipelines (settings.pipelines).
std::vector<std::string> pipelinesOf(const json& r);
// The pipelines a scene was measured with (its space's; a report.json without per-scene
// pipelines: the run's).
std::vector<std::string> pipelinesOf(const json& r, const json& scene);
// The object at j[key] by reference (an empty object when absent): safe to iterate with
// items(), unlike the temporary that json::value() returns.
const json& members(const json& j, const char* key);
// A string as is, a number with 6 digits, else `fallback`.
std::string str(const json& v, const std::string& fallback = "-");
// " over N scenes" for a spread (its "n"), so a median says how many scenes it covers: the
// pipelines' figures may come from different scene sets (a skin-only quantity, a failed scene).
std::string scenesText(const json& spread, const char* what = "scenes");
// The non-zero fallback counters of a scene's pipeline ("none" when all are 0).
std::string fallbacksText(const json& pipelineJson);

}  // namespace mb::document::layout
