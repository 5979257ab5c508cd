#include "harness/document/report_answer_figures.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include "harness/document/report_compact.h"
#include "harness/document/report_document.h"
#include "harness/document/report_figures.h"
#include "harness/document/report_format.h"
#include "harness/document/report_isa.h"
#include "harness/document/report_kind_figures.h"
#include "harness/document/scope_ladder.h"
#include "harness/figures/figure.h"
#include "pipelines/registry.h"

namespace mb::document {
namespace {

using json = nlohmann::json;
using figures::Figure;
using figures::numberOrNaN;

// The motor-blend reference as the figures' scopes name it (harness/render/skin_judgement.h's
// definition; document code reads JSON only).
const char* kMotorBlendReferenceText =
    "the motor-blend reference: the same pose skinned on the CPU by the motor blend, drawn by matrix";

const char* kFetchDevice = "meshoptimizer's analyzers on the mesh and the pipeline's vertex layout (not timed)";

Figure overScenes(std::string name, std::string unit, std::string scope, std::string device, std::string definition,
                  const std::vector<double>& perScene) {
  Figure f;
  f.kind = "modelled";
  f.name = std::move(name), f.unit = std::move(unit), f.scope = std::move(scope), f.device = std::move(device);
  f.statistic = "median over scenes";
  f.definition = std::move(definition);
  f = figures::withQuartiles(f, figures::quartilesOf(perScene));
  if (f.n == 0) f.value = std::nan(""), f.why = "no scene measured it";
  return f;
}

void fetchFigures(json& out, const json& r, const std::vector<std::string>& pipes, const std::string& base) {
  for (const std::string& p : pipes) {
    std::vector<double> perVertex, perFrame;
    for (const json& s : r["scenes"]) {
      if (!isEuclidean(s)) continue;
      const json& f = at(s, {"pipelines", p.c_str(), "vertexFetch"});
      const double b = numberOrNaN(at(s, {"pipelines", base.c_str(), "vertexFetch", "bytesFetchedPerFrame"}));
      if (!f.is_object()) continue;
      if (std::isfinite(numberOrNaN(f["bytesFetchedPerVertex"]))) perVertex.push_back(numberOrNaN(f["bytesFetchedPerVertex"]));
      if (b > 0 && std::isfinite(numberOrNaN(f["bytesFetchedPerFrame"]))) perFrame.push_back(numberOrNaN(f["bytesFetchedPerFrame"]) / b);
    }
    const std::string scope = "shading-attribute stream of every drawn primitive, one frame, Euclidean scenes";
    figures::put(out, overScenes("vertex_fetch.bytes_per_vertex." + p, "bytes", scope, kFetchDevice,
                                 "bytes fetched per vertex referenced in meshoptimizer's fetch model (64-byte lines), with " + p + "'s stride",
                                 perVertex));
    figures::put(out, overScenes("vertex_fetch.bytes_per_frame_over_baseline." + p, "x", scope, kFetchDevice,
                                 "bytes fetched per frame " + p + " / " + base + " (< 1: " + p + " cheaper)", perFrame));
  }
}

// Per family, variant and pipeline, the compiler's statistics of the vertex shader: ISA
// instructions, ACO's inverse-throughput estimate, VGPRs and waves per SIMD.
void isaFigures(json& out, const json& r, const std::vector<std::string>& pipes) {
  const json& isa = at(r, {"isa"});
  const std::tuple<const char*, const char*, const char*, const char*> measures[] = {
      {"instructions", "instructions", "instructions", "ISA instructions of the compiled vertex shader"},
      {"inverse_throughput", "inverseThroughput", "cycles", "ACO's static inverse-throughput estimate of the compiled vertex shader"},
      {"vgprs", "vgprs", "VGPRs", "vector registers the compiled vertex shader allocates"},
      {"waves", "wavesPerSimd", "waves", "waves per SIMD the register use allows (occupancy)"}};
  for (const json& fam : at(isa, {"families"}).is_array() ? isa["families"] : json::array())
    for (const char* variant : {"rigid", "skinned"})
      for (const std::string& p : pipes) {
        const std::string id = fam.value("id", "");
        const json* row = isaRow(isa, p, variant, id);
        for (const auto& [name, key, unit, definition] : measures) {
          Figure f;
          f.kind = "compiled";
          f.name = std::string("isa.") + name + "." + variant + "." + id + "." + p;
          f.unit = unit;
          f.statistic = "compiled: the compiler's statistic";
          f.scope = std::string(variant) + " vertex shader (whole shader, main() included), one vertex (one lane of a wave)";
          f.device = "RADV " + id + " (" + fam.value("generation", "") + "), compiler statistics on the null device, not timed";
          f.definition = definition;
          f.value = row ? numberOrNaN((*row)[key]) : std::nan("");
          f.n = std::isfinite(f.value) ? 1 : 0;
          if (!row) f.why = std::string("no ") + variant + " vertex shader of " + p + " for " + id;
          figures::put(out, f);
        }
      }
}

Figure fragmentFigure(const std::string& name, const std::string& kind, const std::string& unit, double value,
                      const std::string& scope, const std::string& device, const std::string& definition) {
  Figure f;
  f.kind = kind;
  f.name = name, f.unit = unit, f.scope = scope, f.device = device, f.definition = definition;
  f.statistic = kind == "counted" ? "count (mul + add + div + sqrt + other)" : "compiled: the compiler's statistic";
  f.value = value;
  f.n = std::isfinite(value) ? 1 : 0;
  if (!std::isfinite(value)) f.why = "not in this report.json";
  return f;
}

// The fragment stage of each pipeline's rigid program: its AMD ISA per family
// (isa.fragment_instructions / isa.fragment_vgprs.rigid.<family>.<p>), the varyings it reads
// (varyings.slots / varyings.components.<p>: the fragment shader's inputs in its SPIR-V) and the
// counted shading normal per fragment (ops_per_fragment.shading_normal.<normal_mapped|no_normal_map>.<p>).
void fragmentFigures(json& out, const json& r, const std::vector<std::string>& pipes) {
  const json& isa = at(r, {"isa"});
  const json& families = at(isa, {"families"}).is_array() ? isa["families"] : json::array();
  const std::string rigid = "the rigid program's fragment shader (forward.fs as the pipeline links it)";
  for (const std::string& p : pipes) {
    for (const json& fam : families) {
      const std::string id = fam.value("id", "");
      const json* row = isaRow(isa, p, "rigid", id, "fragment");
      const std::string device = "RADV " + id + " (" + fam.value("generation", "") + "), compiler statistics on the null device, not timed";
      figures::put(out, fragmentFigure("isa.fragment_instructions.rigid." + id + "." + p, "compiled", "instructions",
                                       row ? numberOrNaN((*row)["instructions"]) : std::nan(""), rigid, device,
                                       "ISA instructions of the compiled fragment shader"));
      figures::put(out, fragmentFigure("isa.fragment_vgprs.rigid." + id + "." + p, "compiled", "VGPRs",
                                       row ? numberOrNaN((*row)["vgprs"]) : std::nan(""), rigid, device,
                                       "vector registers the compiled fragment shader allocates"));
    }
    const json* first = families.empty() ? nullptr : isaRow(isa, p, "rigid", families.front().value("id", ""));
    for (const auto& [key, field] : {std::pair<const char*, const char*>{"slots", "varyingSlots"}, {"components", "varyingComponents"}})
      figures::put(out, fragmentFigure(std::string("varyings.") + key + "." + p, "compiled", key,
                                       first ? numberOrNaN(first->value(field, json())) : std::nan(""),
                                       "the rigid program's varyings", "SPIR-V of the fragment shader (its inputs)",
                                       std::string("vec4 ") + key + " the rigid program passes to the fragment shader"));
    for (const bool mapped : {true, false}) {
      const std::string kernel = shadingNormalKernel(p, mapped);
      double total = std::nan("");
      for (const json& k : at(r, {"opsPerVertex", "kernels"}).is_array() ? r["opsPerVertex"]["kernels"] : json::array())
        if (k.value("function", "") == kernel) total = opsTotal(k.value("counted", json()));
      figures::put(out, fragmentFigure(std::string("ops_per_fragment.shading_normal.") + (mapped ? "normal_mapped." : "no_normal_map.") + p,
                                       "counted", "ops", total, "one fragment's shading normal, " + kernel +
                                           (mapped ? " (normal-mapped)" : " (no normal map)"),
                                       "counted (op-counting scalar through the GLSL shim)",
                                       "arithmetic operations per fragment; subtraction counts as addition, negation is free"));
    }
  }
}

// The vertex format's own image cost: the worst PSNR over the frames of
// scenes where `p` uploads its mesh vertices (summary.vertexFormatImages: a scene of patches,
// the teapot, draws none of them), so a compact format is not credited with another path's frame.
void ownFormatFigure(json& out, const json& r, const std::string& p, const std::string& base,
                     const std::string& device) {
  const json& im = at(r, {"summary", "vertexFormatImages", p.c_str()});
  if (!im.is_object()) return;
  Figure f;
  f.kind = "measured";
  f.name = "image.worst_psnr_own_format." + p, f.unit = "dB", f.device = device;
  f.scope = "frames where " + p + " draws its own vertex format (its uploaded mesh vertices), Euclidean scenes, each "
            "against its own reference: " + base + ", but a skinned frame of another skinning method than " + base +
            "'s against its own method's reference (" + kMotorBlendReferenceText + ")";
  f.statistic = "minimum over the frames that differ";
  f.definition = "PSNR of " + p + " against its reference; identical frames (infinite PSNR) are counted apart";
  f.value = numberOrNaN(at(im, {"psnr", "min"}));
  f.n = at(im, {"psnr", "n"}).is_number() ? im["psnr"]["n"].get<int>() : 0;
  if (!std::isfinite(f.value))
    f.why = im.value("comparedFrames", 0) > 0 ? "every compared frame identical" : "no frame compared";
  figures::put(out, f);
}

// Every frame of the Euclidean scenes, each judged against its own reference (judgedFrame: a
// skinned frame of another skinning method than the baseline's against its own method's).
struct JudgedImages {
  std::vector<double> psnr, flip;
  int compared = 0, identical = 0, ownSkinReference = 0, notJudged = 0;
  std::vector<std::string> whyNot;  // each reason once
};

JudgedImages judgedImages(const json& r, const std::string& p, const std::string& base) {
  JudgedImages out;
  for (const json& s : r["scenes"]) {
    if (!isEuclidean(s)) continue;
    for (const json& fr : s.value("frames", json::array())) {
      const JudgedFrame j = judgedFrame(s, fr, p, base);
      if (!j.compared) continue;
      if (!j.metrics) {
        ++out.notJudged;
        if (std::find(out.whyNot.begin(), out.whyNot.end(), j.why) == out.whyNot.end()) out.whyNot.push_back(j.why);
        continue;
      }
      const json& m = *j.metrics;
      ++out.compared;
      out.ownSkinReference += j.skinnedOwnMethod && j.reference != base;
      if (m.value("identical", false)) ++out.identical;
      else if (m["psnr"].is_number()) out.psnr.push_back(m["psnr"].get<double>());
      if (at(m, {"flip", "mean"}).is_number()) out.flip.push_back(m["flip"]["mean"].get<double>());
    }
  }
  return out;
}

std::string joinedReasons(const std::vector<std::string>& why) {
  std::string text;
  for (const std::string& w : why) text += (text.empty() ? "" : "; ") + w;
  return text;
}

void imageFigures(json& out, const json& r, const std::vector<std::string>& pipes) {
  const std::string base = pipes.empty() ? "" : pipes[0];
  for (size_t i = 1; i < pipes.size(); ++i) {
    const std::string& p = pipes[i];
    const JudgedImages im = judgedImages(r, p, base);
    const std::string scope = "every frame of the Euclidean scenes, each against its own reference: " + base +
                              ", but a skinned frame of a pipeline that blends joints by another method than " + base +
                              " against its own method's reference (" + kMotorBlendReferenceText + ")";
    Figure w;
    w.kind = "measured";
    w.name = "image.worst_psnr." + p, w.unit = "dB", w.scope = scope, w.device = "the rendered images (8-bit RGBA)";
    w.statistic = "minimum over the frames that differ";
    w.definition = "PSNR of " + p + " against its reference; identical frames (infinite PSNR) are counted apart";
    w.n = int(im.psnr.size());
    w.value = im.psnr.empty() ? std::nan("") : *std::min_element(im.psnr.begin(), im.psnr.end());
    if (im.psnr.empty()) w.why = im.compared ? "every compared frame identical" : "no frame compared";
    figures::put(out, w);
    Figure id;
    id.name = "image.identical_frames." + p, id.unit = "frames", id.scope = scope, id.device = w.device;
    id.statistic = "count", id.value = im.identical, id.n = im.compared;
    id.definition = "frames whose every pixel equals their reference's, of n judged";
    figures::put(out, id);
    Figure own;
    own.name = "image.skinned_frames_own_reference." + p, own.unit = "frames", own.scope = scope, own.device = w.device;
    own.statistic = "count", own.value = im.ownSkinReference, own.n = im.compared;
    own.definition = "skinned frames of the n judged that were judged against " + p +
                     "'s own skinning method's reference, not " + base;
    figures::put(out, own);
    Figure no;
    no.name = "image.frames_not_judged." + p, no.unit = "frames", no.scope = scope, no.device = w.device;
    no.statistic = "count", no.value = im.notJudged, no.n = im.compared + im.notJudged;
    no.definition = "frames drawn by both pipelines that could not be judged (their reference could not be made), of n" +
                    (im.notJudged ? "; why: " + joinedReasons(im.whyNot) : std::string());
    figures::put(out, no);
    ownFormatFigure(out, r, p, base, w.device);
    if (im.flip.empty()) continue;
    Figure fl;
    fl.name = "image.flip_mean_worst." + p, fl.unit = "", fl.scope = scope, fl.device = w.device;
    fl.statistic = "maximum over frames of each frame's mean LDR-FLIP";
    fl.definition = "perceptual difference of " + p + " against its reference (0: none, 1: largest)";
    fl.value = *std::max_element(im.flip.begin(), im.flip.end()), fl.n = int(im.flip.size());
    figures::put(out, fl);
  }
}

}  // namespace

namespace {

bool sameVariants(const std::vector<ShaderVariant>& a, const std::vector<ShaderVariant>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].stage != b[i].stage || a[i].defines != b[i].defines || a[i].draws != b[i].draws ||
        a[i].kernels != b[i].kernels || a[i].fragment != b[i].fragment)
      return false;
  return true;
}

// The family most registered pipelines that run `stage` belong to: the family of that vertex shader.
PipelineFamily stageFamily(const std::string& stage) {
  int motor = 0, matrix = 0;
  for (const PipelineEntry& q : registeredPipelines())
    for (const ShaderVariant& v : q.variants)
      if (v.stage == stage) {
        ++(q.family == PipelineFamily::Motor ? motor : matrix);
        break;
      }
  return motor > matrix ? PipelineFamily::Motor : PipelineFamily::Matrix;
}

}  // namespace

std::string gpuSideOf(const std::string& p) {
  const PipelineEntry* e = findPipeline(p);
  if (!e || e->vertexBytes == 0 || e->variants.empty()) return "";
  // Its shaders are its own family's: it draws with its own GPU side.
  const PipelineFamily gpu = stageFamily(e->variants.front().stage);
  if (gpu == e->family) return "";
  for (const PipelineEntry& q : registeredPipelines())
    if (q.name != p && q.family == gpu && q.space == e->space && q.vertexBytes == e->vertexBytes &&
        q.frame.decodeKernel == e->frame.decodeKernel && q.frame.fetched == e->frame.fetched &&
        q.frame.perFragment == e->frame.perFragment && sameVariants(q.variants, e->variants))
      return q.name;
  return "";
}

std::string pipelineFamily(const std::string& p) {
  const PipelineEntry* e = findPipeline(p);
  if (!e) return p.find("motor") != std::string::npos ? "motor" : "matrix";  // a name this build lacks
  return e->family == PipelineFamily::Motor ? "motor" : "matrix";
}

void addAnswerFigures(json& r) {
  const std::vector<std::string> pipes = at(r, {"settings", "pipelines"}).is_array()
                                             ? r["settings"]["pipelines"].get<std::vector<std::string>>()
                                             : std::vector<std::string>{};
  if (!r.contains("figures") || !r["figures"].is_object()) r["figures"] = json::object();
  if (!r.contains("scenes") || !r["scenes"].is_array()) r["scenes"] = json::array();
  json& out = r["figures"];
  const std::string base = pipes.empty() ? "" : pipes[0];
  fetchFigures(out, r, pipes, base);
  isaFigures(out, r, pipes);
  fragmentFigures(out, r, pipes);
  imageFigures(out, r, pipes);
  curvedFigures(out, r["scenes"].get<std::vector<json>>(), at(r, {"curved", "drift"}), frameTimeDevice(at(r, {"machine"})));
  addKindFigures(r);
  json families = json::object(), gpuSides = json::object();
  for (const std::string& p : pipes) {
    families[p] = pipelineFamily(p);
    if (const std::string q = gpuSideOf(p); !q.empty()) gpuSides[p] = q;
  }
  r["pipelineFamilies"] = families;
  r["pipelineGpuSides"] = gpuSides;
  r["scopeLadder"] = ladderJson(scopeLadder(r));
}

}  // namespace mb::document
