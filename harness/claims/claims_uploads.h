// Where the claims read a pipeline's uploads (PipelineStats): report.json's
// scenes[].pipelines[p].stats, which the report room measured from its own renders, when claims
// was given a report (claims given its JSON inputs opens no GL context and renders nothing);
// else one 32x32 render here (claims run without a report).
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipelines/pipeline.h"
#include "pipelines/result.h"

namespace mb::claims {

class Uploads {
 public:
  Uploads() = default;  // renders here
  // report.json's "scenes" (an array) and where it came from: reads them, never renders.
  Uploads(const nlohmann::json& reportScenes, std::string reportSource);
  // Adds another report's scenes (a report of real files: `claims --corpus-report`) after these.
  void addReport(const nlohmann::json& reportScenes, const std::string& reportSource);

  // The uploads of `pipeline` drawing `scene` (a built-in scene name); from the report, the
  // scene and pipeline as the report drew them, or the error saying which is missing.
  Result<PipelineStats> of(const std::string& scene, const std::string& pipeline) const;
  // report.json's "memory" entry of the scene and pipeline (bytesPerVertexNotNormalMapped ...),
  // or null (not from a report, or absent).
  nlohmann::json memoryOf(const std::string& scene, const std::string& pipeline) const;
  bool fromReport() const { return fromReport_; }
  // "report.json (its scenes' uploads)" or "renders here".
  std::string source() const;
  // Every scene id of the report, in its order (empty when not from a report).
  std::vector<std::string> reportSceneIds() const;

 private:
  const nlohmann::json* entry(const std::string& scene, const std::string& pipeline, std::string& why) const;
  bool fromReport_ = false;
  nlohmann::json scenes_;
  std::string reportSource_;
};

}  // namespace mb::claims
