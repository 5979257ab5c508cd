#include "harness/document/report_layout_sections.h"

#include <algorithm>
#include <map>

#include "harness/document/report_document.h"
#include "harness/document/report_format.h"
#include "harness/document/report_layout_common.h"
#include "harness/document/report_marks.h"

namespace mb::document {

using namespace layout;

namespace {

std::vector<std::string> statsLines(const json& st) {
  if (!st.is_object() || !st.value("loaded", false)) return {};
  // inspect's JSON groups its counters: geometry, materials, skinning, animation, scale.
  auto v = [&](const char* group, const char* k) { return str(at(st, {group, k})); };
  std::vector<std::string> lines = {
      "geometry: " + v("geometry", "meshes") + " meshes, " + v("geometry", "primitives") + " primitives, " +
          v("geometry", "vertices") + " vertices, " + v("geometry", "triangles") + " triangles; " +
          v("geometry", "nodes") + " nodes, " + v("geometry", "meshNodes") + " mesh nodes drawing " +
          v("geometry", "drawnVertices") + " vertices",
      "materials: " + v("materials", "materials") + " materials, " + v("materials", "textures") + " textures; " +
          v("materials", "normalMappedPrimitives") + " normal-mapped primitives (" +
          v("materials", "authoredTangentPrimitives") + " with authored TANGENT)",
      "skinning: " + v("skinning", "skins") + " skins, " + v("skinning", "joints") + " joints; animation: " +
          v("animation", "animations") + " animations, " + v("animation", "channels") + " channels (T " +
          v("animation", "translation") + ", R " + v("animation", "rotation") + ", S " + v("animation", "scale") + ")"};
  if (st.contains("scale") && st["scale"].is_object()) {
    const json& sc = st["scale"];
    lines.push_back("scale: " + str(sc.value("uniformNodes", json())) + " uniform, " +
                    str(sc.value("nonUniformNodes", json())) + " non-uniform, " +
                    str(sc.value("negativeNodes", json())) + " negative, " + str(sc.value("shearNodes", json())) +
                    " sheared nodes; animated scale on " + str(sc.value("animatedScaleNodes", json())) + " nodes");
  }
  std::string fb;
  for (const auto& [k, val] : members(st, "fallbacks").items())
    if (val.is_number() && val.get<double>() != 0) fb += (fb.empty() ? "" : ", ") + k + " " + fmt(val);
  lines.push_back("loader fixes: " + (fb.empty() ? std::string("none") : fb));
  std::string un;
  for (const json& u : st.value("unsupported", json::array())) un += (un.empty() ? "" : "; ") + str(u);
  if (!un.empty()) lines.push_back("unsupported: " + un);
  return lines;
}

// The compared pipelines (after the baseline, pipes[0]) that blend skinned vertices differently
// from the baseline.
std::vector<std::string> methodDiffersOf(const json& s, const std::vector<std::string>& pipes) {
  std::vector<std::string> methodDiffers;
  for (size_t i = 1; i < pipes.size(); ++i)
    if (skinningMethodsDiffer(s, pipes[i], pipes[0])) methodDiffers.push_back(pipes[i]);
  return methodDiffers;
}

// The paragraph on a skinned scene whose pipelines blend by different methods: which pipeline
// blends how, and against which reference each frame is judged (none when all blend alike).
void skinningMethodParagraph(Document& d, const json& s, const std::vector<std::string>& pipes,
                             const std::vector<std::string>& methodDiffers) {
  if (methodDiffers.empty()) return;
  std::string lbs, motors;
  for (const std::string& p : pipes) {
    const std::string blend = str(at(s, {"pipelines"}).is_object() && s["pipelines"].contains(p) ? s["pipelines"][p]["skinBlend"] : json(), "");
    if (blend == "linear blend skinning") lbs += (lbs.empty() ? "" : ", ") + p;
    if (blend == "motor blending") motors += (motors.empty() ? "" : ", ") + p;
  }
  d.paragraph("Skinned scene: " + lbs + " blend joints with linear blend skinning (LBS, a matrix palette); " + motors +
              " blend joint motors (the dual-quaternion method). Where joints turn far apart the two methods pose "
              "the mesh differently by design (LBS loses volume: on a half turn, candy_wrapper, the ring between "
              "the joints collapses towards the axis), so each frame of " + motors + " is judged against its own "
              "method's reference, the motor-blend reference (the same pose skinned on the CPU by the motor blend, "
              "drawn by matrix), in the rows \"vs motor-blend reference\" below; the difference figures of " + motors +
              " against " + pipes[0] + " are the methods' expected difference, measured, not an error of either" +
              (std::any_of(methodDiffers.begin(), methodDiffers.end(), [&](const std::string& p) { return drawnFailures(s, p) > 0; })
                   ? " -- except in the frames marked FAILED, where one image is empty or the drawn pixels differ from "
                     "the pipeline's own method's reference by more than 1 %: a wrong pose, scale or missing mesh."
                   : "."));
}

// The file a frame names under `key` for pipeline `p` ("" when none).
std::string frameFile(const json& f, const char* key, const std::string& p) {
  const json& v = at(f, {key, p.c_str()});
  return v.is_string() ? v.get<std::string>() : std::string();
}

// One frame's small multiples: each pipeline's image (or its error) with, for the compared
// ones, its diff heat map and FLIP map under it.
void frameGallery(Document& d, const json& f, const std::vector<std::string>& pipes) {
  std::vector<std::vector<Cell>> cards;
  for (size_t i = 0; i < pipes.size(); ++i) {
    const std::string& p = pipes[i];
    std::vector<Cell> card = {{p}};
    if (const std::string img = frameFile(f, "images", p); !img.empty()) card.push_back({"", img, img});
    else card.push_back({"error: " + str(at(f, {"errors", p.c_str()}))});
    if (i == 0) card.push_back({"(the baseline)"});
    if (const std::string diff = frameFile(f, "diffs", p); i > 0 && !diff.empty()) card.push_back({"diff", diff, diff});
    if (const std::string flip = frameFile(f, "flipMaps", p); i > 0 && !flip.empty()) card.push_back({"FLIP", flip, flip});
    cards.push_back(std::move(card));
  }
  d.gallery(std::move(cards));
}

// One frame's rows of the metrics table, appended to `metricRows`: each compared pipeline against
// the baseline, and a skinned frame judged by its own skinning method on a second row.
void frameMetricRows(const json& s, const json& f, const std::string& when, const std::vector<std::string>& pipes,
                     const std::vector<std::string>& methodDiffers, std::vector<std::vector<Cell>>& metricRows) {
  for (size_t i = 1; i < pipes.size(); ++i) {
    const json& m = at(f, {"metrics", pipes[i].c_str()});
    if (!m.is_object()) continue;
    // The methods' label only where the frame's drawn pixels allow it; a failed check says why.
    const bool method = methodDifferenceAllowed(
        f, pipes[i], std::find(methodDiffers.begin(), methodDiffers.end(), pipes[i]) != methodDiffers.end());
    const std::string mark = drawnMark(f, pipes[i]);
    // A skinned frame judged by its own skinning method: its check on the row of the figures
    // that judge it (or why they could not be made), after the row against the baseline.
    const JudgedFrame j = judgedFrame(s, f, pipes[i], pipes[0]);
    const bool own = j.skinnedOwnMethod && j.reference != pipes[0];
    metricRows.push_back({{when}, {pipes[i] + (method ? " (skinning method difference)" : "")}, {psnrText(m)},
                          {fmt(m["rmse"], 3)}, {fmt(json(255.0 * m.value("maxError", 0.0)), 3)},
                          {percent(m["fractionOver1"], 3)}, {percent(m["fractionOver4"], 3)},
                          {fmt(at(m, {"flip", "mean"}), 3)}, {fmt(at(m, {"flip", "max"}), 3)},
                          {own ? std::string("judged on the next row") : mark}});
    if (!own) continue;
    const std::string label = pipes[i] + " vs " + j.reference + " (its own skinning method's)";
    if (!j.metrics) {
      metricRows.push_back({{when}, {label}, {j.why}, {"-"}, {"-"}, {"-"}, {"-"}, {"-"}, {"-"}, {mark}});
      continue;
    }
    const json& o = *j.metrics;
    metricRows.push_back({{when}, {label}, {psnrText(o)}, {fmt(o["rmse"], 3)}, {fmt(json(255.0 * o.value("maxError", 0.0)), 3)},
                          {percent(o["fractionOver1"], 3)}, {percent(o["fractionOver4"], 3)},
                          {fmt(at(o, {"flip", "mean"}), 3)}, {fmt(at(o, {"flip", "max"}), 3)}, {mark}});
  }
}

// Small multiples per shown time (of each animation shown): each pipeline's image with its
// diff heat map and LDR-FLIP map (magma: black 0 .. yellow 1) under it, wrapping to the page
// width; the metrics in their own compact table after the images.
void frameSections(Document& d, const json& s, const std::vector<std::string>& pipes,
                   const std::vector<std::string>& methodDiffers) {
  std::map<int, std::string> animName;
  for (const json& a : s.value("animations", json::array())) animName[a.value("index", -1)] = a.value("name", "");
  std::vector<std::vector<Cell>> metricRows;
  for (const json& f : s.value("frames", json::array())) {
    const json& fa = at(f, {"animation"});
    std::string when = "t = " + fixed(f["time"], 3) + " s";
    if (animName.size() > 1 && fa.is_number()) when = animName[fa.get<int>()] + ", " + when;
    d.paragraph(when + ": each pipeline, with its diff against " + pipes[0] + " and its FLIP map under it.");
    frameGallery(d, f, pipes);
    frameMetricRows(s, f, when, pipes, methodDiffers, metricRows);
  }
  if (!metricRows.empty())
    d.table({"time", "pipeline vs " + pipes[0] + " (or its own skinning method's reference)", "PSNR", "RMSE", "max /255", "> 1/255", "> 4/255", "FLIP mean",
             "FLIP max", "drawn-pixel check"},
            metricRows);
}

// One loop of each animation shown, baseline | pipeline | diff, per compared pipeline (or why
// it was not made).
void animationLoops(Document& d, const json& s, const std::vector<std::string>& pipes,
                    const std::vector<std::string>& methodDiffers) {
  json loops = json::array();
  for (const json& a : s.value("animations", json::array()))
    if (a.contains("animated") && a["animated"].is_object()) loops.push_back(a["animated"]);
  if (loops.empty() && s.contains("animated") && s["animated"].is_object()) loops.push_back(s["animated"]);
  for (const json& loop : loops)
    for (const auto& [p, a] : loop.items()) {
      const bool method = std::find(methodDiffers.begin(), methodDiffers.end(), p) != methodDiffers.end();
      const std::string which = a.contains("name") ? "animation " + str(a.value("animation", json())) + " '" + str(a["name"]) + "'" : "animation 0";
      if (a.contains("file"))
        d.figure(a["file"].get<std::string>(), "Animated (" + which + "): " + pipes[0] + " | " + p + " | diff",
                 "One loop of " + which + " (" + fixed(a["duration"], 2) + " s) in " + str(a["frames"]) + " frames at " +
                     str(a["fps"]) + " fps: " + pipes[0] + " left, " + p + " middle, diff heat map right; at most " +
                     percent(a["maxPixelsOver2"], 2) + " of the pixels differ by more than 2/255 in any frame" +
                     (method ? " (the skinning methods' expected difference)." : "."));
      else
        d.paragraph("Animated comparison " + pipes[0] + " vs " + p + " (" + which + ") not made: " + str(a.value("error", json())));
    }
}

// Per pipeline: memory, conversion, fallbacks, ops and timing, one row each (no table when the
// scene has no pipeline results).
void pipelineTable(Document& d, const json& r, const json& s, const std::vector<std::string>& pipes) {
  std::vector<std::vector<Cell>> prow;
  for (const std::string& p : pipes) {
    if (!at(s, {"pipelines"}).is_object() || !s["pipelines"].contains(p)) continue;
    const json& pj = s["pipelines"][p];
    const json& mem = pj.value("memory", json::object());
    const json& t = at(s, {"timing", "pipelines"}).is_object() && s["timing"]["pipelines"].contains(p) ? s["timing"]["pipelines"][p] : json();
    const json& o = at(s, {"opsPerVertex"}).is_object() && s["opsPerVertex"].contains(p) ? s["opsPerVertex"][p] : json();
    prow.push_back({{p}, {fmt(mem.value("bytesPerVertex", json()))}, {fmt(mem.value("floatsPerVertex", json()))},
                    {mem.value("floatsPerTransform", json()).is_null() && mem.contains("floatsPerTransform")
                         ? std::string("none (skinned or instanced draws only)")
                         : fmt(mem.value("floatsPerTransform", json()))},
                    {fmt(mem.value("floatsPerJoint", json()))},
                    {str(mem.value("vertexBytes", json())) + " / " + str(mem.value("skinVertexBytes", json())) + " / " +
                     str(mem.value("indexBytes", json())) + " / " + str(mem.value("textureBytes", json()))},
                    {str(mem.value("uniformBytesPerFrame", json())) + " / " + str(mem.value("skinBytesPerFrame", json()))},
                    {str(pj.value("draws", json()))}, {fixed(at(pj, {"conversionMs", "median"}), 3)},
                    {fallbacksText(pj)}, {o.is_object() ? opsText(o["counted"], 1) : "-"},
                    {t.is_object() ? fixed(t.value("medianMs", json()), 2) + " (" + fixed(t.value("minMs", json()), 2) + ".." +
                                         fixed(t.value("maxMs", json()), 2) + ")" : "-"},
                    {t.is_object() ? fixed(t.value("verticesPerUs", json()), 1) : "-"},
                    {t.is_object() ? fmt(t.value("updateMedianMs", json()), 3) : "-"},
                    {pj["error"].is_string() ? pj["error"].get<std::string>() : ""}});
  }
  if (prow.empty()) return;
  d.paragraph(frameTimeOn(at(s, {"timing", "gl"}).is_object() ? at(s, {"timing", "gl"}) : at(r, {"machine", "gl"})) +
              ": the frame ms column.");
  d.table({"pipeline", "B/vertex", "floats/vertex", "floats/transform", "floats/joint",
           "bytes: vertex / skin / index / texture", "bytes per frame: uniforms / joint palette", "draws",
           "conversion ms (median)", "fallbacks", "ops/vertex (counted, mean)", "frame ms median (min..max)",
           "vertices/us (drawn vertices x instances / median frame)", "CPU update ms", "error"},
          prow);
}

// Instanced draws: what each pipeline streams per instance (measured: bytes handed to GL); no
// table when no pipeline drew instances.
void instanceTable(Document& d, const json& s, const std::vector<std::string>& pipes) {
  std::vector<std::vector<Cell>> irow;
  for (const std::string& p : pipes) {
    const json& mem = at(s, {"pipelines"}).is_object() && s["pipelines"].contains(p) ? s["pipelines"][p].value("memory", json::object()) : json();
    if (!mem.is_object() || !mem.contains("instances") || !mem["instances"].is_number() || mem["instances"].get<double>() == 0) continue;
    const json& fb = s["pipelines"][p].value("fallbacks", json::object());
    irow.push_back({{p}, {str(mem["instances"])}, {fmt(mem.value("bytesPerInstance", json()))}, {str(mem.value("instanceBytes", json()))},
                    {str(fb.value("scaleFallbackInstances", json(0)))}});
  }
  if (irow.empty()) return;
  d.paragraph("Instance memory (EXT_mesh_gpu_instancing or --instances): the per-instance transforms every "
              "pipeline streams once per frame, node world x instance composed on the CPU in the pipeline's "
              "own form (matrix: model + normal mat4; affine family: mat4x3 + mat3 + mirror; motor family: "
              "motor + scale, a vec3 scale on the scale fallback).");
  d.table({"pipeline", "instances", "bytes per instance", "instance bytes per frame", "scale-fallback instances"}, irow);
}

// The CPU update phase by phase (harness/timing: a block of updates with the phase clock on), in
// microseconds; no table when no pipeline timed its phases.
void updatePhaseTable(Document& d, const json& r, const json& s, const std::vector<std::string>& pipes) {
  std::vector<std::vector<Cell>> urow;
  for (const std::string& p : pipes) {
    const json& t = at(s, {"timing", "pipelines"}).is_object() && s["timing"]["pipelines"].contains(p) ? s["timing"]["pipelines"][p] : json();
    const json& ph = t.is_object() ? t.value("updatePhasesMedianMs", json()) : json();
    if (!ph.is_object()) continue;
    std::vector<Cell> row{{p}};
    for (const char* k : {"sampling", "blending", "conversion", "hierarchy", "palette"})
      row.push_back({ph.contains(k) && ph[k].is_number() ? fixed(json(1e3 * ph[k].get<double>()), 2) : "-"});
    row.push_back({t.contains("updateMedianMs") && t["updateMedianMs"].is_number() ? fixed(json(1e3 * t["updateMedianMs"].get<double>()), 2) : "-"});
    urow.push_back(row);
  }
  if (urow.empty()) return;
  const json& m = r["machine"];
  d.paragraph("Measured on " + cpuMachineText(m["cpu"], m["logicalCores"], m["simdTarget"]) +
              " (CPU times hold for this CPU).");
  d.paragraph("CPU update by phase: microseconds per update call, medians over the timed frames, from a block "
              "of updates timed with the pipelines' phase clock on (apart from the whole-update timing, whose "
              "median is the last column; the phases include their clock reads). The matrix forms' hierarchy "
              "includes the normal matrices of the drawn nodes, computed per node as the Sample Viewer's "
              "hierarchy pass does; the motor forms need none.");
  d.table({"pipeline", "sampling us", "blending us", "conversion us", "hierarchy us", "palette us",
           "whole update us"},
          urow);
}

// The scene's frame timing in one paragraph: its error, or its summary with the motor / matrix
// ratios (frame, paired, process CPU, CPU update) whole and vertex-bound.
void timingParagraph(Document& d, const json& r, const json& s) {
  const json& timing = s.value("timing", json());
  if (!timing.is_object()) return;
  if (timing["error"].is_string()) d.paragraph("Frame timing: " + timing["error"].get<std::string>());
  else if (timing.contains("summary")) {
    auto ratios = [](const json& c) {
      return "ratio of the medians " + ratio(at(c, {"ratio_motor_matrix"})) + ", median of paired per-frame ratios " +
             ratio(at(c, {"paired_ratio_motor_matrix"})) + ", process CPU time " +
             ratio(at(c, {"paired_cpu_ratio_motor_matrix"})) + ", CPU update " +
             ratio(at(c, {"update", "ratio_motor_matrix"}));
    };
    const json& vb = timing.value("vertexBound", json());
    d.paragraph(frameTimeOn(timing.value("gl", at(r, {"machine", "gl"}))) + ": " + str(timing["summary"]) +
                " Motor / matrix: " + ratios(timing) +
                "; vertex-bound: " + (vb.contains("skipped") ? str(vb["skipped"]) : ratios(vb)) + ".");
  }
}

}  // namespace

void sceneSection(Document& d, const json& r, const json& s) {
  const std::vector<std::string> pipes = pipelinesOf(r, s);
  d.heading(3, str(s["id"]) + (s["spec"] != s["id"] ? " (" + str(s["spec"]) + ")" : ""), "scene-" + str(s["id"]));
  if (s["error"].is_string()) d.paragraph(std::string(s.value("status", "") == "failed" ? "FAILED" : "Error") + ": " + s["error"].get<std::string>());
  if (s.contains("workerExit")) d.paragraph("Note: the worker process ended with " + str(s["workerExit"]) + " after writing its result.");
  if (!isEuclidean(s)) d.paragraph("Curved space: " + str(s["space"]) + ", drawn by its own pipelines (see Curved space).");
  d.bullets(statsLines(s.value("stats", json())));
  const std::vector<std::string> methodDiffers = methodDiffersOf(s, pipes);
  skinningMethodParagraph(d, s, pipes, methodDiffers);
  frameSections(d, s, pipes, methodDiffers);
  animationLoops(d, s, pipes, methodDiffers);
  pipelineTable(d, r, s, pipes);
  exactFallbackTable(d, s, pipes);
  instanceTable(d, s, pipes);
  updatePhaseTable(d, r, s, pipes);
  timingParagraph(d, r, s);
}

}  // namespace mb::document
