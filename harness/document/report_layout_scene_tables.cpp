// The "Scenes" section: one table of the scene facts, then one small table per quantity with
// the Euclidean scenes as rows and the pipelines as columns, so each fits a page.
#include <algorithm>
#include <functional>
#include <map>

#include "harness/document/report_document.h"
#include "harness/document/report_format.h"
#include "harness/document/report_layout_common.h"
#include "harness/document/report_layout_sections.h"
#include "harness/document/report_marks.h"

namespace mb::document {

using namespace layout;

namespace {

// Worst metrics of `p` over a scene's frames (lowest PSNR, largest changed fraction), each frame
// against its own reference (judgedFrame); the third: "against the motor-blend reference" when a
// skinned frame was judged against its own skinning method's, with the frames not judged.
struct WorstImage {
  std::string psnr = "-", over = "-", note;
};
WorstImage worstImage(const json& s, const std::string& p, const std::string& base) {
  double psnr = 1e300, over = -1;
  bool any = false, allIdentical = true;
  int notJudged = 0;
  std::string own;
  for (const json& f : s.value("frames", json::array())) {
    const JudgedFrame j = judgedFrame(s, f, p, base);
    if (!j.compared) continue;
    if (!j.metrics) {
      ++notJudged;
      continue;
    }
    const json& m = *j.metrics;
    any = true;
    if (j.skinnedOwnMethod && j.reference != base) own = j.reference;
    if (!m.value("identical", false)) {
      allIdentical = false;
      if (m["psnr"].is_number()) psnr = std::min(psnr, m["psnr"].get<double>());
    }
    over = std::max(over, m.value("fractionOver1", 0.0));
  }
  WorstImage w;
  if (any) w.psnr = allIdentical ? "identical" : fixed(json(psnr), 1) + " dB", w.over = percent(json(over), 3);
  if (!own.empty()) w.note = " (skinned: against the " + own + ")";
  if (notJudged) w.note += "; " + std::to_string(notJudged) + " frame(s) not judged";
  return w;
}

// The pipeline `p`'s object in s[key] (null when absent).
const json& pipelineOf(const json& s, const char* key, const std::string& p) {
  static const json none;
  const json& all = at(s, {key});
  return all.is_object() && all.contains(p) ? all[p] : none;
}

using CellOf = std::function<std::string(const json& scene, const std::string& pipeline)>;

// One quantity: its one-line heading, then a row per scene (linked to its section) and a
// column per pipeline in `pipes`, each cell made by `cell`; `extra` adds a last column.
void quantityTable(Document& d, const std::string& heading, const std::vector<const json*>& scenes,
                   const std::vector<std::string>& pipes, const CellOf& cell,
                   const std::string& extraHead = "", const std::function<std::string(const json&)>& extra = {}) {
  d.heading(3, heading);
  std::vector<std::string> head = {"scene"};
  head.insert(head.end(), pipes.begin(), pipes.end());
  if (extra) head.push_back(extraHead);
  std::vector<std::vector<Cell>> rows;
  for (const json* s : scenes) {
    std::vector<Cell> row = {{str((*s)["id"]), "", "#scene-" + str((*s)["id"])}};
    for (const std::string& p : pipes) row.push_back({cell(*s, p)});
    if (extra) row.push_back({extra(*s)});
    rows.push_back(std::move(row));
  }
  d.table(head, rows);
}

void factsTable(Document& d, const std::vector<const json*>& scenes) {
  d.heading(3, "Scene facts: origin, status, vertices, triangles, skins / joints, animations (counts)");
  std::vector<std::vector<Cell>> rows;
  for (const json* sp : scenes) {
    const json& s = *sp;
    const json& st = s.value("stats", json::object());
    rows.push_back({{str(s["id"]), "", "#scene-" + str(s["id"])}, {str(s["origin"])}, {statusText(s)},
                    {str(at(st, {"geometry", "vertices"})) + " / " + str(at(st, {"geometry", "drawnVertices"}))},
                    {str(at(st, {"geometry", "triangles"}))},
                    {str(at(st, {"skinning", "skins"})) + " / " + str(at(st, {"skinning", "joints"}))},
                    {str(at(st, {"animation", "animations"}))}});
  }
  d.table({"scene", "origin", "status", "vertices (mesh / drawn)", "triangles", "skins / joints", "animations"}, rows);
}

// Every pipeline's non-zero fallback counters per scene: a row per scene and distinct set of
// counters, naming the pipelines that have it; scenes without any are left out.
void fallbackTable(Document& d, const std::vector<const json*>& scenes, const std::vector<std::string>& pipes) {
  d.heading(3, "Fallbacks: each pipeline's non-zero fallback counters (counts; scenes without any left out)");
  std::vector<std::vector<Cell>> rows;
  for (const json* s : scenes) {
    std::vector<std::pair<std::string, std::string>> groups;  // counters, pipelines (first-seen order)
    for (const std::string& p : pipes) {
      const json& pj = pipelineOf(*s, "pipelines", p);
      const std::string text = pj.is_object() ? fallbacksText(pj) : "none";
      if (text == "none") continue;
      auto g = std::find_if(groups.begin(), groups.end(), [&](const auto& e) { return e.first == text; });
      if (g == groups.end()) groups.push_back({text, p});
      else g->second += ", " + p;
    }
    for (const auto& [text, names] : groups)
      rows.push_back({{str((*s)["id"]), "", "#scene-" + str((*s)["id"])}, {names}, {text}});
  }
  if (rows.empty()) rows.push_back({{"every scene"}, {"every pipeline"}, {"none"}});
  d.table({"scene", "pipelines", "fallback counters"}, rows);
}

}  // namespace

void sceneTable(Document& d, const json& r) {
  const std::vector<std::string> pipes = pipelinesOf(r);
  d.heading(2, "Scenes", "scenes");
  std::vector<const json*> scenes;  // the curved scenes have their own section and pipelines
  for (const json& s : r["scenes"])
    if (isEuclidean(s)) scenes.push_back(&s);
  factsTable(d, scenes);
  quantityTable(d, "Bytes per vertex [B]: shading attributes uploaded per vertex", scenes, pipes,
                [](const json& s, const std::string& p) { return fmt(at(pipelineOf(s, "pipelines", p), {"memory", "bytesPerVertex"})); });
  quantityTable(d, "Ops per vertex [mul+add]: counted arithmetic of one drawn vertex", scenes, pipes,
                [](const json& s, const std::string& p) {
                  const json& c = at(pipelineOf(s, "opsPerVertex", p), {"counted"});
                  return c.is_object() ? fmt(json(c.value("mul", 0.0) + c.value("add", 0.0)), 4) + " mul+add" : std::string("-");
                });
  quantityTable(d, "Frame time [ms]: median per pipeline; motor/matrix the median of paired per-frame ratios", scenes, pipes,
                [](const json& s, const std::string& p) {
                  const json& t = pipelineOf(at(s, {"timing"}), "pipelines", p);
                  return fixed(t.is_object() ? t.value("medianMs", json()) : json(), 2);
                },
                "motor/matrix", [](const json& s) { return ratio(at(s, {"timing", "paired_ratio_motor_matrix"})); });
  d.paragraph(frameTimeOn(at(r, {"machine", "gl"})) + ".");
  const std::vector<std::string> compared(pipes.begin() + std::min<ptrdiff_t>(1, ptrdiff_t(pipes.size())), pipes.end());
  const std::string base = pipes.empty() ? std::string() : pipes[0];
  std::map<std::pair<const json*, std::string>, WorstImage> worst;  // both image tables read it
  for (const json* s : scenes)
    for (const std::string& p : compared) worst[{s, p}] = worstImage(*s, p, base);
  quantityTable(d, "Worst PSNR [dB] over the scene's frames, each against " + base + " (or its own skinning method's reference)",
                scenes, compared, [&worst](const json& s, const std::string& p) {
                  const WorstImage& w = worst.at({&s, p});
                  const int wrong = drawnFailures(s, p);
                  return w.psnr + w.note + (wrong ? "; " + std::to_string(wrong) + " frame(s) FAILED the drawn-pixel check" : "");
                });
  quantityTable(d, "Pixels off by more than 1/255 [%]: the largest share over the scene's frames", scenes, compared,
                [&worst](const json& s, const std::string& p) { return worst.at({&s, p}).over; });
  fallbackTable(d, scenes, pipes);
}

}  // namespace mb::document
