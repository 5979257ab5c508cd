#include "harness/document/report_layout_common.h"

#include "harness/document/report_format.h"

namespace mb::document::layout {

std::vector<std::string> pipelinesOf(const json& r) {
  return at(r, {"settings", "pipelines"}).is_array() ? r["settings"]["pipelines"].get<std::vector<std::string>>()
                                                     : std::vector<std::string>{};
}

std::vector<std::string> pipelinesOf(const json& r, const json& scene) {
  const json& order = at(scene, {"pipelineOrder"});
  return order.is_array() && !order.empty() ? order.get<std::vector<std::string>>() : pipelinesOf(r);
}

const json& members(const json& j, const char* key) {
  static const json empty = json::object();
  return j.is_object() && j.contains(key) && j[key].is_object() ? j[key] : empty;
}

std::string str(const json& v, const std::string& fallback) {
  return v.is_string() ? v.get<std::string>() : v.is_number() ? fmt(v, 6) : fallback;
}

std::string scenesText(const json& spread, const char* what) {
  if (!spread.is_object() || spread.value("n", 0) == 0) return "";
  const int n = spread.value("n", 0);
  return " over " + std::to_string(n) + " " + (n == 1 ? std::string(what).substr(0, std::string(what).size() - 1) : what);
}

std::string fallbacksText(const json& pj) {
  std::string s;
  for (const auto& [k, v] : members(pj, "fallbacks").items())
    if (v.is_number() && v.get<double>() != 0) s += (s.empty() ? "" : ", ") + k + " " + fmt(v);
  return s.empty() ? "none" : s;
}

}  // namespace mb::document::layout
