// The paper's verdicts against the strongest matrix variant measured. The paper
// compares with the glTF Sample Viewer's path (mat4 model + mat4 normal matrix, two mat4 per
// joint, 12-float vertices); production engines do better: `affine` (mat4x3 + mat3, one mat4x3
// per joint) and `qtangent` (the frame as an int16 quaternion, 28-byte vertices). Every figure
// is measured for every registered pipeline (uploads from renders, ops counted through the
// shim and from SPIR-V, times from the report or a timing run) and the paper's motor pipeline
// is judged against the best matrix-side value: "holds" (reproduced) when the motor is at
// least as good, "does not hold" (differs) otherwise, with the motor variants beside it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "harness/bench/report_bench.h"
#include "harness/claims/claims_device.h"
#include "harness/claims/claims_sources.h"
#include "harness/claims/claims_uploads.h"
#include "harness/claims/claims_vertex_ops.h"
#include "harness/claims/claims_work.h"
#include "harness/ops/ops_vertex.h"

namespace mb::claims {
namespace {

using json = nlohmann::json;

const char* kSection = "Against the strongest baseline";

// Which side of the comparison a pipeline's GPU data is on. The matrix side is every pipeline
// whose vertex shader transforms with matrices (hybrid too: its GPU side is qtangent's); the
// motor side is the paper's pipeline and its variants.
bool motorSide(const std::string& p) { return p.rfind("motor", 0) == 0; }

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

std::string pct(double a, double b) {  // a relative to b
  if (!(b > 0)) return "n/a";
  char s[32];
  std::snprintf(s, sizeof s, "%+.0f %%", 100.0 * (a / b - 1.0));
  return s;
}

// One figure for every pipeline, lower is better; judged as above.
struct Figure {
  std::string id, statement, unit, method;
  std::string paper;  // the paper's verdict (vs the Sample Viewer), as text
  std::map<std::string, double> values;
  std::string missing;  // why some or all values are absent
  bool excludeHybrid = false;  // a timed figure: hybrid's CPU side is motor work, not a matrix baseline
  double tolerance = 0;        // a timed figure: kTimeTolerance (counts and bytes are exact)
};

Claim judge(const Figure& f) {
  Claim c{f.id, kSection, f.statement};
  c.paper = f.paper;
  c.method = f.method;
  if (!f.values.count("motor") || !f.values.count("matrix")) {
    c.measured = "-";
    c.measuredValue = nullptr;
    c.verdict = Verdict::NotMeasurable;
    c.verdictText = "not measurable here: " + (f.missing.empty() ? "no value for matrix or motor" : f.missing);
    return c;
  }
  // Registry order breaks ties: a matrix pipeline before hybrid, motor before motor_q.
  std::string strongest, bestMotor;
  for (const std::string& p : pipelineNames()) {
    if (!f.values.count(p)) continue;
    const double v = f.values.at(p);
    if (motorSide(p)) {
      if (bestMotor.empty() || v < f.values.at(bestMotor)) bestMotor = p;
    } else if (!(f.excludeHybrid && p == "hybrid")) {
      if (strongest.empty() || v < f.values.at(strongest)) strongest = p;
    }
  }
  const double motor = f.values.at("motor"), matrix = f.values.at("matrix");
  const double best = f.values.at(strongest), bm = f.values.at(bestMotor);
  std::string all;
  for (const std::string& p : pipelineNames())
    if (f.values.count(p)) all += (all.empty() ? "" : ", ") + p + " " + num(f.values.at(p));
  c.measured = all + " " + f.unit + "; strongest matrix variant: " + strongest + " " + num(best);
  json values = json::object();
  for (const auto& [p, v] : f.values) values[p] = v;
  c.measuredValue = {{"values", values}, {"strongest", strongest}, {"bestMotor", bestMotor}};
  const std::string vsPaper = "vs the Sample Viewer's matrix: motor " + pct(motor, matrix);
  const std::string vsBest = "vs " + strongest + ": motor " + pct(motor, best) +
                             (bestMotor != "motor" ? ", " + bestMotor + " " + pct(bm, best) : "");
  const bool holds = motor <= best * (1.0 + f.tolerance);
  c.verdict = holds ? Verdict::Reproduced : Verdict::Differs;
  const std::string within =
      f.tolerance > 0 ? " (timed: as fast = within " + std::to_string(int(f.tolerance * 100 + 0.5)) + " % or faster)" : "";
  c.verdictText = std::string(holds ? "holds" : "does not hold") + " against the strongest baseline" + within + ": " +
                  vsBest + " (" + vsPaper + ")";
  if (!f.missing.empty()) c.verdictText += "; partly not measured: " + f.missing;
  return c;
}

// PipelineStats of every pipeline on a built-in scene (claims_uploads.h).
std::map<std::string, PipelineStats> statsOn(const Uploads& uploads, const std::string& sceneName, std::string& missing) {
  std::map<std::string, PipelineStats> out;
  for (const std::string& p : pipelineNames()) {
    auto f = uploads.of(sceneName, p);
    if (f) out[p] = *f;
    else missing += p + ": " + f.error() + "; ";
  }
  return out;
}

double opsTotal(const OpCounts& c) { return double(c.mul + c.add + c.div + c.sqrt + c.other); }
double opsTotal(const spirv::Counts& c) { return double(c.mul + c.add + c.div + c.sqrt + c.other); }

// The median over scenes of time(p) / time(reference) from report-style timing JSON
// ({scene: timing}); `path` selects the configuration ("" or "vertexBound") and `key` the time.
// Scenes below the minimum of work (claims_work.h) are left out and named in `skipped`.
std::map<std::string, double> timeRatios(const json& timings, const std::string& path, const std::string& key,
                                         const std::string& reference, int& scenes, const json& sceneStats,
                                         std::string& skipped) {
  std::map<std::string, std::vector<double>> per;
  scenes = 0;
  for (const auto& [scene, t] : timings.items()) {
    const json& cfg = path.empty() ? t : t.value(path, json());
    if (!cfg.is_object() || !cfg.contains("pipelines")) continue;
    const json& ps = cfg["pipelines"];
    if (!ps.contains(reference) || !ps[reference].value(key, json()).is_number()) continue;
    const double ref = ps[reference][key].get<double>();
    if (!(ref > 0)) continue;
    // The shortest timed block: a frame is one block; an update block is R calls (claims_work.h).
    const bool update = key == "updateMedianMs";
    auto block = [&](const json& v) { return update ? updateBlockMs(v[key].get<double>(), v) : v[key].get<double>(); };
    double least = block(ps[reference]);
    for (const auto& [p, v] : ps.items())
      if (v.value(key, json()).is_number()) least = std::min(least, block(v));
    const json stats = sceneStats.is_object() ? sceneStats.value(scene, json()) : json();
    if (const std::string why = belowMinimum(stats, least, update ? "update" : "frame"); !why.empty()) {
      skipped += (skipped.empty() ? "" : "; ") + scene + " (" + why + ")";
      continue;
    }
    ++scenes;
    // A frame time's ratio is the median of per-frame paired ratios where the timing recorded it
    // (report_timing's pairedRatioToMatrix: one statistic for every time ratio), else of the medians.
    for (const auto& [p, v] : ps.items()) {
      if (!v.value(key, json()).is_number()) continue;
      const json& paired = key == "medianMs" ? v.value("pairedRatioToMatrix", json()) : json();
      per[p].push_back(paired.is_object() && paired.value("median", json()).is_number() ? paired["median"].get<double>()
                                                                                       : v[key].get<double>() / ref);
    }
  }
  std::map<std::string, double> out;
  for (auto& [p, v] : per) {
    std::sort(v.begin(), v.end());
    out[p] = v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
  }
  return out;
}

// CPU kernel `kernel` (bench pairs in and out of cache): the fastest motor implementation's
// time per item against the fastest matrix implementation's (shim, GLM or SIMD).
Claim kernelClaim(const std::string& kernel, const json& pairs, const std::string& source) {
  Claim c{"cpu_" + kernel + "_vs_strongest", kSection,
          "CPU kernel " + kernel + ": time per vertex, fastest motor vs fastest matrix implementation"};
  c.paper = "as fast as matrices";
  c.method = "motorbench bench pairs " + kernel +
             " in and out of cache: items/s of every implementation (the shader source through the shim, "
             "GLM's operators, the Highway SIMD kernels of kernels/simd), each kind's fastest taken; holds when the "
             "fastest motor is at least as fast in both working sets; source: " +
             (source.empty() ? std::string("none") : source);
  json values = json::object();
  std::string text;
  bool holds = true;
  int sizes = 0;
  std::string disturbed;  // sizes whose pair was disturbed
  std::string machine;    // the CPU and SIMD target the pairs ran on
  if (pairs.is_array())
    for (const json& p : pairs) {
      if (p.value("kernel", "") != kernel || !p["ratio_motor_fastest_matrix"].is_number()) continue;
      machine = report::pairMachineText(p);
      const std::string size = p["size"].is_string() ? p["size"].get<std::string>() : "-";
      if (p.value("disturbed", false)) {  // taken on shared cores: not a verdict input
        disturbed += (disturbed.empty() ? "" : ", ") + size;
        continue;
      }
      const std::string fm = p["fastest_matrix"].get<std::string>(), fmo = p["fastest_motor"].get<std::string>();
      const double ratio = p["ratio_motor_fastest_matrix"].get<double>();  // > 1: motor faster
      values[size] = {{"fastestMatrix", fm}, {"fastestMotor", fmo}, {"ratioItemsPerSecond", ratio}};
      text += (text.empty() ? "" : "; ") + size + ": " + fmo + " " + num(p[fmo].value("items_per_second", 0.0)) +
              " vs " + fm + " " + num(p[fm].value("items_per_second", 0.0)) + " items/s (motor time " +
              pct(1.0 / ratio, 1.0) + ")";
      holds = holds && ratio >= 1.0;
      ++sizes;
    }
  if (!text.empty()) text += "; on " + machine;
  if (!sizes || !disturbed.empty()) {  // a verdict needs both working sets, undisturbed
    c.measured = text.empty() ? "-" : text;
    c.measuredValue = nullptr;
    c.verdict = Verdict::NotMeasurable;
    c.verdictText = disturbed.empty()
                        ? "not measurable here: no " + kernel + " bench pair with a motor and a matrix implementation"
                        : "not measurable here: the " + kernel + " bench pairs (" + disturbed +
                              ") were timed while other work shared the cores (disturbed)";
    return c;
  }
  c.measured = text;
  c.measuredValue = values;
  c.verdict = holds ? Verdict::Reproduced : Verdict::Differs;
  c.verdictText = std::string(holds ? "holds" : "does not hold") +
                  " against the fastest matrix implementation measured (" + text + ")";
  return c;
}

// ---- memory, from the uploads -----------------------------------------------------------
// Bytes per vertex and floats per transform on normal_torus, floats per joint on skinned_tube,
// every pipeline, each judged.
void memoryFigures(const Uploads& uploads, std::vector<Claim>& out) {
  std::string rigidMissing, skinMissing;
  const auto rigid = statsOn(uploads, "normal_torus", rigidMissing);
  const auto skinned = statsOn(uploads, "skinned_tube", skinMissing);
  auto trim = [](std::string s) { return s.size() >= 2 ? s.substr(0, s.size() - 2) : s; };
  Figure bpv{"bytes_per_vertex_vs_strongest", "bytes per vertex (normal-mapped: position, frame, uv)",
             "bytes/vertex",
             "PipelineStats.vertexBytes / vertices (the shading attributes uploaded) of every pipeline on the "
             "built-in normal_torus (normal-mapped, so every pipeline uploads a full frame); uploads: " + uploads.source(),
             "motor 36 vs matrix 48 bytes (-25 %)"};
  Figure fpt{"floats_per_transform_vs_strongest", "floats per transform (per-draw uniforms)", "floats",
             "PipelineStats.floatsPerTransform of every pipeline on normal_torus (model + normal matrix, or motor)",
             "motor 8 vs matrix 32 floats (-75 %)"};
  Figure fpj{"floats_per_joint_vs_strongest", "floats per skin joint (palette uploaded per frame)", "floats",
             "PipelineStats.floatsPerJoint of every pipeline on the built-in skinned_tube",
             "(not claimed; Sample Viewer: 2 mat4 = 32 per joint, motor 8)"};
  for (const auto& [p, s] : rigid) {
    if (s.vertices) bpv.values[p] = double(s.vertexBytes) / double(s.vertices);
    fpt.values[p] = s.floatsPerTransform;
  }
  for (const auto& [p, s] : skinned) fpj.values[p] = s.floatsPerJoint;
  bpv.missing = fpt.missing = trim(rigidMissing);
  fpj.missing = trim(skinMissing);
  out.push_back(judge(bpv));
  out.push_back(judge(fpt));
  out.push_back(judge(fpj));
}

// ---- ops per vertex, counted and SPIR-V --------------------------------------------------
// The op-count row of pipeline p's variant `label` (nullptr when none).
const opsv::VariantRow* variantRow(const opsv::VertexOps& ops, const std::string& p, const std::string& label) {
  for (const auto& v : ops.variants)
    if (v.variant.pipeline == p && v.variant.label == label) return &v;
  return nullptr;
}

// The op-count row of the kernel function `fn` (nullptr when none).
const opsv::KernelRow* kernelRow(const opsv::VertexOps& ops, const std::string& fn) {
  for (const auto& k : ops.kernels)
    if (k.kernel.function == fn) return &k;
  return nullptr;
}

struct OpsFigure { const char* id; const char* label; bool withClip; const char* statement; const char* paper; };
const OpsFigure kOpsFigures[] = {
    {"ops_rigid_vs_strongest", "rigid", false, "ops per rigid vertex with frame (transform only)",
     "motor 47/38 vs matrix 48/36 mul/add: as cheap"},
    {"ops_skinned_vs_strongest", "skinned", false, "ops per skinned vertex (4 joints, transform only)",
     "(not claimed)"},
    {"ops_clip_vs_strongest", "rigid", true, "ops per rigid vertex with frame, object to clip",
     "(not claimed)"},
};

// One ops figure, counted or SPIR-V: every pipeline's total ops per vertex (a pipeline with 0,
// its kernels not joined, left out and named).
Figure opsFigure(const opsv::VertexOps& ops, const OpsFigure& of, bool spirvSide) {
  Figure f{std::string(of.id) + (spirvSide ? "_spirv" : ""), std::string(of.statement) + (spirvSide ? ", SPIR-V" : ", counted"),
           "ops (mul + add + div + sqrt + other)", "", of.paper};
  f.method = spirvSide
                 ? "the optimised SPIR-V (glslangValidator + spirv-opt -O) of the functions the pipeline's vertex "
                   "shader calls, vector ops expanded to scalar ops" +
                       std::string(of.withClip ? " (transform + world to clip)" : " (the transform function)")
                 : "the functions the pipeline's vertex shader calls, executed on mb::Counted" +
                       std::string(of.withClip ? " (transform + world to clip)" : " (the transform function)");
  std::string zero, unused;
  // Counted, object to clip: each variant's kernels counted by function name (the join of
  // claims_vertex_ops.h), the same numbers as the speed row.
  const std::map<std::string, double> countedClip =
      of.withClip && !spirvSide ? opsPerPipeline(of.label, false, unused) : std::map<std::string, double>{};
  for (const std::string& p : pipelineNames()) {
    const opsv::VariantRow* v = variantRow(ops, p, of.label);
    if (!v || v->variant.kernels.empty()) continue;
    double total = -1;
    if (of.withClip) {
      if (!spirvSide) total = countedClip.count(p) ? countedClip.at(p) : 0.0;
      else if (v->probes) total = opsTotal(*v->probes);
    } else if (const opsv::KernelRow* k = kernelRow(ops, v->variant.kernels.front())) {
      if (!spirvSide) total = opsTotal(k->counted);
      else if (k->optimised) total = opsTotal(*k->optimised);
    }
    // No vertex shader transforms for free: 0 means the pipeline's kernels were not joined
    // (harness/ops), never a strongest baseline.
    if (total > 0) f.values[p] = total;
    else if (total == 0) zero += (zero.empty() ? "" : ", ") + p;
  }
  if (!zero.empty()) f.missing = "0 ops counted for " + zero + " (its kernels are not joined; left out)";
  if (spirvSide && !ops.toolsProblem.empty()) f.missing += (f.missing.empty() ? "" : "; ") + ops.toolsProblem;
  return f;
}

// The matrix pipeline skins as the Sample Viewer does (palette relative to the mesh node), the
// motor pipeline with a world palette: the skinned verdict adds the same configuration on both
// sides as well, where all four kernels were counted.
void addMatchedSkinning(const opsv::VertexOps& ops, bool spirvSide, Claim& judged) {
  auto total = [&](const char* fn) -> double {
    const opsv::KernelRow* k = kernelRow(ops, fn);
    if (!k) return 0;
    return spirvSide ? (k->optimised ? opsTotal(*k->optimised) : 0) : opsTotal(k->counted);
  };
  const double refM = total("matrixSkinnedVertex"), refQ = total("motorSkinnedVertexReference");
  const double worldM = total("matrixSkinnedVertexWorld"), worldQ = total("motorSkinnedVertex");
  if (refM > 0 && refQ > 0 && worldM > 0 && worldQ > 0)
    judged.verdictText += "; matched configurations, motor vs matrix: palette relative to the mesh node " +
                          num(refQ) + " vs " + num(refM) + " (" + pct(refQ, refM) + "), world palette " +
                          num(worldQ) + " vs " + num(worldM) + " (" + pct(worldQ, worldM) + ")";
}

// Every ops figure, counted then SPIR-V, judged; returns the counted ops per rigid vertex,
// object to clip, of every pipeline (the frame-time rows' check).
std::map<std::string, double> opsFigures(std::vector<Claim>& out) {
  const opsv::VertexOps& ops = vertexOps();
  std::map<std::string, double> clipOps;  // counted ops per rigid vertex, object to clip (the timing check)
  for (const OpsFigure& of : kOpsFigures)
    for (const bool spirvSide : {false, true}) {
      const Figure f = opsFigure(ops, of, spirvSide);
      if (of.withClip && !spirvSide) clipOps = f.values;
      Claim judged = judge(f);
      if (std::string(of.label) == "skinned" && judged.verdict != Verdict::NotMeasurable)
        addMatchedSkinning(ops, spirvSide, judged);
      out.push_back(judged);
    }
  return clipOps;
}

// ---- time: frame time per scene, vertex-bound, CPU update -------------------------------
struct TimeFigure { const char* id; const char* path; const char* key; const char* statement; bool cpu; };
const TimeFigure kTimeFigures[] = {
    {"frame_time_vs_strongest", "", "medianMs", "frame time (median over scenes of time / matrix's time)", false},
    {"frame_time_vertex_bound_vs_strongest", "vertexBound", "medianMs",
     "frame time, vertex-bound viewport (median over scenes of time / matrix's time)", false},
    {"cpu_update_vs_strongest", "", "updateMedianMs",
     "CPU update: hierarchy, animation, skin palette, and the matrix forms' node normal matrices (median over "
     "scenes of time / matrix's time)", true},
};

// One time figure judged: each pipeline's median ratio to matrix over the scenes with the
// minimum of work (hybrid listed, not taken as the baseline), within kTimeTolerance; a frame
// time on a CPU rasterizer that times pipelines of different op counts alike is inconclusive.
Claim timeClaim(const TimeFigure& tf, const nlohmann::json& timings, const std::string& timingSource,
                const nlohmann::json& sceneStats, const TimingDevice& device,
                const std::map<std::string, double>& clipOps) {
  int scenes = 0;
  std::string skipped;
  Figure f{tf.id, tf.statement, "x matrix", "", "as fast as matrices"};
  f.values = timings.is_object() ? timeRatios(timings, tf.path, tf.key, "matrix", scenes, sceneStats, skipped)
                                 : std::map<std::string, double>{};
  f.excludeHybrid = true;  // its CPU side is the motor pipeline's
  f.tolerance = kTimeTolerance;
  f.method = std::string("median over ") + std::to_string(scenes) + " scenes of each pipeline's median " + tf.key +
             " / matrix's (" + (tf.cpu ? std::string("ratio of medians; CPU wall clock")
                                        : "the median of per-frame paired ratios where recorded, else the ratio of "
                                          "medians; " + device.label()) + "); " + minimumRule() +
             (skipped.empty() ? "" : " (not counted: " + skipped + ")") + "; source: " + timingSource +
             "; hybrid is listed but not taken as the matrix baseline" +
             (tf.cpu ? std::string(": its update is the motor work plus the conversion to mat4x3")
                     : std::string(": it draws exactly as qtangent (frame time: clear + draws + glFinish)"));
  if (f.values.empty())
    f.missing = timings.is_object() && !skipped.empty() ? "no scene with the minimum of work (" + skipped + ")"
                                                         : "no timing (give --report with timing, or drop --no-run)";
  Claim c = judge(f);
  if (!tf.cpu && c.verdict != Verdict::NotMeasurable) {
    c.verdictText += "; device: " + device.label();
    // A CPU rasterizer's frame time cannot tell pipelines apart whose arithmetic differs by
    // more than 25 % when it times them within the noise: any two timed pipelines
    // (not only motor and the strongest) that show it make every ratio of this timing moot.
    if (device.cpuRasterizer)
      if (const auto alike = timedAlike(f.values, clipOps)) {
        c.verdict = Verdict::Inconclusive;
        c.verdictText = "unable to discriminate on a CPU rasterizer: " + alike->dearer + " and " + alike->cheaper +
                        " differ by " + pct(alike->opsRatio, 1.0) + " in counted ops per vertex but take the same "
                        "time within " + std::to_string(int(kTimeTolerance * 100)) + " % (" +
                        pct(alike->timeRatio, 1.0) + "); device: " + device.label();
      }
  }
  return c;
}

}  // namespace

std::vector<Claim> strongestBaselineClaims(const nlohmann::json& timings, const std::string& timingSource,
                                           const nlohmann::json& kernelPairs, const std::string& kernelSource,
                                           const nlohmann::json& sceneStats, const nlohmann::json& timingMachine,
                                           const Uploads& uploads) {
  std::vector<Claim> out;
  for (const char* k : {"vertex_frame", "skinned_vertex"}) out.push_back(kernelClaim(k, kernelPairs, kernelSource));
  memoryFigures(uploads, out);
  const std::map<std::string, double> clipOps = opsFigures(out);
  const TimingDevice device = timingDevice(timingMachine);
  for (const TimeFigure& tf : kTimeFigures)
    out.push_back(timeClaim(tf, timings, timingSource, sceneStats, device, clipOps));
  return out;
}

}  // namespace mb::claims
