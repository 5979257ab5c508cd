#include "harness/document/report_layout.h"

#include "harness/document/report_format.h"

namespace mb::report {
namespace {

using json = nlohmann::json;

std::vector<std::string> pipelinesOf(const json& r) {
  return at(r, {"settings", "pipelines"}).is_array() ? r["settings"]["pipelines"].get<std::vector<std::string>>()
                                                     : std::vector<std::string>{};
}

// The object at j[key] by reference (an empty object when absent): safe to iterate with
// items(), unlike the temporary that json::value() returns.
const json& members(const json& j, const char* key) {
  static const json empty = json::object();
  return j.is_object() && j.contains(key) && j[key].is_object() ? j[key] : empty;
}

std::string str(const json& v, const std::string& fallback = "-") {
  return v.is_string() ? v.get<std::string>() : v.is_number() ? fmt(v, 6) : fallback;
}

// " over N scenes" for a spread (its "n"), so a median says how many scenes it covers: the
// pipelines' figures may come from different scene sets (a skin-only quantity, a failed scene).
std::string scenesText(const json& spread, const char* what = "scenes") {
  if (!spread.is_object() || spread.value("n", 0) == 0) return "";
  const int n = spread.value("n", 0);
  return " over " + std::to_string(n) + " " + (n == 1 ? std::string(what).substr(0, std::string(what).size() - 1) : what);
}

void header(Document& d, const json& r) {
  const json& m = r["machine"];
  d.paragraph("Measured on " + str(m["cpu"]) + " (" + str(m["logicalCores"]) + " logical cores), " +
              str(m["os"]) + "; GL: " + str(at(m, {"gl", "renderer"})) + ", " +
              str(at(m, {"gl", "version"})) + " (" + str(at(m, {"gl", "backend"})) +
              "); LP_NUM_THREADS=" + str(m["lpNumThreads"], "unset") + "; " + str(m["build"]) +
              " build; " + str(m["date"]) + ".");
  const json& s = r["settings"];
  std::string pipes;
  for (const std::string& p : pipelinesOf(r)) pipes += (pipes.empty() ? "" : ", ") + p;
  d.paragraph("Pipelines " + pipes + " (diffs against " + str(s["baseline"]) + "); images " +
              str(s["width"]) + "x" + str(s["height"]) + " at up to three animation times per scene; " +
              str(s["frames"]) + " timed frames per pipeline and scene; " + str(s["jobs"]) +
              " parallel scene job(s). Every figure below comes from this run; report.json holds them all.");
  const json& sum = r["summary"];
  d.paragraph(str(sum["scenes"]) + " scene(s): " + str(sum["ok"], "0") + " ok, " + str(sum["partial"], "0") +
              " partial, " + str(sum["failed"], "0") + " failed.");
}

void summary(Document& d, const json& r) {
  const std::vector<std::string> pipes = pipelinesOf(r);
  const json& sum = r["summary"];
  d.heading(2, "Summary", "summary");
  std::vector<std::string> head = {"quantity (median (min..max) over the N scenes that have it)"};
  for (const std::string& p : pipes) head.push_back(p);
  std::vector<std::vector<Cell>> rows;
  auto row = [&](const std::string& label, auto value) {
    std::vector<Cell> cells = {{label}};
    for (const std::string& p : pipes) cells.push_back({value(p)});
    rows.push_back(cells);
  };
  auto fromSpread = [&](const char* key, int digits) {
    return [&sum, key, digits](const std::string& p) {
      const json& spread = at(sum, {"pipelines"})[p][key];
      return spreadText(spread, digits) + scenesText(spread);
    };
  };
  row("bytes per vertex, shading attributes", fromSpread("bytesPerVertex", 3));
  row("bytes per vertex, normal-mapped primitives", fromSpread("bytesPerVertexNormalMapped", 3));
  row("bytes per vertex, primitives without normal map", fromSpread("bytesPerVertexNotNormalMapped", 3));
  row("bytes per vertex incl. skin + extra streams", fromSpread("bytesPerVertexAll", 3));
  row("floats per vertex", fromSpread("floatsPerVertex", 3));
  row("floats per transform", fromSpread("floatsPerTransform", 3));
  row("floats per transform incl. the per-draw scale", fromSpread("floatsPerTransformWithScale", 3));
  row("floats per joint (skinned scenes)", fromSpread("floatsPerJoint", 3));
  row("load-time conversion [ms]", fromSpread("conversionMs", 3));
  const json& ops = r["opsPerVertex"];
  for (const char* label : {"rigid", "rigid, no tangent", "skinned", "skinned, reference", "skinned, world palette",
                            "scaled fallback", "bezier patch"})
    for (const char* way : {"counted", "spirv"}) {
      bool any = false;
      for (const json& v : ops.value("variants", json::array())) any = any || v.value("label", "") == label;
      if (!any) continue;
      row(std::string("ops per vertex, ") + label + " shader (" + (std::string(way) == "counted" ? "counted" : "SPIR-V") + ")",
          [&](const std::string& p) {
            for (const json& v : ops.value("variants", json::array()))
              if (v.value("pipeline", "") == p && v.value("label", "") == label) return opsText(v[way]);
            return std::string("-");
          });
    }
  d.table(head, rows);
  std::vector<std::string> lines;
  for (size_t i = 1; i < pipes.size(); ++i) {
    const json& im = at(sum, {"images"})[pipes[i]];
    lines.push_back(pipes[i] + " vs " + pipes[0] + ": " + str(im["comparedFrames"], "0") + " frames compared, " +
                    str(im["identicalFrames"], "0") + " identical; PSNR of the others " +
                    spreadText(im["psnr"], 4) + " dB" + scenesText(im["psnr"], "frames") + "; pixels off by more than 1/255: at most " +
                    percent(at(im, {"fractionOver1", "max"}), 3) + "; largest channel error " +
                    fmt(at(im, {"maxError", "max"}).is_number() ? json(255.0 * im["maxError"]["max"].get<double>()) : json(), 3) +
                    "/255.");
  }
  const json& ft = sum["frameTimeRatio"];
  lines.push_back("Frame time motor / matrix (median frame, per scene): " +
                  (ft.value("n", 0) ? ratio(ft["median"]) + " (" + ratio(ft["min"]) + ".." + ratio(ft["max"]) + ")" : "-") +
                  scenesText(ft) + " (< 1: motor faster).");
  std::string kr;
  for (const auto& [k, v] : members(sum, "kernelRatios").items())
    if (k.rfind("vertex_frame", 0) == 0 || k.rfind("skinned_vertex", 0) == 0) kr += (kr.empty() ? "" : ", ") + k + " " + ratio(v);
  lines.push_back("CPU kernel throughput motor / matrix (items/s, > 1: motor faster): " +
                  (kr.empty() ? str(at(r, {"kernels", "error"}), "not measured") : kr) + ".");
  d.bullets(lines);
}

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

void plots(Document& d, const json& r) {
  d.heading(2, "Plots", "plots");
  const json& p = r["plots"];
  if (p.value("files", json::array()).empty()) {
    d.paragraph("No plots: " + str(p["error"], "unknown reason") + ".");
    return;
  }
  if (p["error"].is_string()) d.paragraph("Note: " + p["error"].get<std::string>());
  for (const json& f : p["files"]) d.figure(str(f["file"]), str(f["title"]), str(f["caption"], ""));
}

std::string fallbacksText(const json& pj) {
  std::string s;
  for (const auto& [k, v] : members(pj, "fallbacks").items())
    if (v.is_number() && v.get<double>() != 0) s += (s.empty() ? "" : ", ") + k + " " + fmt(v);
  return s.empty() ? "none" : s;
}

// Worst metrics of `p` over a scene's frames (lowest PSNR, largest changed fraction).
std::pair<std::string, std::string> worstImage(const json& s, const std::string& p) {
  double psnr = 1e300, over = -1;
  bool any = false, allIdentical = true;
  for (const json& f : s.value("frames", json::array())) {
    const json& m = at(f, {"metrics"});
    if (!m.is_object() || !m.contains(p)) continue;
    any = true;
    if (!m[p].value("identical", false)) {
      allIdentical = false;
      if (m[p]["psnr"].is_number()) psnr = std::min(psnr, m[p]["psnr"].get<double>());
    }
    over = std::max(over, m[p].value("fractionOver1", 0.0));
  }
  if (!any) return {"-", "-"};
  return {allIdentical ? "identical" : fixed(json(psnr), 1) + " dB", percent(json(over), 3)};
}

void sceneTable(Document& d, const json& r) {
  const std::vector<std::string> pipes = pipelinesOf(r);
  d.heading(2, "Scenes", "scenes");
  std::vector<std::string> head = {"scene", "status", "vertices (mesh / drawn)", "triangles", "skins / joints", "animations"};
  for (const std::string& p : pipes) head.push_back(p + " B/vertex");
  for (const std::string& p : pipes) head.push_back(p + " ops/vertex");
  for (const std::string& p : pipes) head.push_back(p + " frame ms");
  head.push_back("frame time motor/matrix");
  for (size_t i = 1; i < pipes.size(); ++i) head.insert(head.end(), {pipes[i] + " worst PSNR", pipes[i] + " px > 1/255"});
  head.push_back("fallbacks (last pipeline)");
  std::vector<std::vector<Cell>> rows;
  for (const json& s : r["scenes"]) {
    const json& st = s.value("stats", json::object());
    std::vector<Cell> row = {{str(s["id"]), "", "#scene-" + str(s["id"])}, {str(s["status"])},
                             {str(at(st, {"geometry", "vertices"})) + " / " + str(at(st, {"geometry", "drawnVertices"}))},
                             {str(at(st, {"geometry", "triangles"}))},
                             {str(at(st, {"skinning", "skins"})) + " / " + str(at(st, {"skinning", "joints"}))},
                             {str(at(st, {"animation", "animations"}))}};
    for (const std::string& p : pipes) row.push_back({fmt(at(s, {"pipelines"}).is_object() && s["pipelines"].contains(p) ? at(s["pipelines"][p], {"memory", "bytesPerVertex"}) : json())});
    for (const std::string& p : pipes) {
      const json& o = at(s, {"opsPerVertex"});
      row.push_back({o.is_object() && o.contains(p) && o[p]["counted"].is_object()
                         ? fmt(json(o[p]["counted"].value("mul", 0.0) + o[p]["counted"].value("add", 0.0)), 4) + " mul+add"
                         : "-"});
    }
    for (const std::string& p : pipes) row.push_back({fixed(at(s, {"timing", "pipelines"}).is_object() && s["timing"]["pipelines"].contains(p) ? s["timing"]["pipelines"][p].value("medianMs", json()) : json(), 2)});
    row.push_back({ratio(at(s, {"timing", "ratio_motor_matrix"}))});
    for (size_t i = 1; i < pipes.size(); ++i) {
      auto [psnr, over] = worstImage(s, pipes[i]);
      row.push_back({psnr});
      row.push_back({over});
    }
    const json& last = at(s, {"pipelines"}).is_object() && s["pipelines"].contains(pipes.back()) ? s["pipelines"][pipes.back()] : json();
    row.push_back({last.is_object() ? fallbacksText(last) : "-"});
    rows.push_back(row);
  }
  d.table(head, rows);
}

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

void sceneSection(Document& d, const json& r, const json& s) {
  const std::vector<std::string> pipes = pipelinesOf(r);
  d.heading(3, str(s["id"]) + (s["spec"] != s["id"] ? " (" + str(s["spec"]) + ")" : ""), "scene-" + str(s["id"]));
  if (s["error"].is_string()) d.paragraph(std::string(s.value("status", "") == "failed" ? "FAILED" : "Error") + ": " + s["error"].get<std::string>());
  if (s.contains("workerExit")) d.paragraph("Note: the worker process ended with " + str(s["workerExit"]) + " after writing its result.");
  d.bullets(statsLines(s.value("stats", json())));
  if (at(s, {"vertexMix", "skinned"}).is_number() && s["vertexMix"]["skinned"].get<double>() > 0)
    d.paragraph("Skinned scene: the matrix pipeline blends joints with linear blend skinning (LBS), the motor "
                "pipeline blends joint motors (the dual-quaternion method). Where joints turn far apart the two "
                "methods pose the mesh differently by design (LBS loses volume, a candy wrapper pinches), so the "
                "difference columns below measure the methods' expected difference, not an error of either.");
  // Thumbnails: one row per time.
  std::vector<std::string> head = {"time [s]"};
  for (const std::string& p : pipes) head.push_back(p);
  for (size_t i = 1; i < pipes.size(); ++i) head.push_back("diff " + pipes[i] + " vs " + pipes[0]);
  head.push_back("metrics");
  std::vector<std::vector<Cell>> rows;
  for (const json& f : s.value("frames", json::array())) {
    std::vector<Cell> row = {{fixed(f["time"], 3)}};
    for (const std::string& p : pipes) {
      const json& img = at(f, {"images"}).is_object() && f["images"].contains(p) ? f["images"][p] : json();
      if (img.is_string()) row.push_back({"", img.get<std::string>(), img.get<std::string>()});
      else row.push_back({"error: " + str(at(f, {"errors"}).is_object() && f["errors"].contains(p) ? f["errors"][p] : json())});
    }
    std::string metrics;
    for (size_t i = 1; i < pipes.size(); ++i) {
      const json& img = at(f, {"diffs"}).is_object() && f["diffs"].contains(pipes[i]) ? f["diffs"][pipes[i]] : json();
      row.push_back(img.is_string() ? Cell{"", img.get<std::string>(), img.get<std::string>()} : Cell{"-"});
      const json& m = at(f, {"metrics"}).is_object() && f["metrics"].contains(pipes[i]) ? f["metrics"][pipes[i]] : json();
      if (m.is_object())
        metrics += (metrics.empty() ? "" : "; ") + pipes[i] + ": PSNR " + psnrText(m) + ", RMSE " + fmt(m["rmse"], 3) +
                   ", max " + fmt(json(255.0 * m.value("maxError", 0.0)), 3) + "/255, > 1/255 " +
                   percent(m["fractionOver1"], 3) + ", > 4/255 " + percent(m["fractionOver4"], 3);
    }
    row.push_back({metrics.empty() ? "-" : metrics});
    rows.push_back(row);
  }
  if (!rows.empty()) d.table(head, rows);
  // One loop of the animation, baseline | pipeline | diff, per compared pipeline.
  if (s.contains("animated") && s["animated"].is_object())
    for (const auto& [p, a] : s["animated"].items()) {
      if (a.contains("file"))
        d.figure(a["file"].get<std::string>(), "Animated: " + pipes[0] + " | " + p + " | diff",
                 "One loop of animation 0 (" + fixed(a["duration"], 2) + " s) in " + str(a["frames"]) + " frames at " +
                     str(a["fps"]) + " fps: " + pipes[0] + " left, " + p + " middle, diff heat map right; at most " +
                     percent(a["maxPixelsOver2"], 2) + " of the pixels differ by more than 2/255 in any frame.");
      else
        d.paragraph("Animated comparison " + pipes[0] + " vs " + p + " not made: " + str(a.value("error", json())));
    }
  // Per pipeline: memory, conversion, fallbacks, timing.
  std::vector<std::vector<Cell>> prow;
  for (const std::string& p : pipes) {
    if (!at(s, {"pipelines"}).is_object() || !s["pipelines"].contains(p)) continue;
    const json& pj = s["pipelines"][p];
    const json& mem = pj.value("memory", json::object());
    const json& t = at(s, {"timing", "pipelines"}).is_object() && s["timing"]["pipelines"].contains(p) ? s["timing"]["pipelines"][p] : json();
    const json& o = at(s, {"opsPerVertex"}).is_object() && s["opsPerVertex"].contains(p) ? s["opsPerVertex"][p] : json();
    prow.push_back({{p}, {fmt(mem.value("bytesPerVertex", json()))}, {fmt(mem.value("floatsPerVertex", json()))},
                    {fmt(mem.value("floatsPerTransform", json()))}, {fmt(mem.value("floatsPerJoint", json()))},
                    {str(mem.value("vertexBytes", json())) + " / " + str(mem.value("skinVertexBytes", json())) + " / " +
                     str(mem.value("indexBytes", json())) + " / " + str(mem.value("textureBytes", json()))},
                    {str(mem.value("uniformBytesPerFrame", json())) + " / " + str(mem.value("skinBytesPerFrame", json()))},
                    {str(pj.value("draws", json()))}, {fixed(at(pj, {"conversionMs", "median"}), 3)},
                    {fallbacksText(pj)}, {o.is_object() ? opsText(o["counted"], 1) : "-"},
                    {t.is_object() ? fixed(t.value("medianMs", json()), 2) + " (" + fixed(t.value("minMs", json()), 2) + ".." +
                                         fixed(t.value("maxMs", json()), 2) + ")" : "-"},
                    {t.is_object() ? fmt(t.value("updateMedianMs", json()), 3) : "-"},
                    {pj["error"].is_string() ? pj["error"].get<std::string>() : ""}});
  }
  if (!prow.empty())
    d.table({"pipeline", "B/vertex", "floats/vertex", "floats/transform", "floats/joint",
             "bytes: vertex / skin / index / texture", "bytes per frame: uniforms / joint palette", "draws",
             "conversion ms (median)", "fallbacks", "ops/vertex (counted, mean)", "frame ms median (min..max)",
             "CPU update ms", "error"},
            prow);
  // The CPU update phase by phase (harness/timing: a block of updates with the phase clock on).
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
  if (!urow.empty()) {
    d.paragraph("CPU update by phase: microseconds per update call, medians over the timed frames, from a block "
                "of updates timed with the pipelines' phase clock on (apart from the whole-update timing, whose "
                "median is the last column; the phases include their clock reads).");
    d.table({"pipeline", "sampling us", "blending us", "conversion us", "hierarchy us", "palette us",
             "whole update us"},
            urow);
  }
  const json& timing = s.value("timing", json());
  if (timing.is_object()) {
    if (timing["error"].is_string()) d.paragraph("Frame timing: " + timing["error"].get<std::string>());
    else if (timing.contains("summary")) {
      auto ratios = [](const json& c) {
        return "frame " + ratio(at(c, {"ratio_motor_matrix"})) + ", paired per frame " +
               ratio(at(c, {"paired_ratio_motor_matrix"})) + ", process CPU time " +
               ratio(at(c, {"paired_cpu_ratio_motor_matrix"})) + ", CPU update " +
               ratio(at(c, {"update", "ratio_motor_matrix"}));
      };
      const json& vb = timing.value("vertexBound", json());
      d.paragraph("Frame timing: " + str(timing["summary"]) + " Motor / matrix: " + ratios(timing) +
                  "; vertex-bound: " + (vb.contains("skipped") ? str(vb["skipped"]) : ratios(vb)) + ".");
    }
  }
}

void opsSection(Document& d, const json& r) {
  const json& ops = r["opsPerVertex"];
  d.heading(2, "Ops per vertex", "ops");
  d.paragraph("Each pipeline's vertex-shader variants (transform + world to clip). Counted: the GLSL "
              "functions executed once on the op-counting scalar through the shim; SPIR-V: the real "
              "vertex shader compiled with glslangValidator, optimised with spirv-opt -O, vector and "
              "matrix instructions expanded to scalar operations." +
              (ops.value("toolsProblem", "").empty() ? std::string() : " SPIR-V not counted: " + str(ops["toolsProblem"])));
  std::vector<std::vector<Cell>> rows;
  for (const json& v : ops.value("variants", json::array()))
    rows.push_back({{str(v["pipeline"])}, {str(v["label"])}, {str(v["shader"])}, {opsText(v["counted"])},
                    {opsText(v["spirv"])}, {str(v["difference"], "")}});
  d.table({"pipeline", "variant", "shader", "counted", "SPIR-V", "why they differ"}, rows);
  rows.clear();
  for (const json& k : ops.value("kernels", json::array()))
    rows.push_back({{str(k["pipeline"])}, {str(k["kernel"])}, {str(k["function"])}, {opsText(k["counted"])},
                    {opsText(k["spirv"])}, {str(k["difference"], "") + (str(k["note"], "").empty() ? "" : " " + str(k["note"]))}});
  d.table({"pipeline", "kernel", "function", "counted", "SPIR-V (probe)", "difference / note"}, rows);
}

void kernelSection(Document& d, const json& r) {
  const json& k = r["kernels"];
  d.heading(2, "Kernel throughput (CPU, Google Benchmark)", "kernels");
  if (k["error"].is_string()) {
    d.paragraph("Not available: " + k["error"].get<std::string>() + ".");
    return;
  }
  d.paragraph("motorbench bench (" + std::string(k.value("source", "") == "run" ? "run by this report" : "read from " + str(k["file"])) +
              "): matrix and motor kernels compiled from the same shader source through the shim with "
              "float; glm = GLM's own operators (extra baseline). Out of cache = arrays of at least 256 MiB; "
              "bw = bytes/s over the STREAM probe. Ratios of items/s: > 1 means faster than matrix.");
  std::vector<std::vector<Cell>> rows;
  for (const json& p : k.value("pairs", json::array())) {
    auto ips = [&](const char* side) { return fmt(at(p, {side, "items_per_second"}), 4); };
    auto bw = [&](const char* side) { return fixed(at(p, {side, "bw_fraction"}), 2); };
    rows.push_back({{str(p["kernel"])}, {str(p["size"], "-")}, {ips("matrix")}, {ips("motor")}, {ips("glm")},
                    {ratio(p["ratio_motor_matrix"])}, {ratio(p["ratio_glm_matrix"])},
                    {bw("matrix") + " / " + bw("motor")}});
  }
  d.table({"kernel", "working set", "matrix items/s", "motor items/s", "glm items/s", "motor/matrix", "glm/matrix",
           "bw fraction matrix / motor"},
          rows);
  std::string probe;
  for (const json& p : k.value("probe", json::array()))
    probe += (probe.empty() ? "" : ", ") + str(p["name"]) + " " + fmt(json(p.value("bytes_per_second", 0.0) / 1e9), 3) + " GB/s";
  if (!probe.empty()) d.paragraph("Bandwidth probe (one core): " + probe + ".");
}

void method(Document& d) {
  d.heading(2, "How this was measured", "method");
  d.bullets({
      "Images: each pipeline renders the scene on the headless GL context (renderFrame, as `motorbench "
      "render`), at t = 0, 1/3 and 2/3 of the first animation's duration (t = 0 only, the rest pose, for "
      "scenes without animation); metrics and heat maps are those of `motorbench compare` (OpenImageIO, "
      "8-bit RGBA, the first pipeline is the baseline).",
      "Memory: PipelineStats, summed from the sizes passed to the GL upload calls of prepare() and the last "
      "update()/render(); bytes per vertex = shading-attribute bytes / uploaded vertices.",
      "Ops per vertex: counted by executing the pipelines' GLSL transform functions on an op-counting scalar, "
      "and cross-checked in the optimised SPIR-V of the real vertex shaders; per scene, the mean over drawn "
      "vertices, weighted by the variant (rigid, skinned, scaled fallback) each vertex goes through.",
      "Frame timing (harness/timing/frame_timing.h, as `motorbench time`): per scene, in a worker process that runs "
      "alone (never alongside other scenes); wall clock around update + render + glFinish after warm-up, each "
      "frame the fastest of a few renders, pipelines interleaved; process CPU time and the CPU update beside "
      "it; ratios are motor / matrix from the same process.",
      "Kernel throughput: Google Benchmark via `motorbench bench` (JSON kept next to the report).",
      "Load-time conversion: PipelineStats.conversionMs of each prepare() (median of the image renders).",
      "Statistics: `motorbench inspect`'s per-file statistics (pipelines/scene/scene_stats.h)."});
}

}  // namespace

Document reportDocument(const json& r) {
  Document d;
  d.title = "motorbench report";
  header(d, r);
  summary(d, r);
  plots(d, r);
  sceneTable(d, r);
  for (const json& s : r["scenes"]) sceneSection(d, r, s);
  opsSection(d, r);
  kernelSection(d, r);
  method(d);
  glossary(d, r);
  return d;
}

}  // namespace mb::report
