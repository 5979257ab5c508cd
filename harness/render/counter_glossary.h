// What every counter the tool prints means: PipelineStats (memory, draws, pipeline fallbacks),
// LoadStats (what the loader had to fix) and the image metrics of compare/report/check. One
// table, shown on stderr next to a non-zero loader fallback (render/compare), as the report's
// glossary (report.json "glossary") and in the README (a test keeps the README in step).
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipelines/scene/scene.h"

namespace mb {

struct CounterEntry {
  std::string group;  // "PipelineStats", "LoadStats", "ImageMetrics"
  std::string key;    // field name as in the JSON files (toJson)
  std::string unit;   // "bytes", "vertices", "primitives", ... ("" when a plain number)
  std::string meaning;
};

// Every counter, grouped, in the order of the structs. A test checks that every key of
// toJson(PipelineStats), toJson(LoadStats) and toJson(ImageMetrics) has an entry.
const std::vector<CounterEntry>& counterGlossary();
// The entry of `key` in `group`, nullptr when none.
const CounterEntry* findCounter(const std::string& group, const std::string& key);
// {group: {key: {"unit", "meaning"}}} for report.json.
nlohmann::json glossaryJson();

// One line per non-zero LoadStats counter of `scene`, for stderr: "loader fallback:
// imagesNotDecoded 1 (images): image not decoded; sampled as 1x1 white". Empty when none.
std::vector<std::string> loaderFallbackLines(const Scene& scene);
// The non-zero LoadStats counters of `scene` as {key: count} (empty object when none).
nlohmann::json loaderFallbackJson(const Scene& scene);

}  // namespace mb
