#include "harness/document/report_marks.h"

#include "harness/document/report_format.h"

namespace mb::document {
namespace {

using json = nlohmann::json;

const json& check(const json& frame, const std::string& p) {
  static const json none;
  const json& c = at(frame, {"drawnCheck"});
  return c.is_object() && c.contains(p) && c[p].is_object() ? c[p] : none;
}

std::string errorOf(const json& scene) {
  return scene.contains("error") && scene["error"].is_string() ? scene["error"].get<std::string>() : "no reason recorded";
}

}  // namespace

std::vector<std::string> failedSceneLines(const json& r) {
  std::vector<std::string> lines;
  for (const json& s : r.value("scenes", json::array()))
    if (const std::string status = s.value("status", "failed"); status != "ok")
      lines.push_back(s.value("id", "?") + " (" + status + "): " + errorOf(s));
  return lines;
}

std::string statusText(const json& s) {
  const std::string status = s.value("status", "failed");
  return status == "ok" ? status : status + ": " + errorOf(s);
}

std::string drawnMark(const json& frame, const std::string& p) {
  const json& c = check(frame, p);
  if (!c.is_object() || !c.value("failed", false)) return "";
  return "FAILED: " + (c["reason"].is_string() ? c["reason"].get<std::string>() : std::string("drawn pixels differ"));
}

bool methodDifferenceAllowed(const json& frame, const std::string& p, bool sceneLevel) {
  const json& c = check(frame, p);
  return sceneLevel && (!c.is_object() || c.value("skinningMethodNote", false));
}

int drawnFailures(const json& s, const std::string& p) {
  int n = 0;
  for (const json& f : s.value("frames", json::array())) n += !drawnMark(f, p).empty();
  return n;
}

void exactFallbackTable(Document& d, const json& s, const std::vector<std::string>& pipes) {
  static const char* const kKeys[] = {"linearFallbackDraws", "skinFallbackDraws", "skinFallbackJoints",
                                      "fallbackVertices"};
  std::vector<std::vector<Cell>> rows;
  for (const std::string& p : pipes) {
    const json& fb = at(s, {"pipelines"}).is_object() && s["pipelines"].contains(p) ? at(s["pipelines"][p], {"fallbacks"}) : json();
    if (!fb.is_object()) continue;
    bool any = false;
    std::vector<Cell> row = {{p}};
    for (const char* k : kKeys) {
      const json& v = fb.contains(k) ? fb[k] : json();
      any = any || (v.is_number() && v.get<double>() != 0);
      row.push_back({fmt(v, 12)});
    }
    if (any) rows.push_back(row);
  }
  if (rows.empty()) return;
  d.paragraph("Exact fallbacks of the motor family (the most in any frame drawn): rigid draws whose world transform is not a "
              "similarity, drawn with a general linear part before the motor; skinned draws whose joint palette is not "
              "one common uniform scale, their joints, and the vertices all those draws drew (see the Glossary).");
  d.table({"pipeline", "linear fallback draws", "skin fallback draws", "skin fallback joints", "fallback vertices"}, rows);
}

}  // namespace mb::document
