#include "harness/document/report_layout_sections.h"

#include <algorithm>
#include <map>

#include "harness/document/ops_ranking.h"
#include "harness/document/report_document.h"
#include "harness/document/report_format.h"
#include "harness/document/report_layout_common.h"
#include "harness/document/report_marks.h"
#include "harness/figures/figure.h"

namespace mb::document {

using namespace layout;


// The heat maps' colour scale (report.json "diffLegend") and what every counter means
// (report.json "glossary"), so the figures above read without the source.
void glossary(Document& d, const json& r) {
  d.heading(2, "Glossary", "glossary");
  const json& legend = r["diffLegend"];
  if (legend.is_object()) {
    std::string stops;
    for (const json& s : legend.value("stops", json::array()))
      stops += (stops.empty() ? "" : ", ") + str(s["steps"]) + " step(s) rgb(" + str(s["rgb"][0]) + "," +
               str(s["rgb"][1]) + "," + str(s["rgb"][2]) + ")";
    d.paragraph("Diff heat maps: " + str(legend["unchanged"]) + "; " + str(legend["scale"]) + ". Colours: " + stops + ".");
  }
  for (const auto& [group, entries] : members(r, "glossary").items()) {
    std::vector<std::vector<Cell>> rows;
    for (const auto& [key, e] : entries.items()) rows.push_back({{key}, {str(e["unit"], "")}, {str(e["meaning"], "")}});
    d.heading(3, group);
    d.table({"counter", "unit", "meaning"}, rows);
  }
}

// Curved space: each curved scene with its own space's pipelines, one row per
// pipeline, and the camera drift when the run measured it.
void curvedSection(Document& d, const json& r) {
  const json& rows = at(r, {"summary", "curved"});
  if (!rows.is_array() || rows.empty()) return;
  d.heading(2, "Curved space", "curved");
  d.paragraph("Spherical (S3) and hyperbolic (H3) scenes drawn by their space's pipelines: the matrix side "
              "uploads an O(4) / O(3,1) 4x4 matrix per instance, the motor side an 8-float motor (S3: the "
              "quaternion pair) and sandwiches in the vertex shader. Floats per instance as uploaded; ops per "
              "vertex in two scopes: counted, the instance transform only (position + normal by camera * instance, "
              "the projection left out), and SPIR-V whole shader, the optimised vertex shader with main() (the "
              "projection included, one mat4 * vec4 the same on both sides); PSNR of the motor images against the matrix ones; frame time motor / matrix "
              "paired per frame in one run, at the timing viewport and at the small vertex-bound one.");
  std::vector<std::vector<Cell>> table;
  for (const json& c : rows) {
    const std::vector<std::string> pipes = c.value("pipelines", json::array()).get<std::vector<std::string>>();
    for (size_t k = 0; k < pipes.size(); ++k) {
      const std::string& p = pipes[k];
      const json& o = at(c, {"opsPerVertex"}).is_object() && c["opsPerVertex"].contains(p) ? c["opsPerVertex"][p] : json();
      const bool first = k == 0;
      table.push_back({{first ? str(c["id"]) : "", "", first ? "#scene-" + str(c["id"]) : ""},
                       {first ? str(c["space"]) : ""}, {p},
                       {fmt(at(c, {"floatsPerInstance"}).is_object() && c["floatsPerInstance"].contains(p) ? c["floatsPerInstance"][p] : json())},
                       {o.is_object() ? opsText(o["counted"]) : "-"}, {o.is_object() ? opsText(o["spirv"]) : "-"},
                       {first ? "baseline" : str(at(c, {"images", "identicalFrames"}), "0") + " of " +
                                                 str(at(c, {"images", "comparedFrames"}), "0") + " identical; PSNR " +
                                                 spreadText(at(c, {"images", "psnr"}), 4) + " dB"},
                       {first ? "" : ratio(at(c, {"frameTimeRatio", "normal"}))},
                       {first ? "" : ratio(at(c, {"frameTimeRatio", "vertexBound"}))}});
    }
  }
  d.paragraph(frameTimeOn(at(r, {"machine", "gl"})) + ": the two motor/matrix columns.");
  d.table({"scene", "space", "pipeline", "floats per instance", "ops per vertex (counted, transform only)",
           "ops per vertex (SPIR-V whole shader, projection included)",
           "images vs matrix side", "frame time motor/matrix", "vertex-bound motor/matrix"},
          table);
  const json& drift = at(r, {"curved", "drift"});
  if (at(drift, {"spaces"}).is_array()) {
    std::vector<std::vector<Cell>> dr;
    for (const json& sp : drift["spaces"])
      for (const char* side : {"matrix", "motor"})
        dr.push_back({{str(sp["space"])}, {side}, {fmt(at(sp, {side, "raw"}), 3)}, {fmt(at(sp, {side, "renormalised"}), 3)},
                      {opsText(at(sp, {side, "renormOps"}))}, {str(at(sp, {side, "renormalisation"}), "")}});
    d.paragraph("Camera drift after " + str(at(drift, {"steps"})) + " accumulated float steps (" + str(at(drift, {"step"}), "") +
                "): distance from the group, matrix max|M^T eta M - eta|, motor max|M~M - 1| (S3 pair: "
                "||L|^2 - 1|, ||R|^2 - 1|), without renormalisation and renormalised after every step (`motorbench drift`).");
    d.table({"space", "side", "raw", "renormalised", "one renormalisation", "method"}, dr);
  } else if (at(drift, {"error"}).is_string()) {
    d.paragraph("Camera drift not measured: " + drift["error"].get<std::string>());
  }
}


// inspect's statistics apart for the generated built-in scenes and for real files (a
// fraction over "a corpus" must not count the built-ins, which exercise features on purpose).
void statisticsSection(Document& d, const json& r) {
  const json& st = at(r, {"summary", "statistics"});
  if (!st.is_object()) return;
  d.heading(2, "Scene statistics by origin", "statistics");
  d.paragraph("Counts over the loaded scenes, the built-in ones (generated by code to exercise skinning, "
              "hierarchy, scale and normal maps: not a sample of real content) apart from the files. "
              "Fractions of real content come from the files column only; a sample of N files cannot "
              "show a fraction below 1/N.");
  auto frac = [](const json& a, const char* n) {
    const int loaded = a.value("loaded", 0);
    return str(a.value(n, json()), "0") + (loaded ? " (" + percent(json(double(a.value(n, 0)) / loaded), 1) + ")" : "");
  };
  std::vector<std::vector<Cell>> rows;
  const json& b = at(st, {"builtIn"});
  const json& f = at(st, {"files"});
  if (!b.is_object() || !f.is_object()) return;
  rows.push_back({{"loaded (failed)"}, {str(b.value("loaded", json()), "0") + " (" + str(b.value("failed", json()), "0") + ")"},
                  {str(f.value("loaded", json()), "0") + " (" + str(f.value("failed", json()), "0") + ")"}});
  for (const auto& [label, key] : std::vector<std::pair<std::string, const char*>>{
           {"skinned", "filesSkinned"}, {"normal-mapped", "filesNormalMapped"},
           // A scale channel whose keys never change sets a scale and animates nothing: counted apart.
           {"scale keys changing the scale", "filesWithChangingScale"},
           {"scale channels with constant keys only", "filesWithOnlyConstantScaleChannels"},
           {"non-uniform scale", "filesWithNonUniformScale"},
           {"non-uniform scale only on leaves", "filesWithNonUniformOnlyOnLeaves"},
           {"negative scale (mirror)", "filesWithNegativeScale"}, {"loader fallbacks", "filesWithFallbacks"},
           {"unsupported features", "filesWithUnsupported"}})
    rows.push_back({{label}, {frac(b, key)}, {frac(f, key)}});
  for (const char* k : {"vertices", "triangles", "primitives", "joints", "channels"})
    rows.push_back({{k}, {str(b.value(k, json()), "0")}, {str(f.value(k, json()), "0")}});
  d.table({"scenes with ...", "built-in (synthetic)", "files (real)"}, rows);
}

void opsSection(Document& d, const json& r) {
  const json& ops = r["opsPerVertex"];
  d.heading(2, "Ops per vertex", "ops");
  d.paragraph("Each pipeline's vertex-shader variants (transform + world to clip). Counted: the GLSL "
              "functions executed once on the op-counting scalar through the shim; SPIR-V probe: those "
              "functions compiled alone; SPIR-V whole shader: the real vertex shader with its main(); both "
              "compiled with glslangValidator, optimised with spirv-opt -O, vector and "
              "matrix instructions expanded to scalar operations." +
              (ops.value("toolsProblem", "").empty() ? std::string() : " SPIR-V not counted: " + str(ops["toolsProblem"])));
  std::vector<std::vector<Cell>> rows;
  // One row per registered pipeline (harness/ops/pipeline_ops.h): what the README's table quotes.
  auto figure = [](const json& f, const char* way) { return f.is_object() ? opsText(f[way]) : std::string("-"); };
  for (const json& p : ops.value("perPipeline", json::array()))
    rows.push_back({{str(p["pipeline"])}, {figure(p["rigid"], "counted")}, {figure(p["skinned"], "counted")},
                    {figure(p["toClip"], "counted")}, {figure(p["toClip"], "spirv")}, {figure(p["patch"], "counted")},
                    {str(p["problem"], "")}});
  if (!rows.empty())
    d.table({"pipeline", "rigid (transform)", "skinned (transform, 4 joints)", "rigid to clip", "to clip (SPIR-V probes)",
             "bezier patch to clip", "problem"},
            rows);
  opsRankingSection(d, r);  // the three measures' ranking, as report.json "opsRanking" has it
  rows.clear();
  for (const json& v : ops.value("variants", json::array()))
    rows.push_back({{str(v["pipeline"])}, {str(v["label"])}, {str(v["shader"])}, {opsText(v["counted"])},
                    {opsText(v["spirv"])}, {str(v["difference"], "")}});
  d.table({"pipeline", "variant", "shader", "counted", "SPIR-V whole shader", "why they differ"}, rows);
  rows.clear();
  for (const json& k : ops.value("kernels", json::array()))
    rows.push_back({{str(k["pipeline"])}, {str(k["kernel"])}, {str(k["function"])}, {opsText(k["counted"])},
                    {opsText(k["spirv"])}, {str(k["difference"], "") + (str(k["note"], "").empty() ? "" : " " + str(k["note"]))}});
  d.table({"pipeline", "kernel", "function", "counted", "SPIR-V probe", "difference / note"}, rows);
}

namespace {

// "Google Benchmark's median of 3 repetitions" from the sides' recorded repetitions; a bench
// file that does not record them says so.
std::string repetitionsText(const json& kernels) {
  std::vector<int> seen;
  for (const json& p : kernels.value("pairs", json::array()))
    for (const auto& [side, v] : p.items())
      if (at(v, {"repetitions"}).is_number_integer() &&
          std::find(seen.begin(), seen.end(), v["repetitions"].get<int>()) == seen.end())
        seen.push_back(v["repetitions"].get<int>());
  if (seen.empty()) return "one run or Google Benchmark's median of repetitions (not recorded in this report.json)";
  std::sort(seen.begin(), seen.end());
  if (seen == std::vector<int>{1}) return "one Google Benchmark run";
  std::string n;
  for (int k : seen) n += (n.empty() ? "" : " or ") + std::to_string(k);
  return "Google Benchmark's median of " + n + " repetitions (each repetition and their spread in bench.json)";
}

}  // namespace

void kernelSection(Document& d, const json& r) {
  const json& k = r["kernels"];
  d.heading(2, "Kernel throughput (CPU, Google Benchmark)", "kernels");
  if (k["error"].is_string()) {
    d.paragraph("Not available: " + k["error"].get<std::string>() + ".");
    return;
  }
  // The machine the bench ran on (its JSON's context; an older bench file lacks it).
  const json& ctx = k.value("context", json::object());
  d.paragraph("Measured on " +
              (ctx.contains("cpu_model")
                   ? cpuMachineText(ctx["cpu_model"], ctx["logical_cores"], ctx["simd_target"])
                   : "an unnamed CPU (the bench file does not name it; this report ran on " +
                         cpuMachineText(r["machine"]["cpu"], r["machine"]["logicalCores"], r["machine"]["simdTarget"]) + ")") +
              " (CPU kernel ratios hold for the CPU named).");
  d.paragraph("motorbench bench (" + std::string(k.value("source", "") == "run" ? "run by this report" : "read from " + str(k["file"])) +
              "): matrix and motor kernels compiled from the same shader source through the shim with "
              "float; glm = GLM's own operators (extra baseline); simd_matrix / simd_motor = kernels/simd, the same math "
              "hand-vectorised with Highway (compose also has simd_affine, the mat4x3 product, and lanes_motor, the "
              "4-lane motor product of the motor pipelines' CPU update). Out of cache = arrays "
              "of at least 256 MiB; "
              "bw = bytes/s over the STREAM probe. Each items/s is " + repetitionsText(k) +
              ". Every ratio is time per item motor / matrix (the inverse of the items/s "
              "ratio; < 1: motor faster), as in the summary and the plot. Skinned vertices in "
              "matched configurations: skinned_vertex with a world-space palette on every side, "
              "skinned_vertex_reference in the references' form (the node's transform after the blend) on every side.");
  std::vector<std::vector<Cell>> rows;
  for (const json& p : k.value("pairs", json::array())) {
    auto ips = [&](const char* side) { return fmt(at(p, {side, "items_per_second"}), 4); };
    auto bw = [&](const char* side) { return fixed(at(p, {side, "bw_fraction"}), 2); };
    // The time ratios are report.json's figures (kernel_time.<pair>.*), the values the summary quotes.
    const std::string pair = str(p["pair"]);
    const auto shim = figures::figureNamed(r, "kernel_time." + pair + ".shim_motor_over_shim_matrix");
    const auto fastest = figures::figureNamed(r, "kernel_time." + pair + ".fastest_motor_over_fastest_matrix");
    const std::string best = fastest ? figureMark(fastest->name, figures::valueText(*fastest)) + " (" +
                                           str(p["fastest_motor"]) + " / " + str(p["fastest_matrix"]) + ")"
                                     : "-";
    rows.push_back({{str(p["kernel"])}, {str(p["size"], "-")}, {ips("matrix")}, {ips("motor")}, {ips("glm")},
                    {ips("simd_matrix")}, {ips("simd_motor")},
                    {shim ? figureMark(shim->name, figures::valueText(*shim)) : "-"}, {best},
                    {bw("matrix") + " / " + bw("motor") + " / " + bw("simd_matrix") + " / " + bw("simd_motor")}});
  }
  d.table({"kernel", "working set", "matrix items/s", "motor items/s", "glm items/s", "simd_matrix items/s",
           "simd_motor items/s", "time motor / matrix (shim sources)", "time fastest motor / fastest matrix",
           "bw fraction matrix / motor / simd_matrix / simd_motor"},
          rows);
  std::string probe;
  for (const json& p : k.value("probe", json::array()))
    probe += (probe.empty() ? "" : ", ") + str(p["name"]) + " " + fmt(json(p.value("bytes_per_second", 0.0) / 1e9), 3) + " GB/s";
  if (!probe.empty()) d.paragraph("Bandwidth probe (one core): " + probe + ".");
}

void method(Document& d) {
  d.heading(2, "How this was measured", "method");
  d.bullets({
      "Images: each pipeline of the scene's space renders it on the headless GL context (renderFrame, as "
      "`motorbench render`), at t = 0, 1/3 and 2/3 of each animation shown (the first, or those --anim "
      "chose; t = 0 only, the rest pose, for scenes without animation); metrics and heat maps are those of `motorbench compare` (OpenImageIO, "
      "8-bit RGBA, the first pipeline is the baseline).",
      "Memory: PipelineStats, summed from the sizes passed to the GL upload calls of prepare() and the last "
      "update()/render(); bytes per vertex = shading-attribute bytes / uploaded vertices.",
      "Ops per vertex: counted by executing the pipelines' GLSL transform functions on an op-counting scalar, "
      "and cross-checked in the optimised SPIR-V of the real vertex shaders; per scene, the mean over drawn "
      "vertices, weighted by the variant (rigid, skinned, scaled fallback) each vertex goes through; the "
      "vertices the motor family's exact fallback drew (the most in any frame) at its own variants (linear "
      "fallback, skinned linear fallback).",
      "Frame timing (harness/timing/frame_timing.h, as `motorbench time`): per scene, in a worker process that runs "
      "alone (never alongside other scenes); on a CPU rasterizer the wall clock around update + render + glFinish, "
      "on a real GPU GL_TIME_ELAPSED timer queries (wall clock beside them), after warm-up, each "
      "frame the fastest of a few renders, pipelines interleaved; process CPU time and the CPU update beside "
      "it; ratios are motor / matrix from the same process.",
      "Kernel throughput: Google Benchmark via `motorbench bench` (JSON kept next to the report).",
      "Load-time conversion: PipelineStats.conversionMs of each prepare() (median of the image renders).",
      "Statistics: `motorbench inspect`'s per-file statistics (pipelines/scene/scene_stats.h)."});
}

}  // namespace mb::document
