#include "harness/report/report_sources.h"

#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/skin_method.h"
#include "pipelines/scene/scene_stats.h"

namespace mb::report {

std::string sceneOrigin(const std::string& spec) { return isBuiltinScene(spec) ? "built-in" : "file"; }

std::string skinBlendOf(const std::string& pipeline) {
  switch (skinMethodOf(pipeline)) {  // the pipeline's registry line (pipelines/skin_method.h)
    case SkinMethod::LinearBlend: return "linear blend skinning";
    case SkinMethod::MotorBlend: return "motor blending";
    case SkinMethod::None: return "";
  }
  return "";
}

nlohmann::json statisticsByOrigin(const nlohmann::json& scenes) {
  nlohmann::json builtIn = nlohmann::json::array(), files = nlohmann::json::array();
  for (const nlohmann::json& s : scenes) {
    if (!s.contains("stats") || !s["stats"].is_object()) continue;
    const std::string origin = s.value("origin", sceneOrigin(s.value("spec", "")));
    (origin == "built-in" ? builtIn : files).push_back(s["stats"]);
  }
  return {{"builtIn", aggregateFileJson(builtIn)}, {"files", aggregateFileJson(files)}};
}

}  // namespace mb::report
