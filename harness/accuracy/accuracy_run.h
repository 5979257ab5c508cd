// `motorbench accuracy`'s document: {"schema": kAccuracySchema, "tool", "scope", "figures":
// {name: figure}, "details": {what each measurement found per scene, animation or mesh}}. The
// built-in run measures every step of builtinSteps(); a run over a folder of skinned files
// measures their volumes only (corpus/accuracy.json).
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipelines/result.h"

namespace mb::accuracy {

inline constexpr const char* kAccuracySchema = "motorbench-accuracy/1";

// An empty document whose "scope" says what the run covers.
nlohmann::json newDocument(const std::string& scope);

// One measurement of the built-in run: a name for the progress line and what it adds to a
// document's "figures" and "details".
struct Step {
  const char* name;
  std::function<void(nlohmann::json& doc)> run;
};
// The camera drift over `driftSteps` steps (the figures' definition: 10^6, kDriftSteps).
std::vector<Step> builtinSteps(int64_t driftSteps);

// The skinned-file volumes of `dir` into `doc`; an error names the folder.
Status addSkinnedFileFigures(const std::string& dir, nlohmann::json& doc);

}  // namespace mb::accuracy
