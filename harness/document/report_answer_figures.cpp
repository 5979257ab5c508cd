#include "harness/document/report_answer_figures.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include "harness/document/report_document.h"
#include "harness/document/report_figures.h"
#include "harness/document/report_format.h"
#include "harness/document/report_isa.h"
#include "harness/document/report_kind_figures.h"
#include "harness/document/scope_ladder.h"
#include "harness/figures/figure.h"
#include "pipelines/registry.h"

namespace mb::report {
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
                                 "bytes a GPU fetches (64-byte lines) per vertex referenced, with " + p + "'s stride",
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
  imageFigures(out, r, pipes);
  curvedFigures(out, r["scenes"].get<std::vector<json>>(), at(r, {"curved", "drift"}), frameTimeDevice(at(r, {"machine"})));
  addKindFigures(r);
  json families = json::object();
  for (const std::string& p : pipes) families[p] = pipelineFamily(p);
  r["pipelineFamilies"] = families;
  r["scopeLadder"] = ladderJson(scopeLadder(r));
}

}  // namespace mb::report
