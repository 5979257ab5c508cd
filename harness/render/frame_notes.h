// What a frame did not draw as authored, said next to it: the pipeline's fallbacks (the
// PipelineStats counters of pipelines/pipeline.h that count a case drawn another way) and the
// file's features no pipeline draws (Scene::unsupported, the list `inspect` prints). render and
// compare print these lines on stderr; the report keeps the same counters per pipeline.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipelines/pipeline.h"
#include "pipelines/scene/scene.h"

namespace mb {

// The fallback counters, in PipelineStats' order: the report's `pipelines.<p>.fallbacks`.
const std::vector<std::string>& pipelineFallbackKeys();
// {key: count} for every fallback counter, zeros included.
nlohmann::json pipelineFallbackJson(const PipelineStats& stats);
// One line per non-zero fallback counter, with the glossary's unit and meaning:
// "motor fallback: linearFallbackDraws 3 draws: rigid draws whose ...". Empty when none.
std::vector<std::string> pipelineFallbackLines(const std::string& pipeline, const PipelineStats& stats);
// One line per feature of the file that is not drawn (inspect's "unsupported" list):
// "unsupported (not drawn): mesh 0 primitive 0: 2 morph targets ignored". Empty when none.
std::vector<std::string> unsupportedLines(const Scene& scene);

}  // namespace mb
