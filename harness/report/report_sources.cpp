#include "harness/report/report_sources.h"

#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/scene_stats.h"

namespace mb::report {

std::string sceneOrigin(const std::string& spec) { return isBuiltinScene(spec) ? "built-in" : "file"; }

std::string skinBlendOf(const std::string& pipeline) {
  // From each pipeline's vertex shader: matrix.vs and affine.vs (affine, qtangent, hybrid,
  // matrix_c) blend a matrix palette; motor.vs (motor, motor_q, motor_c, motor_cf) blends joint motors.
  for (const char* lbs : {"matrix", "affine", "qtangent", "hybrid", "matrix_c"})
    if (pipeline == lbs) return "linear blend skinning";
  for (const char* motor : {"motor", "motor_q", "motor_c", "motor_cf"})
    if (pipeline == motor) return "motor blending";
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
