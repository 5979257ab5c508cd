#include "harness/render/frame_notes.h"

#include "harness/render/counter_glossary.h"
#include "harness/render/render_frame.h"
#include "pipelines/scene/scene_stats.h"

namespace mb {

const std::vector<std::string>& pipelineFallbackKeys() {
  static const std::vector<std::string> keys = {
      "nonUniformScaleNodes", "negativeScaleNodes", "shearMatrixNodes",    "zeroScalarFrames",
      "biasedFrames",         "scaleFallbackInstances", "rotorSplitVertices", "rotorUnresolvedTriangles",
      "linearFallbackDraws",  "skinFallbackDraws",  "skinFallbackJoints",  "fallbackVertices",
      "skinFallbackVertices", "morphNotDrawnNodes"};
  return keys;
}

nlohmann::json pipelineFallbackJson(const PipelineStats& stats) {
  const nlohmann::json all = toJson(stats);  // one serialisation of every counter
  nlohmann::json j = nlohmann::json::object();
  for (const std::string& k : pipelineFallbackKeys()) j[k] = all.contains(k) ? all[k] : nlohmann::json(0);
  return j;
}

std::vector<std::string> pipelineFallbackLines(const std::string& pipeline, const PipelineStats& stats) {
  std::vector<std::string> lines;
  const nlohmann::json j = pipelineFallbackJson(stats);
  for (const std::string& k : pipelineFallbackKeys()) {
    if (!j[k].is_number() || j[k].get<double>() == 0) continue;
    std::string line = pipeline + " fallback: " + k + " " + j[k].dump();
    if (const CounterEntry* e = findCounter("PipelineStats", k))
      line += (e->unit.empty() ? "" : " " + e->unit) + ": " + e->meaning;
    lines.push_back(line);
  }
  return lines;
}

std::vector<std::string> unsupportedLines(const Scene& scene) {
  std::vector<std::string> lines;
  // inspect's own list (FileStats::unsupported), so the two commands never disagree.
  for (const std::string& u : computeFileStats(scene).unsupported) lines.push_back("unsupported (not drawn): " + u);
  return lines;
}

}  // namespace mb
