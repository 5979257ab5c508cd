#include "harness/document/report_document.h"

#include <algorithm>
#include <limits>

#include "harness/document/report_figures.h"
#include "harness/document/report_format.h"
#include "harness/figures/figure_statistics.h"

namespace mb::document {
namespace {

using json = nlohmann::json;
using figures::spread;

// A number at `path` inside `j` (a sequence of keys), or NaN.
double number(const json& j, std::initializer_list<const char*> path) {
  const json* at = &j;
  for (const char* k : path) {
    if (!at->is_object() || !at->contains(k)) return std::numeric_limits<double>::quiet_NaN();
    at = &(*at)[k];
  }
  return at->is_number() ? at->get<double>() : std::numeric_limits<double>::quiet_NaN();
}

void push(std::vector<double>& v, double x) {
  if (x == x) v.push_back(x);
}

// A spread plus "none": the scenes where the pipeline uploaded no value of it at all.
json withNone(json spread, int none) {
  spread["none"] = none;
  return spread;
}

json pipelineSummary(const std::vector<json>& scenes, const std::string& p) {
  std::vector<double> bpv, bpvAll, bpvNm, bpvPlain, fpv, fpt, fptScale, fpj, conv, bpi;
  int noTransform = 0;  // scenes where the pipeline uploaded no node transform (skinned or instanced draws only)
  for (const json& s : scenes) {
    if (!s.contains("pipelines") || !s["pipelines"].contains(p)) continue;
    const json& pj = s["pipelines"][p];
    push(bpv, number(pj, {"memory", "bytesPerVertex"}));
    push(bpvAll, number(pj, {"memory", "bytesPerVertexAll"}));
    push(bpvNm, number(pj, {"memory", "bytesPerVertexNormalMapped"}));        // NaN (skipped) when none
    push(bpvPlain, number(pj, {"memory", "bytesPerVertexNotNormalMapped"}));
    const double ts = number(pj, {"memory", "floatsPerTransformWithScale"});
    if (ts > 0) fptScale.push_back(ts);
    // A scene of patches only (teapot) uploads control points, no mesh vertex: no figure, not 0.
    if (const double fv = number(pj, {"memory", "floatsPerVertex"}); fv > 0) fpv.push_back(fv);
    const double t = number(pj, {"memory", "floatsPerTransform"});
    if (t > 0) fpt.push_back(t);
    else if (pj.contains("memory") && pj.value("error", json()).is_null()) ++noTransform;
    const double jn = number(pj, {"memory", "floatsPerJoint"});
    if (jn > 0) fpj.push_back(jn);
    push(conv, number(pj, {"conversionMs", "median"}));
    push(bpi, number(pj, {"memory", "bytesPerInstance"}));  // NaN (skipped) without instances
  }
  return {{"bytesPerVertex", spread(bpv)}, {"bytesPerVertexAll", spread(bpvAll)},
          {"bytesPerVertexNormalMapped", spread(bpvNm)}, {"bytesPerVertexNotNormalMapped", spread(bpvPlain)},
          {"floatsPerTransformWithScale", spread(fptScale)},
          {"floatsPerVertex", spread(fpv)}, {"floatsPerTransform", withNone(spread(fpt), noTransform)},
          {"floatsPerJoint", spread(fpj)}, {"conversionMs", spread(conv)}, {"bytesPerInstance", spread(bpi)}};
}

// Image agreement of `p` with the baseline over the frames of the scenes `include` takes: each
// frame judged against its own reference (judgedFrame) when `judged`, else against the baseline
// (the skinning methods' difference, measured).
template <class Pred>
json imageSummary(const std::vector<json>& scenes, const std::string& p, const std::string& baseline, Pred include,
                  bool judged) {
  std::vector<double> psnr, over1, over4, maxErr;
  int identical = 0, compared = 0, wrongShape = 0, notJudged = 0;
  json against = json::object(), whyNot = json::array();
  for (const json& s : scenes) {
    if (!include(s)) continue;
    for (const json& f : s.value("frames", json::array())) {
      const JudgedFrame j = judged ? judgedFrame(s, f, p, baseline) : JudgedFrame{};
      const json& plain = at(f, {"metrics", p.c_str()});
      if (judged ? !j.compared : !plain.is_object()) continue;
      // compare's drawn-pixel check (one image empty, counts > 1 % apart) failed on this frame
      // (a frame not judged by its own method: against the baseline, the strict reading).
      const json& check = at(f, {"drawnCheck"});
      wrongShape += check.is_object() && check.contains(p) && check[p].is_object() && check[p].value("failed", false);
      if (judged && !j.metrics) {
        ++notJudged;
        const std::string why = s.value("id", "?") + " t=" + fmt(f.value("time", json()), 4) + ": " + j.why;
        if (whyNot.size() < 20) whyNot.push_back(why);  // the first ones: enough to see the reason
        continue;
      }
      const json& m = judged ? *j.metrics : plain;
      ++compared;
      if (judged) against[j.reference] = against.value(j.reference, 0) + 1;
      if (m.value("identical", false)) ++identical;
      else push(psnr, number(m, {"psnr"}));
      push(over1, number(m, {"fractionOver1"}));
      push(over4, number(m, {"fractionOver4"}));
      push(maxErr, number(m, {"maxError"}));
    }
  }
  json out = {{"comparedFrames", compared}, {"identicalFrames", identical}, {"drawnCheckFailed", wrongShape},
              {"psnr", spread(psnr)}, {"fractionOver1", spread(over1)}, {"fractionOver4", spread(over4)},
              {"maxError", spread(maxErr)}};
  if (judged) out.update({{"judgedAgainst", against}, {"notJudgedFrames", notJudged}, {"notJudged", whyNot}});
  return out;
}

// A curved scene's figures side by side: its space's pipelines, floats per instance
// as uploaded, ops per vertex, worst PSNR against the matrix side, frame-time ratios.
json curvedRow(const json& s) {
  json row = {{"id", s.value("id", "")}, {"space", s.value("space", "")}, {"status", s.value("status", "")},
              {"pipelines", s.value("pipelineOrder", json::array())}, {"floatsPerInstance", json::object()},
              {"opsPerVertex", s.value("opsPerVertex", json())}};
  const json& pipelines = at(s, {"pipelines"});
  if (pipelines.is_object())
    for (const auto& [p, pj] : pipelines.items())
      row["floatsPerInstance"][p] = pj.is_object() ? at(pj, {"memory", "floatsPerTransform"}) : json();
  std::vector<double> psnr;
  int identical = 0, compared = 0;
  for (const json& f : s.value("frames", json::array())) {
    const json& metrics = at(f, {"metrics"});
    if (!metrics.is_object()) continue;
    for (const auto& [p, m] : metrics.items()) {
      ++compared;
      if (m.value("identical", false)) ++identical;
      else push(psnr, number(m, {"psnr"}));
    }
  }
  row["images"] = {{"comparedFrames", compared}, {"identicalFrames", identical}, {"psnr", spread(psnr)}};
  const json& t = s.value("timing", json::object());
  row["frameTimeRatio"] = {{"normal", at(t, {"paired_ratio_motor_matrix"})},
                           {"vertexBound", at(t, {"vertexBound", "paired_ratio_motor_matrix"})}};
  return row;
}

}  // namespace

bool isEuclidean(const json& scene) { return scene.value("space", "Euclidean") == "Euclidean"; }

JudgedFrame judgedFrame(const json& scene, const json& frame, const std::string& p, const std::string& baseline) {
  JudgedFrame j;
  const json& plain = at(frame, {"metrics", p.c_str()});
  j.compared = plain.is_object();
  if (!j.compared) return j;
  const json& skin = at(frame, {"skinJudgement", p.c_str()});
  if (skin.is_object()) {
    j.skinnedOwnMethod = true;
    j.reference = skin.value("reference", "");
    const json& own = at(frame, {"referenceMetrics", p.c_str()});
    if (skin.value("judged", false) && own.is_object()) j.metrics = &own;
    else
      j.why = "not judged against the " + j.reference + ": " +
              (skin["why"].is_string() ? skin["why"].get<std::string>() : std::string("no reason recorded"));
    return j;
  }
  if (skinningMethodsDiffer(scene, p, baseline)) {
    j.reference = baseline;
    j.why = "a skinned frame of another skinning method than " + baseline + "'s with no judgement by its own method "
            "(a report.json made before skinned frames were judged so: run the report again)";
    return j;
  }
  j.metrics = &plain;
  j.reference = baseline;
  return j;
}

bool skinningMethodsDiffer(const json& scene, const std::string& p, const std::string& baseline) {
  const json& mix = scene.value("vertexMix", json::object());
  if (!mix.is_object() || !(mix.value("skinned", 0.0) > 0)) return false;
  const json& ps = scene.value("pipelines", json::object());
  auto blend = [&](const std::string& q) {
    return ps.contains(q) && ps[q].is_object() ? ps[q].value("skinBlend", "") : std::string();
  };
  return !blend(p).empty() && !blend(baseline).empty() && blend(p) != blend(baseline);
}

json assembleReport(json machine, json settings, std::vector<json> scenes, json ops, json kernels) {
  const std::vector<std::string> pipelines = settings["pipelines"].get<std::vector<std::string>>();
  for (const json& s : scenes)
    if (s.contains("gl") && (!machine.contains("gl") || machine["gl"].contains("error"))) machine["gl"] = s["gl"];
  json summary = {{"scenes", scenes.size()}, {"ok", 0}, {"partial", 0}, {"failed", 0}};
  for (const json& s : scenes) summary[s.value("status", "failed")] = summary.value(s.value("status", "failed"), 0) + 1;
  for (const std::string& p : pipelines) summary["pipelines"][p] = pipelineSummary(scenes, p);
  // Skinned scenes whose two pipelines blend joints differently (LBS vs motor blending) are
  // summed apart: their difference is the methods' expected one, not an equivalence error.
  for (size_t i = 1; i < pipelines.size(); ++i) {
    const std::string p = pipelines[i], base = pipelines[0];
    auto differ = [&](const json& s) { return skinningMethodsDiffer(s, p, base); };
    auto every = [](const json&) { return true; };
    summary["images"][p] = imageSummary(scenes, p, base, every, true);
    summary["skinningMethodImages"][p] = imageSummary(scenes, p, base, differ, false);
    // The vertex format's own image cost: frames of scenes where the pipeline
    // uploads its mesh vertices (a scene of patches, the teapot, draws none of them).
    auto ownVertices = [&](const json& s) { return number(s, {"pipelines", p.c_str(), "memory", "bytesPerVertex"}) > 0; };
    summary["vertexFormatImages"][p] = imageSummary(scenes, p, base, ownVertices, true);
  }
  json curved = json::array(), origins = {{"built-in", 0}, {"file", 0}};
  for (const json& s : scenes) {
    const std::string origin = s.value("origin", "");
    if (origins.contains(origin)) origins[origin] = origins[origin].get<int>() + 1;
    if (!isEuclidean(s)) {
      curved.push_back(curvedRow(s));
      continue;
    }
  }
  summary["curved"] = curved;
  summary["origins"] = origins;
  const json figures = reportFigures(machine, settings, scenes, ops, kernels);
  // The summary's frame time is the figure (median over scenes of the paired per-frame ratios).
  const auto ft = figures::figureNamed(figures, "frame_time.motor_over_matrix");
  summary["frameTimeRatio"] = {{"figure", "frame_time.motor_over_matrix"}, {"n", ft ? ft->n : 0}};
  if (ft && ft->n > 0) {
    summary["frameTimeRatio"]["median"] = ft->value;
    // The range over the scenes the median is taken over: frame_time.<scene>.motor_over_matrix
    // (not the other pipelines' frame_time.<p>_over_matrix, which share the prefix).
    std::vector<double> perScene;
    for (const auto& [name, f] : figures.items())
      if (name.rfind("frame_time.", 0) == 0 && std::count(name.begin(), name.end(), '.') == 2 &&
          name.size() > 18 && name.compare(name.size() - 18, 18, ".motor_over_matrix") == 0 && f["value"].is_number())
        perScene.push_back(f["value"].get<double>());
    const figures::Quartiles q = figures::quartilesOf(perScene);
    summary["frameTimeRatio"]["min"] = q.min, summary["frameTimeRatio"]["max"] = q.max;
  }
  // CPU kernels, fastest against fastest (not the shim sources against each other), as a time
  // ratio (< 1: motor faster, the report's one convention), with the sides, the
  // CPU and SIMD target they ran on, and the disturbance mark.
  json kr = json::object();
  for (const json& p : kernels.value("pairs", json::array()))
    if (p["ratio_motor_fastest_matrix"].is_number() && p["ratio_motor_fastest_matrix"].get<double>() > 0)
      kr[p.value("pair", "")] = {{"motorOverMatrixTime", 1.0 / p["ratio_motor_fastest_matrix"].get<double>()},
                                 {"fastestMotor", p["fastest_motor"]}, {"fastestMatrix", p["fastest_matrix"]},
                                 {"machine", p.value("machine_text", "")}, {"disturbed", p.value("disturbed", false)}};
  summary["kernelRatios"] = kr;
  return {{"schema", kReportSchema},
          {"tool", "motorbench report"},
          {"machine", machine},
          {"settings", settings},
          {"summary", summary},
          {"figures", figures},
          {"scenes", scenes},
          {"opsPerVertex", ops},
          {"kernels", kernels},
          {"plots", {{"available", false}, {"error", "not made yet"}, {"files", json::array()}}},
          {"files", {{"json", "report.json"}, {"markdown", "report.md"}, {"html", "report.html"},
                     {"bench", kernels.value("file", json())}}}};
}

}  // namespace mb::document
