#include "harness/document/report_kind_figures.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>

#include "harness/document/report_document.h"
#include "harness/document/report_figures.h"
#include "harness/document/report_format.h"
#include "harness/document/report_isa.h"
#include "harness/figures/figure.h"

namespace mb::document {
namespace {

using json = nlohmann::json;
using figures::Figure;
using figures::numberOrNaN;

const char* kNotRecorded =
    "not recorded in this report.json (its scenes carry no contentKinds: made before the answer was split by kind)";
const char* kCountDevice = "counted on the loaded scene (the draw list, times each node's instances)";
const char* kFetchDevice = "meshoptimizer's analyzers on each drawn primitive with the pipeline's stride (not timed)";

bool isFile(const json& s) { return s.value("origin", "") == "file"; }

bool anyFile(const json& r) {
  for (const json& s : r["scenes"])
    if (isFile(s)) return true;
  return false;
}

// The scenes a kind is measured over: the content (the file scenes, else every scene), or the
// built-in scenes beside files for "built_in". Euclidean scenes that recorded their kinds.
std::vector<const json*> scopeScenes(const json& r, const std::string& kind) {
  const bool files = anyFile(r);
  std::vector<const json*> out;
  for (const json& s : r["scenes"]) {
    if (!isEuclidean(s) || !at(s, {"contentKinds", "cells"}).is_array()) continue;
    if (kind == "built_in" ? files && !isFile(s) : !files || isFile(s)) out.push_back(&s);
  }
  return out;
}

std::string scopeText(const json& r, const std::string& kind, const std::string& label) {
  const size_t n = scopeScenes(r, kind).size();
  const std::string scenes = kind == "built_in" ? std::to_string(n) + " built-in scene(s), controlled cases"
                             : anyFile(r)       ? "the report's " + std::to_string(n) + " file scene(s)"
                                                : "the report's " + std::to_string(n) + " scene(s)";
  return (kind == "all" || kind == "built_in" ? "every drawn primitive" : "drawn primitives " + label) + " of " +
         scenes + ", one frame, Euclidean scenes";
}

bool cellIn(const json& cell, const std::string& kind) {
  if (kind == "all" || kind == "built_in") return true;
  if (kind == "normal_mapped") return cell.value("normalMapped", false);
  if (kind == "not_normal_mapped") return !cell.value("normalMapped", false);
  return cell.value("deformation", "") == kind;
}

// The key of pipelines[p].vertexFetch.byKind for a kind ("" for the whole scene).
std::string fetchKey(const std::string& kind) {
  if (kind == "normal_mapped") return "normalMapped";
  if (kind == "not_normal_mapped") return "notNormalMapped";
  return kind == "all" || kind == "built_in" ? "" : kind;
}

double kindVertices(const json& s, const std::string& kind, const char* what = "vertices") {
  double v = 0;
  for (const json& c : s["contentKinds"]["cells"])
    if (cellIn(c, kind)) v += c.value(what, 0.0);
  return v;
}

Figure make(const std::string& name, const std::string& unit, const std::string& statistic, const std::string& scope,
            const std::string& device, const std::string& definition) {
  Figure f;
  f.name = name, f.unit = unit, f.statistic = statistic, f.scope = scope, f.device = device, f.definition = definition;
  f.value = std::nan("");
  // The kind of figure by its family: fetched bytes a model, ops counted or compiled, ISA compiled.
  f.kind = name.find("fetched") != std::string::npos                                        ? "modelled"
           : name.find("ops_counted") != std::string::npos                                  ? "counted"
           : name.find("ops_spirv") != std::string::npos || name.find("isa_") != std::string::npos ? "compiled"
                                                                                             : "measured";
  return f;
}

void putValue(json& out, Figure f, double value, int n, const std::string& whyMissing) {
  f.value = value, f.n = std::isfinite(value) ? n : 0;
  if (!std::isfinite(value)) f.why = whyMissing;
  figures::put(out, f);
}

void countFigures(json& out, const json& r, const ContentKindDef& k, double allVertices, double allPrimitives) {
  double v = 0, p = 0;
  const std::vector<const json*> scenes = scopeScenes(r, k.id);
  for (const json* s : scenes) v += kindVertices(*s, k.id), p += kindVertices(*s, k.id, "primitives");
  const std::string scope = scopeText(r, k.id, k.label);
  const int n = int(scenes.size());
  putValue(out, make("kind.vertices." + k.id, "vertices", "sum over scenes", scope, kCountDevice,
                     "vertices drawn per frame (each primitive's vertices times its node's instances)"),
           n ? v : std::nan(""), n, "no scene recorded its content kinds");
  putValue(out, make("kind.primitives." + k.id, "primitives", "sum over scenes", scope, kCountDevice,
                     "primitives drawn per frame (times each node's instances)"),
           n ? p : std::nan(""), n, "no scene recorded its content kinds");
  if (k.id == "all" || k.id == "built_in") return;
  putValue(out, make("kind.share_vertices." + k.id, "%", "share of a sum", scope, kCountDevice,
                     "drawn vertices of this kind / drawn vertices of the content, in %"),
           allVertices > 0 ? 100 * v / allVertices : std::nan(""), n, "the content draws no vertex");
  putValue(out, make("kind.share_primitives." + k.id, "%", "share of a sum", scope, kCountDevice,
                     "drawn primitives of this kind / drawn primitives of the content, in %"),
           allPrimitives > 0 ? 100 * p / allPrimitives : std::nan(""), n, "the content draws no primitive");
}

struct FetchSum {
  double fetched = 0, unique = 0, referenced = 0;
  int scenes = 0;
};

// Per frame, summed over the scenes both `p` and `base` measured.
FetchSum fetchSum(const std::vector<const json*>& scenes, const std::string& kind, const std::string& p,
                  const std::string& base) {
  FetchSum sum;
  const std::string key = fetchKey(kind);
  for (const json* s : scenes) {
    const json& f = at(*s, {"pipelines", p.c_str(), "vertexFetch"});
    if (!f.is_object() || !at(*s, {"pipelines", base.c_str(), "vertexFetch"}).is_object()) continue;
    const json& k = key.empty() ? f : at(f, {"byKind", key.c_str()});
    ++sum.scenes;
    if (!k.is_object()) continue;  // the scene has none of this kind
    sum.fetched += k.value("bytesFetchedPerFrame", 0.0), sum.unique += k.value("uniqueVertexBytesPerFrame", 0.0);
    sum.referenced += k.value("verticesReferencedPerFrame", 0.0);
  }
  return sum;
}

void bytesFigures(json& out, const json& r, const ContentKindDef& k, const std::vector<std::string>& pipes) {
  const std::string base = pipes.empty() ? "" : pipes[0];
  const std::vector<const json*> scenes = scopeScenes(r, k.id);
  const std::string scope = scopeText(r, k.id, k.label);
  for (const std::string& p : pipes) {
    const FetchSum s = fetchSum(scenes, k.id, p, base), b = fetchSum(scenes, k.id, base, base);
    const std::string none = s.scenes ? "the content has no vertex of this kind" : "no scene measured the vertex fetch";
    auto per = [](double a, double n) { return n > 0 ? a / n : std::nan(""); };
    putValue(out, make("kind.fetched_bytes_per_vertex." + k.id + "." + p, "bytes", "sum over scenes / sum over scenes",
                       scope, kFetchDevice, "bytes fetched per vertex referenced in meshoptimizer's fetch model (64-byte lines), with " + p + "'s stride"),
             per(s.fetched, s.referenced), s.scenes, none);
    putValue(out, make("kind.uploaded_bytes_per_vertex." + k.id + "." + p, "bytes", "sum over scenes / sum over scenes",
                       scope, kFetchDevice, "shading-attribute bytes " + p + " uploads per vertex referenced (its stride)"),
             per(s.unique, s.referenced), s.scenes, none);
    if (p == base) continue;
    putValue(out, make("kind.fetched_over_baseline." + k.id + "." + p, "x", "ratio of sums over scenes", scope,
                       kFetchDevice, "bytes fetched per frame " + p + " / " + base + " (< 1: " + p + " cheaper)"),
             per(s.fetched, b.fetched), s.scenes, none);
    putValue(out, make("kind.uploaded_over_baseline." + k.id + "." + p, "x", "ratio of sums over scenes", scope,
                       kFetchDevice, "vertex bytes uploaded for one frame's vertices " + p + " / " + base +
                                         " (< 1: " + p + " cheaper)"),
             per(s.unique, b.unique), s.scenes, none);
  }
}

// The cost of one shader variant (by its label) of a pipeline; NaN where none was measured.
using CostOf = std::function<double(const std::string& label)>;

double firstCost(const CostOf& cost, std::initializer_list<const char*> labels) {
  for (const char* l : labels)
    if (const double c = cost(l); std::isfinite(c)) return c;
  return std::nan("");
}

// The scene's exact-fallback shares of its rigid and skinned vertices (as report_ops weighs the
// scene's ops: vertexMix and opsPerVertex[p].fallbackVertices), spread evenly over its cells.
struct Fractions {
  double scaled = 0, linear = 0, skinLinear = 0;
};

Fractions fractionsOf(const json& s, const std::string& p) {
  const json& mix = at(s, {"vertexMix"});
  const double rigid = numberOrNaN(at(mix, {"rigid"})), skinned = numberOrNaN(at(mix, {"skinned"}));
  const double scaled = numberOrNaN(at(mix, {"scaledFallback"}));
  const json& fb = at(s, {"opsPerVertex", p.c_str(), "fallbackVertices"});
  const double fbRigid = numberOrNaN(at(fb, {"rigid"})), fbSkin = numberOrNaN(at(fb, {"skinned"}));
  Fractions f;
  if (rigid > 0) {
    f.linear = fbRigid > 0 ? std::min(1.0, fbRigid / rigid) : 0;
    f.scaled = scaled > 0 ? std::min(1.0, scaled / rigid) : 0;
  }
  if (skinned > 0 && fbSkin > 0) f.skinLinear = std::min(1.0, fbSkin / skinned);
  return f;
}

// The cost per vertex of a cell: the variant its primitives draw with (the most specific one
// the pipeline has: a no-tangent variant for primitives without a normal map, the instanced or
// morph variant), mixed with the scene's exact-fallback variants by their share.
double cellCost(const json& cell, const Fractions& fr, const CostOf& cost) {
  const bool nm = cell.value("normalMapped", false), instanced = cell.value("instanced", false);
  const std::string deformation = cell.value("deformation", "rigid");
  if (deformation == "skinned") {
    const double base = nm ? cost("skinned") : firstCost(cost, {"skinned, no tangent", "skinned"});
    const double fb = cost("skinned, linear fallback");
    return std::isfinite(fb) && fr.skinLinear > 0 ? (1 - fr.skinLinear) * base + fr.skinLinear * fb : base;
  }
  double base;
  if (deformation == "morph") base = firstCost(cost, {"rigid, morph", "rigid, morph frame (a)", "rigid"});
  else if (instanced)
    base = nm ? firstCost(cost, {"rigid, instanced", "rigid"})
              : firstCost(cost, {"rigid, no tangent, instanced", "rigid, instanced", "rigid, no tangent", "rigid"});
  else base = nm ? cost("rigid") : firstCost(cost, {"rigid, no tangent", "rigid"});
  const double linear = instanced ? std::nan("") : cost("linear fallback");
  const double scaled = instanced ? firstCost(cost, {"scaled fallback, instanced", "scaled fallback"}) : cost("scaled fallback");
  const double fl = std::isfinite(linear) ? fr.linear : 0;
  const double fs = std::isfinite(scaled) ? std::min(fr.scaled, 1 - fl) : 0;
  double c = (1 - fl - fs) * base;
  if (fl > 0) c += fl * linear;
  if (fs > 0) c += fs * scaled;
  return c;
}

// Mean over the kind's drawn vertices of each cell's cost; NaN (with `why`) where a variant is missing.
double weightedCost(const std::vector<const json*>& scenes, const std::string& kind, const std::string& p,
                    const std::function<CostOf(const std::string&)>& costFor, int& n) {
  double sum = 0, vertices = 0;
  n = 0;
  const CostOf cost = costFor(p);
  for (const json* s : scenes) {
    if (!at(*s, {"pipelines", p.c_str()}).is_object()) continue;
    const Fractions fr = fractionsOf(*s, p);
    ++n;
    for (const json& c : (*s)["contentKinds"]["cells"]) {
      const double v = c.value("vertices", 0.0);
      if (!cellIn(c, kind) || v <= 0) continue;
      sum += v * cellCost(c, fr, cost), vertices += v;
    }
  }
  return vertices > 0 ? sum / vertices : std::nan("");
}

const char* kVariantStatistic = "mean over drawn vertices, each by the shader variant its primitive draws with";
const char* kVariantDefinition =
    " per vertex, each vertex by its primitive's variant (no-tangent variants for primitives without a normal map where "
    "the pipeline has them, instanced and morph variants), the exact fallback's variants by the scene's share of "
    "fallback vertices";

void opsFigures(json& out, const json& r, const ContentKindDef& k, const std::vector<std::string>& pipes) {
  const std::vector<const json*> scenes = scopeScenes(r, k.id);
  const json& variants = at(r, {"opsPerVertex", "variants"});
  for (const char* way : {"counted", "spirv"}) {
    auto costFor = [&](const std::string& p) -> CostOf {
      return [&, p](const std::string& label) {
        for (const json& v : variants.is_array() ? variants : json::array())
          if (v.value("pipeline", "") == p && v.value("label", "") == label) return opsTotal(v.value(way, json()));
        return std::nan("");
      };
    };
    for (const std::string& p : pipes) {
      int n = 0;
      const double v = weightedCost(scenes, k.id, p, costFor, n);
      putValue(out, make(std::string("kind.ops_") + way + "." + k.id + "." + p, "ops", kVariantStatistic,
                         scopeText(r, k.id, k.label),
                         way == std::string("counted") ? "counted (op-counting scalar through the GLSL shim)"
                                                       : "SPIR-V whole shader (main() included)",
                         std::string("arithmetic operations (mul + add + div + sqrt + other)") + kVariantDefinition),
               v, n, variants.is_array() ? "no vertex of this kind, or a variant it draws was not counted"
                                         : "no ops counted in this report");
    }
  }
}

void isaFigures(json& out, const json& r, const ContentKindDef& k, const std::vector<std::string>& pipes) {
  const json& isa = at(r, {"isa"});
  const std::vector<const json*> scenes = scopeScenes(r, k.id);
  for (const json& fam : at(isa, {"families"}).is_array() ? isa["families"] : json::array()) {
    const std::string id = fam.value("id", "");
    auto costFor = [&](const std::string& p) -> CostOf {
      return [&, p](const std::string& label) {
        const json* row = isaRow(isa, p, label, id);
        return row ? numberOrNaN((*row)["instructions"]) : std::nan("");
      };
    };
    for (const std::string& p : pipes) {
      int n = 0;
      const double v = weightedCost(scenes, k.id, p, costFor, n);
      putValue(out, make("kind.isa_instructions." + k.id + "." + id + "." + p, "instructions", kVariantStatistic,
                         scopeText(r, k.id, k.label),
                         "RADV " + id + " (" + fam.value("generation", "") + "), compiler statistics on the null device, not timed",
                         std::string("ISA instructions of the compiled vertex shader") + kVariantDefinition),
               v, n, "no vertex of this kind, or no compiled shader of a variant it draws");
    }
  }
}

void timeFigure(json& out, const json& r, const ContentKindDef& k) {
  std::vector<double> ratios;
  int withKind = 0;
  for (const json* s : scopeScenes(r, k.id)) {
    if (kindVertices(*s, k.id) <= 0) continue;
    ++withKind;
    const double x = numberOrNaN(at(*s, {"timing", "paired_ratio_motor_matrix"}));
    if (std::isfinite(x)) ratios.push_back(x);
  }
  Figure f = make("kind.frame_time." + k.id, "x", "median over the scenes with this kind of each scene's median of "
                  "per-frame paired ratios", scopeText(r, k.id, k.label) + " (whole scenes that draw this kind)",
                  frameTimeDevice(at(r, {"machine"})), "frame time motor / matrix (< 1: motor faster)");
  f = figures::withQuartiles(f, figures::quartilesOf(ratios));
  if (f.n == 0) f.value = std::nan(""), f.why = withKind ? "not measured: no scene of this kind was timed" : "no scene of this kind";
  figures::put(out, f);
}

void imageFigures(json& out, const json& r, const ContentKindDef& k, const std::vector<std::string>& pipes) {
  const std::string base = pipes.empty() ? "" : pipes[0];
  for (size_t i = 1; i < pipes.size(); ++i) {
    const std::string& p = pipes[i];
    double worst = INFINITY;
    int compared = 0, identical = 0;
    for (const json* s : scopeScenes(r, k.id)) {
      if (kindVertices(*s, k.id) <= 0) continue;
      for (const json& fr : s->value("frames", json::array())) {
        const JudgedFrame j = judgedFrame(*s, fr, p, base);
        if (!j.compared || !j.metrics) continue;
        ++compared;
        if (j.metrics->value("identical", false)) ++identical;
        else if ((*j.metrics)["psnr"].is_number()) worst = std::min(worst, (*j.metrics)["psnr"].get<double>());
      }
    }
    const std::string scope = scopeText(r, k.id, k.label) + " (every frame of the scenes that draw this kind, each "
                              "against its own reference)";
    putValue(out, make("kind.image_worst_psnr." + k.id + "." + p, "dB", "minimum over the frames that differ", scope,
                       "the rendered images (8-bit RGBA)", "PSNR of " + p + " against its reference"),
             std::isfinite(worst) ? worst : std::nan(""), compared,
             compared ? "every compared frame identical" : "no frame compared");
    putValue(out, make("kind.image_identical_frames." + k.id + "." + p, "frames", "count", scope,
                       "the rendered images (8-bit RGBA)", "frames whose every pixel equals their reference's, of n judged"),
             identical, compared, "");
  }
}

void notRecorded(json& out, const ContentKindDef& k) {
  Figure f = make("kind.vertices." + k.id, "vertices", "sum over scenes", "", kCountDevice, "vertices drawn per frame");
  f.why = kNotRecorded;
  figures::put(out, f);
}

}  // namespace

const std::vector<ContentKindDef>& contentKindDefs() {
  static const std::vector<ContentKindDef> kinds = {
      {"all", "all content"},   {"normal_mapped", "normal-mapped"}, {"not_normal_mapped", "not normal-mapped"},
      {"skinned", "skinned"},   {"morph", "morph"},                 {"rigid", "rigid"},
      {"built_in", "built-in scenes"}};
  return kinds;
}

bool kindsRecorded(const json& r) {
  for (const json& s : at(r, {"scenes"}).is_array() ? r["scenes"] : json::array())
    if (at(s, {"contentKinds", "cells"}).is_array()) return true;
  return false;
}

bool hasBuiltInBesideFiles(const json& r) {
  bool file = false, builtIn = false;
  for (const json& s : at(r, {"scenes"}).is_array() ? r["scenes"] : json::array())
    if (at(s, {"contentKinds", "cells"}).is_array() && isEuclidean(s)) (isFile(s) ? file : builtIn) = true;
  return file && builtIn;
}

void addKindFigures(json& r) {
  if (!r.contains("figures") || !r["figures"].is_object()) r["figures"] = json::object();
  json& out = r["figures"];
  if (!kindsRecorded(r)) {
    notRecorded(out, contentKindDefs()[0]);
    return;
  }
  const std::vector<std::string> pipes = at(r, {"settings", "pipelines"}).is_array()
                                             ? r["settings"]["pipelines"].get<std::vector<std::string>>()
                                             : std::vector<std::string>{};
  double allVertices = 0, allPrimitives = 0;
  for (const json* s : scopeScenes(r, "all"))
    allVertices += kindVertices(*s, "all"), allPrimitives += kindVertices(*s, "all", "primitives");
  for (const ContentKindDef& k : contentKindDefs()) {
    if (k.id == "built_in" && !hasBuiltInBesideFiles(r)) continue;
    countFigures(out, r, k, allVertices, allPrimitives);
    bytesFigures(out, r, k, pipes);
    opsFigures(out, r, k, pipes);
    isaFigures(out, r, k, pipes);
    timeFigure(out, r, k);
    imageFigures(out, r, k, pipes);
  }
}

}  // namespace mb::document
