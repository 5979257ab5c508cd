#include "harness/document/report_figures.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <map>

#include "harness/document/report_format.h"
#include "pipelines/registry.h"

namespace mb::document {
namespace {

using json = nlohmann::json;
using figures::Figure;
using figures::numberOrNaN;

const char* kPairedStatistic = "median of per-frame paired ratios (both pipelines render each frame back to back)";
const char* kOverScenes = "median over scenes of each scene's median of per-frame paired ratios";

std::string sizeOf(const json& config) {
  if (!config.value("width", json()).is_number()) return "";
  return std::to_string(config["width"].get<int>()) + "x" + std::to_string(config["height"].get<int>());
}

bool euclidean(const json& s) { return s.value("space", "Euclidean") == "Euclidean"; }

// Frame-time figures of one configuration ("" = the normal one, "vertexBound") over scenes.
void frameTimeFigures(json& out, const std::vector<json>& scenes, const char* config, const std::string& device) {
  const std::string key = config[0] ? "frame_time_vertex_bound" : "frame_time";
  std::vector<double> perScene;
  std::string sizes;
  for (const json& s : scenes) {
    if (!euclidean(s)) continue;
    const json& timing = s.value("timing", json());
    const json& c = config[0] ? at(timing, {config}) : timing;
    if (!c.is_object()) continue;
    Figure f = sceneFrameTimeFigure(key + "." + s.value("id", "") + ".motor_over_matrix", c, device);
    figures::put(out, f);
    if (std::isfinite(f.value)) {
      perScene.push_back(f.value);
      if (sizes.find(sizeOf(c)) == std::string::npos) sizes += (sizes.empty() ? "" : ", ") + sizeOf(c);
    }
  }
  // Every pipeline against the matrix pipeline, from each scene's paired ratios (report_timing's
  // pairedRatioToMatrix): the compact table and the plots read these.
  std::map<std::string, std::vector<double>> byPipeline;
  for (const json& s : scenes) {
    if (!euclidean(s)) continue;
    const json& c = config[0] ? at(s.value("timing", json()), {config}) : s.value("timing", json());
    const json& ps = at(c, {"pipelines"});
    if (!ps.is_object()) continue;
    for (const auto& [p, v] : ps.items())
      if (at(v, {"pairedRatioToMatrix", "median"}).is_number()) byPipeline[p].push_back(v["pairedRatioToMatrix"]["median"]);
  }
  for (const auto& [p, v] : byPipeline) {
    Figure f;
    f.kind = "measured";
    f.name = key + "." + p + "_over_matrix";
    f.unit = "x";
    f.statistic = kOverScenes;
    f.scope = std::string(config[0] ? "vertex-bound viewport, " : "whole frame, ") + "Euclidean scenes";
    f.device = device;
    f.definition = "frame time " + p + " / matrix (< 1: " + p + " faster); spread: the interquartile range over the scenes";
    figures::put(out, figures::withQuartiles(f, figures::quartilesOf(v)));
  }
  Figure all;
  all.kind = "measured";
  all.name = key + ".motor_over_matrix";
  all.unit = "x";
  all.statistic = kOverScenes;
  all.scope = std::string(config[0] ? "vertex-bound viewport, " : "whole frame, ") + "Euclidean scenes" +
              (sizes.empty() ? "" : " at " + sizes);
  all.device = device;
  all.definition = "frame time motor / matrix (< 1: motor faster); spread: the interquartile range over the scenes";
  figures::put(out, figures::withQuartiles(all, figures::quartilesOf(perScene)));
}

// Per pipeline, the median over scenes of one PipelineStats figure.
void memoryFigure(json& out, const std::vector<json>& scenes, const std::vector<std::string>& pipelines,
                  const char* field, const std::string& name, const std::string& unit, const std::string& scope) {
  for (const std::string& p : pipelines) {
    std::vector<double> v;
    for (const json& s : scenes) {
      const double x = numberOrNaN(at(s, {"pipelines", p.c_str(), "memory", field}));
      if (x > 0) v.push_back(x);
    }
    Figure f;
    f.kind = "measured";
    f.name = name + "." + p;
    f.unit = unit;
    f.statistic = "median over scenes";
    f.scope = scope;
    f.device = "buffers uploaded (PipelineStats)";
    f.definition = std::string("PipelineStats.") + field + " of the pipeline's uploads, per scene that has it";
    figures::put(out, figures::withQuartiles(f, figures::quartilesOf(v)));
  }
}

Figure opsFigure(const std::string& name, double total, const std::string& scope, const std::string& source) {
  Figure f;
  f.kind = name.find(".counted.") != std::string::npos ? "counted" : "compiled";
  f.name = name;
  f.value = total;
  f.unit = "ops";
  f.n = std::isfinite(total) ? 1 : 0;
  f.statistic = "count (mul + add + div + sqrt + other)";
  f.scope = scope;
  f.device = source;
  f.definition = "arithmetic operations per vertex; subtraction counts as addition, negation is free";
  if (!std::isfinite(total)) f.why = "not counted";
  return f;
}

// Ops per vertex: counted and SPIR-V of the transform functions compiled alone (the probe), per
// kind; SPIR-V of the whole vertex shader (main() included) per shader variant.
void opsFigures(json& out, const json& ops) {
  const std::pair<const char*, const char*> kinds[] = {{"rigid", "rigid vertex with frame, transform only"},
                                                       {"skinned", "skinned vertex (4 joints), transform only"},
                                                       {"toClip", "rigid vertex with frame, object to clip"}};
  // A curved pipeline's probe is its instance transform (position and normal by camera * instance);
  // the projection, the same on both sides, is in main() only (its whole-shader figure).
  const char* kCurvedScope = "instance vertex (position + normal by camera * instance), projection left out";
  for (const json& row : ops.value("perPipeline", json::array())) {
    const std::string p = row.value("pipeline", "");
    const PipelineEntry* e = findPipeline(p);
    const bool curved = e && e->space != Space::Euclidean;
    for (const auto& [kind, euclideanScope] : kinds) {
      const std::string k = kind == std::string("toClip") ? "to_clip" : kind;
      const std::string scope = curved ? kCurvedScope : euclideanScope;
      figures::put(out, opsFigure("ops_per_vertex." + k + ".counted." + p, opsTotal(at(row, {kind, "counted"})), scope,
                                  "counted (op-counting scalar through the GLSL shim)"));
      figures::put(out, opsFigure("ops_per_vertex." + k + ".spirv_probe." + p, opsTotal(at(row, {kind, "spirv"})), scope,
                                  "SPIR-V probe: the transform functions compiled alone"));
    }
  }
  for (const json& v : ops.value("variants", json::array()))
    figures::put(out, opsFigure("ops_per_vertex." + v.value("label", "") + ".spirv_whole_shader." + v.value("pipeline", ""),
                                opsTotal(v.value("spirv", json())), "whole vertex shader " + v.value("shader", ""),
                                "SPIR-V whole shader: main() included"));
}

// "the median of 3 repetitions" (the sides' recorded count; a bench file without it: "one run
// or the median of the bench's repetitions").
std::string repetitionsOf(const json& pair, std::initializer_list<std::string> sides) {
  int n = 0;
  for (const std::string& side : sides) {
    const json& r = at(pair, {side.c_str(), "repetitions"});
    if (!r.is_number_integer()) return "one run or the median of the bench's repetitions (not recorded)";
    n = n == 0 ? r.get<int>() : std::min(n, r.get<int>());
  }
  return n > 1 ? "the median of " + std::to_string(n) + " repetitions" : "one run";
}

// CPU kernels: time of the fastest motor implementation / the fastest matrix implementation
// (items/s inverted), and the shim sources against each other, named apart.
void kernelFigures(json& out, const json& kernels, const std::string& cpu) {
  for (const json& p : kernels.value("pairs", json::array())) {
    const std::string pair = p.value("pair", "");
    auto ips = [&](const std::string& side) { return numberOrNaN(at(p, {side.c_str(), "items_per_second"})); };
    auto add = [&](const std::string& name, const std::string& motor, const std::string& matrix, const std::string& what) {
      Figure f;
      f.kind = "measured";
      f.name = name;
      f.unit = "x";
      f.value = ips(motor) > 0 && ips(matrix) > 0 ? ips(matrix) / ips(motor) : std::nan("");
      f.n = std::isfinite(f.value) ? 1 : 0;
      f.statistic = "ratio of two Google Benchmark throughputs (items/s), each " + repetitionsOf(p, {motor, matrix}) +
                    ", expressed as time motor / matrix";
      f.scope = "CPU kernel " + pair + ": " + what + " (" + motor + " / " + matrix + ")";
      f.device = cpu;
      // The Highway target beside the CPU where a side is a SIMD kernel (its label).
      for (const std::string& side : {motor, matrix})
        if (at(p, {side.c_str(), "label"}).is_string()) {
          f.device += ", Highway " + at(p, {side.c_str(), "label"}).get<std::string>();
          break;
        }
      // Disturbed when either side's figure was (report_bench: CPU/real and the run queue).
      for (const std::string& side : {motor, matrix}) {
        const json& d = at(p, {side.c_str(), "disturbance"});
        if (d.is_object() && (f.disturbed.is_null() || d.value("disturbed", false))) f.disturbed = d;
      }
      f.definition = "time per item motor / matrix (< 1: motor faster)";
      if (!std::isfinite(f.value)) f.why = "no throughput for " + motor + " or " + matrix;
      figures::put(out, f);
    };
    for (const auto& [side, v] : p.items()) {
      if (!at(v, {"items_per_second"}).is_number() || ips(side) <= 0) continue;
      Figure f;
      f.kind = "measured";
      f.name = "kernel_time." + pair + "." + side;
      f.value = 1e9 / ips(side);
      f.unit = "ns";
      f.n = 1;
      f.statistic = "measured: Google Benchmark time per item (items/s inverted), " + repetitionsOf(p, {side});
      f.scope = "CPU kernel " + pair + ", implementation " + side;
      f.device = cpu + (at(v, {"label"}).is_string() ? ", Highway " + v["label"].get<std::string>() : "");
      f.disturbed = at(v, {"disturbance"});
      f.definition = "nanoseconds per item of " + side;
      figures::put(out, f);
    }
    add("kernel_time." + pair + ".fastest_motor_over_fastest_matrix", p.value("fastest_motor", "motor"),
        p.value("fastest_matrix", "matrix"), "fastest motor implementation vs fastest matrix implementation");
    add("kernel_time." + pair + ".shim_motor_over_shim_matrix", "motor", "matrix",
        "the shader sources through the GLSL shim on both sides");
  }
}

}  // namespace

// Curved space (the non-Euclidean scenes and the drift run): per scene the frame-time ratio
// motor / matrix and each pipeline's floats per instance; per space and side the drift.
void curvedFigures(json& out, const std::vector<json>& scenes, const json& drift, const std::string& device) {
  for (const json& s : scenes) {
    if (euclidean(s)) continue;
    const std::string id = s.value("id", "");
    const json& timing = s.value("timing", json());
    if (timing.is_object()) {
      figures::put(out, sceneFrameTimeFigure("curved.frame_time." + id + ".motor_over_matrix", timing, device));
      if (timing.contains("vertexBound"))
        figures::put(out, sceneFrameTimeFigure("curved.frame_time_vertex_bound." + id + ".motor_over_matrix", timing["vertexBound"], device));
    }
    const json pipelines = s.value("pipelines", json::object());
    for (const auto& [p, v] : pipelines.items()) {
      Figure f;
      f.kind = "measured";
      f.name = "curved.floats_per_instance." + id + "." + p;
      f.value = numberOrNaN(at(v, {"memory", "floatsPerTransform"}));
      f.unit = "floats";
      f.n = 1;
      f.statistic = "counted: instance-buffer floats uploaded per instance";
      f.scope = id;
      f.device = "buffers uploaded (PipelineStats)";
      f.definition = "PipelineStats.floatsPerTransform (instance bytes / instances / 4) of " + p;
      figures::put(out, f);
    }
  }
  for (const json& space : at(drift, {"spaces"}).is_array() ? drift["spaces"] : json::array())
    for (const char* side : {"matrix", "motor"})
      for (const char* kind : {"raw", "renormalised"}) {
        Figure f;
        f.kind = "measured";
        f.name = "curved.drift." + space.value("space", "") + "." + side + "." + kind;
        f.value = numberOrNaN(at(space, {side, kind}));
        f.unit = "";
        f.n = drift.value("steps", 0);
        f.statistic = "measured: error after every step, in float";
        f.scope = space.value("space", "") + " camera, " + drift.value("step", "");
        f.device = "CPU, float";
        f.definition = std::string(side) + (kind == std::string("raw") ? " without renormalisation" : " renormalised every step") +
                       ": distance of the accumulated transform from the exact one";
        figures::put(out, f);
      }
}

double opsTotal(const json& ops) {
  if (!ops.is_object()) return std::nan("");
  double t = 0;
  for (const char* k : {"mul", "add", "div", "sqrt", "other"}) t += numberOrNaN(ops.value(k, json(0)));
  return t;
}

std::string frameTimeDevice(const json& machine) {
  const json& gl = at(machine, {"gl"});
  const std::string renderer = gl.is_object() ? gl.value("renderer", "") : "";
  const bool software = gl.is_object() && !gl.value("realGpu", false);
  if (renderer.empty()) return "unknown device";
  return software ? "CPU rasterizer (" + renderer + "), wall clock" : renderer;
}

Figure sceneFrameTimeFigure(const std::string& name, const json& config, const std::string& device) {
  Figure f;
  f.kind = "measured";
  f.name = name;
  f.unit = "x";
  f.statistic = kPairedStatistic;
  f.scope = "whole frame" + (sizeOf(config).empty() ? std::string() : " at " + sizeOf(config));
  f.device = device;
  f.definition = "frame time motor / matrix (< 1: motor faster)";
  f.value = numberOrNaN(config.value("paired_ratio_motor_matrix", json()));
  f.disturbed = config.value("disturbance", json());  // harness/timing/disturbance.h (null: not assessed)
  const json& spread = config.value("paired_ratio_spread", json());
  if (spread.is_object() && spread.value("q1", json()).is_number()) {
    f.q1 = spread["q1"].get<double>(), f.q3 = spread["q3"].get<double>();
    f.n = spread.value("n", 0);
  } else {  // a report.json before the spread was recorded: the frames of the motor side
    f.n = at(config, {"pipelines", "motor", "frames"}).is_number() ? at(config, {"pipelines", "motor", "frames"}).get<int>() : 0;
  }
  if (!std::isfinite(f.value))
    f.why = config.contains("skipped") ? config["skipped"].get<std::string>() : "no paired frame ratio";
  return f;
}

// Per pipeline, the exact fallback it drew (PipelineStats; each scene's most in any frame drawn,
// summed over the Euclidean scenes): scenes, draws (rigid + skinned), joints and vertices.
void fallbackFigures(json& out, const std::vector<json>& scenes, const std::vector<std::string>& pipelines) {
  for (const std::string& p : pipelines) {
    double draws = 0, joints = 0, vertices = 0, taking = 0;
    int n = 0;
    for (const json& s : scenes) {
      const json& fb = at(s, {"pipelines", p.c_str(), "fallbacks"});
      if (!euclidean(s) || !fb.is_object()) continue;
      ++n;
      const double d = fb.value("linearFallbackDraws", 0.0) + fb.value("skinFallbackDraws", 0.0);
      draws += d, joints += fb.value("skinFallbackJoints", 0.0), vertices += fb.value("fallbackVertices", 0.0);
      taking += d > 0;
    }
    auto put = [&](const std::string& what, double value, const std::string& unit, const std::string& definition) {
      Figure f;
      f.kind = "measured";
      f.name = "fallback." + what + "." + p;
      f.value = value;
      f.unit = unit;
      f.statistic = "sum over scenes of each scene's most in any frame drawn";
      f.scope = "Euclidean scenes";
      f.device = "counted by the pipeline (PipelineStats)";
      f.n = n;
      f.definition = definition;
      figures::put(out, f);
    };
    put("scenes", taking, "scenes", "scenes in which " + p + " drew with its exact fallback (a transform that is not a similarity)");
    put("draws", draws, "draws", "draws " + p + " made with its exact fallback (rigid: a general linear part; skinned: per-joint linear parts)");
    put("joints", joints, "joints", "joints of the palettes " + p + "'s skin fallback draws used");
    put("vertices", vertices, "vertices", "vertices " + p + "'s exact fallback draws drew");
  }
}

// Per scene and pipeline, Pipeline::update's median time and its hierarchy phase, in
// microseconds (report_timing's updateMedianMs / updatePhasesMedianMs, wall clock).
void updateFigures(json& out, const std::vector<json>& scenes) {
  for (const json& s : scenes) {
    const json& timing = s.value("timing", json());
    const json& ps = at(timing, {"pipelines"});
    if (!ps.is_object()) continue;
    for (const auto& [p, v] : ps.items()) {
      auto put = [&](const std::string& name, const json& ms, const std::string& what) {
        Figure f;
        f.kind = "measured";
        f.name = name + "." + s.value("id", "") + "." + p;
        f.value = numberOrNaN(ms) * 1000.0;
        f.unit = "us";
        f.n = v.value("updateCallsPerBlock", 0);
        f.statistic = "measured: median over timed blocks of the mean time per call";
        f.scope = what + " of " + s.value("id", "") + " (" + std::to_string(at(v, {"drawnVertices"}).is_number()
                                                                           ? v["drawnVertices"].get<int>() : 0) +
                  " drawn vertices)";
        f.device = "CPU wall clock";
        f.definition = "microseconds per Pipeline::update call of " + p;
        f.disturbed = timing.value("disturbance", json());
        if (!std::isfinite(f.value)) f.why = "not timed";
        figures::put(out, f);
      };
      put("update", v.value("updateMedianMs", json()), "the whole CPU update (sampling, blending, hierarchy, palette)");
      put("update.hierarchy", at(v, {"updatePhasesMedianMs", "hierarchy"}), "the hierarchy phase (each node composed with its parent)");
    }
  }
}

json reportFigures(const json& machine, const json& settings, const std::vector<json>& scenes, const json& ops,
                   const json& kernels) {
  json out = json::object();
  const std::string device = frameTimeDevice(machine);
  frameTimeFigures(out, scenes, "", device);
  frameTimeFigures(out, scenes, "vertexBound", device);
  const std::vector<std::string> pipelines = settings.value("pipelines", std::vector<std::string>{});
  memoryFigure(out, scenes, pipelines, "bytesPerVertex", "bytes_per_vertex", "bytes",
               "shading attributes per vertex (position, frame, uv)");
  memoryFigure(out, scenes, pipelines, "floatsPerTransform", "floats_per_transform", "floats",
               "per-draw transform uniforms");
  memoryFigure(out, scenes, pipelines, "floatsPerTransformWithScale", "floats_per_transform_with_scale", "floats",
               "per-draw transform uniforms with the per-draw scale float");
  memoryFigure(out, scenes, pipelines, "floatsPerJoint", "floats_per_joint", "floats", "joint palette per joint");
  fallbackFigures(out, scenes, pipelines);
  updateFigures(out, scenes);
  opsFigures(out, ops);
  kernelFigures(out, kernels, machine.value("cpu", "") + " (" + std::to_string(machine.value("logicalCores", 0)) +
                                  " logical cores)");
  return out;
}

}  // namespace mb::document
