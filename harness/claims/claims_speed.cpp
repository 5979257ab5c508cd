// "PGA motors can be just as fast as 4x4 matrices to transform your mesh vertices":
// judged on what the paper's sentence claims, a rigid vertex with its full tangent frame
// to world space, the paper's motor against the paper's 4x4 baseline (the Sample Viewer's matrix
// pipeline). The skinned vertex is its own row (ours: the sentence does not claim it); the
// strongest matrix forms are the "vs strongest" rows. Kinds of evidence, each a cost ratio motor /
// matrix (< 1: motor cheaper): ops per vertex counted and SPIR-V (probe) of the transform
// function, AMD ISA instructions and occupancy (waves per SIMD; VGPRs only through it) of the
// whole vertex shader, the CPU kernel (fastest implementation of each side), frame time in a
// vertex-bound viewport (the median of per-frame paired ratios).
#include <algorithm>
#include <cmath>
#include <map>

#include "harness/bench/fastest_sides.h"
#include "harness/bench/report_bench.h"
#include "harness/claims/claims_device.h"
#include "harness/claims/claims_ranking.h"
#include "harness/claims/claims_sources.h"
#include "harness/claims/claims_vertex_ops.h"
#include "harness/claims/claims_work.h"
#include "harness/document/ops_ranking.h"
#include "harness/ops/pipeline_ops.h"
#include "harness/timing/frame_timing.h"

namespace mb::claims {
namespace {

using json = nlohmann::json;

std::string pct(double r) { return fmt("%+.0f %%", 100.0 * (r - 1.0)); }
std::string x2(double r) { return fmt("%.2fx", r); }

// The paper's sentence (section "Tangent frames"), quoted by the row it decides.
const char* kSentence =
    "\"in order to transform a vertex with full tangent frame to world space, our PGA approach needs only "
    "(16 + 9 + 21 + 1 = 47) multiplications and (12 + 8 + 18 = 38) additions. That is nearly identical to the 48 "
    "multiplications and 36 additions that would be required if we use 4x4 matrices [...] PGA motors can be just as "
    "fast as 4x4 matrices to transform your mesh vertices\"";

// One kind of evidence: motor cost / matrix cost.
struct Evidence {
  std::string kind, detail;
  double costRatio = -1;  // < 0: not measured
  std::string why;        // not usable: why (missing, cannot discriminate, disturbed)
  bool usable() const { return costRatio >= 0 && why.empty(); }
};

struct Scope {
  const char* label;    // pipeline_ops figure and shader variant: "rigid" | "skinned"
  const char* what;     // "rigid vertex with frame" ...
  const char* kernel;   // the CPU bench kernel
  const char* scene;    // the vertex-bound scene
};

Evidence opsEvidence(const Scope& s, bool spirv) {
  Evidence e{std::string("ops per vertex, ") + s.what + " (transform only), " + (spirv ? "SPIR-V (probe)" : "counted")};
  double motor = -1, matrix = -1;
  for (const opsv::PipelineOps& row : opsv::pipelineOps(vertexOps())) {
    const opsv::OpsFigure& f = std::string(s.label) == "rigid" ? row.rigid : row.skinned;
    if (!f.present || (row.pipeline != "motor" && row.pipeline != "matrix")) continue;
    const double v = spirv ? (f.spirv ? double(opsv::total(*f.spirv)) : -1) : double(opsv::total(f.counted));
    (row.pipeline == "motor" ? motor : matrix) = v;
  }
  if (motor > 0 && matrix > 0) {
    e.costRatio = motor / matrix;
    e.detail = "motor " + fmt("%.0f", motor) + " / matrix " + fmt("%.0f", matrix) + " ops";
  } else {
    e.why = spirv && !vertexOps().toolsProblem.empty() ? vertexOps().toolsProblem : "no count for motor or matrix";
  }
  return e;
}

// ISA of the whole vertex shader `program` (its normal-mapped form when present) per family and
// NGG mode, motor against matrix; the worst family is the evidence. `occupancy`: waves per SIMD
// (cost = matrix waves / motor waves), else instructions.
Evidence isaEvidence(const json& isa, const Scope& s, bool occupancy) {
  Evidence e{std::string("AMD ISA ") + (occupancy ? "occupancy (waves per SIMD)" : "instructions") + ", whole " +
             s.label + " vertex shader"};
  if (!isa.is_object() || !isa.value("shaders", json()).is_array()) {
    e.why = "no ISA statistics";
    return e;
  }
  const IsaTable table = isaVertexTable(isa, s.label);
  std::vector<double> ratios;
  for (const auto& [family, byPipeline] : table) {
    if (!byPipeline.count("motor") || !byPipeline.count("matrix")) continue;
    const IsaStats& m = byPipeline.at("motor");
    const IsaStats& x = byPipeline.at("matrix");
    const double r = occupancy ? (m.waves > 0 ? x.waves / m.waves : -1) : m.instructions / x.instructions;
    if (r <= 0) continue;
    ratios.push_back(r);
    e.detail += (e.detail.empty() ? "" : "; ") + family + " " + x2(r) +
                (occupancy ? " (waves " + fmt("%.0f", m.waves) + " vs " + fmt("%.0f", x.waves) + ", VGPRs " +
                                 fmt("%.0f", m.vgprs) + " vs " + fmt("%.0f", x.vgprs) + ")"
                           : " (" + fmt("%.0f", m.instructions) + " vs " + fmt("%.0f", x.instructions) + ")");
  }
  if (ratios.empty()) {
    e.why = std::string("no ") + s.label + " vertex shader of motor and matrix in the ISA statistics";
    return e;
  }
  e.costRatio = *std::max_element(ratios.begin(), ratios.end());
  e.detail = "worst of " + std::to_string(ratios.size()) + " families: " + e.detail;
  return e;
}

// The CPU kernel: the fastest motor implementation against the fastest matrix implementation
// measured (every matrix side of these kernels is a 4x4 form), the worse of in and out of cache.
Evidence cpuEvidence(const SpeedInputs& in, const Scope& s) {
  Evidence e{std::string("CPU kernel ") + s.kernel + ", fastest motor vs fastest 4x4 matrix implementation"};
  std::vector<double> ratios;
  std::string machine;  // the CPU and SIMD target the pairs ran on
  if (in.kernelPairs.is_array())
    for (const json& p : in.kernelPairs) {
      if (p.value("kernel", "") != s.kernel) continue;
      machine = report::pairMachineText(p);
      const bench::FastestSides f = bench::fastestSides(p);
      const std::string size = p["size"].is_string() ? p["size"].get<std::string>() : std::string("?");
      if (!f.disturbed.empty()) {
        e.why = size + " disturbed: " + f.disturbed.dump();
        continue;
      }
      if (f.costRatio() < 0) continue;
      ratios.push_back(f.costRatio());
      e.detail += (e.detail.empty() ? "" : "; ") + size + ": " + f.motorSide + " / " + f.matrixSide + " time " + x2(f.costRatio());
    }
  if (!ratios.empty()) e.costRatio = *std::max_element(ratios.begin(), ratios.end());
  else if (e.why.empty()) e.why = std::string("no ") + s.kernel + " bench pair";
  if (!machine.empty()) e.detail += (e.detail.empty() ? "on " : "; on ") + machine;
  return e;
}

// Frame time in the vertex-bound viewport: the median of per-frame paired ratios motor / matrix;
// not usable below the minimum of work or where a CPU rasterizer times unequal arithmetic alike.
Evidence frameEvidence(const SpeedInputs& in, const Scope& s, const TimingDevice& device) {
  Evidence e{std::string("frame time, vertex-bound ") + s.scene + " (median of per-frame paired ratios)"};
  const json timing = in.timings.is_object() ? in.timings.value(s.scene, json()) : json();
  const json vb = timing.is_object() ? timing.value("vertexBound", json()) : json();
  if (!vb.is_object() || !vb.value("paired_ratio_motor_matrix", json()).is_number()) {
    e.why = std::string("no vertex-bound timing of ") + s.scene;
    return e;
  }
  e.costRatio = vb["paired_ratio_motor_matrix"].get<double>();
  e.detail = std::string(s.scene) + " at " + std::to_string(vb.value("width", 0)) + "x" + std::to_string(vb.value("height", 0)) +
             ", " + device.label();
  if (vb.value("paired_ratio_spread", json()).is_object())
    e.detail += ", IQR " + fmt("%.3g", vb["paired_ratio_spread"].value("q1", 0.0)) + ".." +
                fmt("%.3g", vb["paired_ratio_spread"].value("q3", 0.0));
  // A skinned scene timed with each pipeline's default skinning configuration (an older
  // report.json) compares two configurations, not two representations: not usable.
  if (in.frameTimes.is_array())
    for (const json& f : in.frameTimes)
      if (f.value("scene", "") == s.scene && f.value("skinSpace", "-").find("defaults") != std::string::npos) {
        e.detail += "; skinning: " + f["skinSpace"].get<std::string>();
        e.why = "asymmetric: the pipelines' default skinning configurations differ";
      }
  std::map<std::string, double> times;
  const json pipelines = vb.value("pipelines", json::object());  // named: items() of a temporary dangles
  for (const auto& [p, v] : pipelines.items())
    if (p != "hybrid" && v.is_object() && v.value("medianMs", json()).is_number() && v["medianMs"].get<double>() > 0)
      times[p] = v["medianMs"];
  double least = 1e300;
  for (const auto& [p, t] : times) least = std::min(least, t);
  const json stats = in.sceneStats.is_object() ? in.sceneStats.value(s.scene, json()) : json();
  if (!times.empty())
    if (const std::string why = belowMinimum(stats, least, "frame"); !why.empty()) e.why = "below the minimum of work: " + why;
  std::string zero;
  if (device.cpuRasterizer && e.why.empty())
    if (const auto alike = timedAlike(times, opsPerPipeline(s.label, false, zero)))
      e.why = "unable to discriminate on a CPU rasterizer (" + alike->dearer + " and " + alike->cheaper + ": counted ops " +
              pct(alike->opsRatio) + ", time " + pct(alike->timeRatio) + ")";
  return e;
}

std::string ruleText() {
  return "a kind agrees when the motor costs at most " + fmt("%.0f", kTimeTolerance * 100) +
         " % more than the matrix (cost ratio <= " + fmt("%.2f", 1 + kTimeTolerance) +
         "); reproduced when every usable kind agrees, differs when every usable kind disagrees, inconclusive when "
         "they split; kinds not measured or not usable (below the minimum of work, a device that cannot discriminate, "
         "disturbed) are listed and not counted";
}

Claim judgeKinds(Claim c, const std::vector<Evidence>& ev, const std::string& ranking) {
  json kinds = json::object();
  std::string text, agree, disagree, unusable;
  for (const Evidence& e : ev) {
    kinds[e.kind] = {{"costRatio", e.costRatio >= 0 ? json(e.costRatio) : json()}, {"usable", e.usable()},
                     {"detail", e.detail}};
    if (!e.why.empty()) kinds[e.kind]["caveat"] = e.why;
    text += (text.empty() ? "" : "; ") + e.kind + " " + (e.costRatio >= 0 ? x2(e.costRatio) : std::string("-")) +
            (e.detail.empty() ? "" : " (" + e.detail + ")");
    if (!e.usable()) unusable += (unusable.empty() ? "" : "; ") + e.kind + ": " + (e.why.empty() ? "not measured" : e.why);
    else if (e.costRatio <= 1.0 + kTimeTolerance) agree += (agree.empty() ? "" : ", ") + e.kind + " " + x2(e.costRatio);
    else disagree += (disagree.empty() ? "" : ", ") + e.kind + " (motor " + pct(e.costRatio) + ")";
  }
  c.measuredValue = {{"kinds", kinds}, {"tolerance", kTimeTolerance}, {"rule", ruleText()}};
  c.method += " Rule: " + ruleText() + ".";
  if (agree.empty() && disagree.empty()) {
    c.measured = "-";
    c.verdict = Verdict::NotMeasurable;
    c.verdictText = "not measurable here: " + unusable;
    return c;
  }
  c.measured = text + " (cost ratio motor / matrix, < 1: motor cheaper)";
  if (disagree.empty()) c.verdict = Verdict::Reproduced, c.verdictText = "reproduced: every usable kind agrees: " + agree;
  else if (agree.empty()) c.verdict = Verdict::Differs, c.verdictText = "differs: every usable kind disagrees: " + disagree;
  else
    c.verdict = Verdict::Inconclusive,
    c.verdictText = "inconclusive: the usable kinds split; agree: " + agree + "; disagree: " + disagree;
  if (!unusable.empty()) c.verdictText += "; not counted: " + unusable;
  if (!ranking.empty()) c.verdictText += "; " + ranking;
  return c;
}

Claim scopeClaim(const SpeedInputs& in, const Scope& s, Claim c) {
  const TimingDevice device = timingDevice(in.timingMachine);
  std::vector<Evidence> ev = {opsEvidence(s, false)};
  if (in.spirv) ev.push_back(opsEvidence(s, true));
  ev.push_back(isaEvidence(in.isa, s, false));
  ev.push_back(isaEvidence(in.isa, s, true));
  ev.push_back(cpuEvidence(in, s));
  ev.push_back(frameEvidence(in, s, device));
  c.method = std::string("the paper's motor pipeline against its 4x4 baseline (the Sample Viewer's matrix pipeline), ") + s.what +
             ": ops of the transform function counted on mb::Counted and in its SPIR-V probe (the function compiled alone); "
             "AMD ISA of the whole vertex shader per family (motorbench isa, source " +
             (in.isaSource.empty() ? std::string("none") : in.isaSource) +
             "; the worst family; occupancy is the register cost that decides throughput, VGPRs quoted beside it); the CPU "
             "kernel " + s.kernel + " of motorbench bench (source " + (in.kernelSource.empty() ? std::string("none") : in.kernelSource) +
             "; the fastest implementation of each side, the worse of in and out of cache); frame time of " + s.scene +
             " in its vertex-bound viewport on " + device.label() + " (" + minimumRule() + ").";
  const std::string ranking = disagreementLine(in.opsRanking.value(s.label, json()));
  return judgeKinds(c, ev, ranking.empty() ? "" : ranking + " (ops_ranking_" + s.label + ")");
}

}  // namespace

std::vector<Claim> speedClaims(const SpeedInputs& given) {
  SpeedInputs in = given;
  if (!in.opsRanking.is_object()) {  // the report's ranking function on this process's op counts
    in.opsRanking = report::opsRanking(opsv::toJson(vertexOps())["variants"], in.isa);
    in.opsRankingSource = "claims' own op counts and " + (in.isaSource.empty() ? std::string("no ISA statistics") : in.isaSource) +
                          " (no report.json \"opsRanking\")";
  }
  Claim rigid{"as_fast_as_matrices", "Speed",
              "motors transform a vertex with full tangent frame to world space as fast as 4x4 matrices"};
  rigid.paper = std::string("as fast (47/38 vs 48/36 mul/add per vertex): ") + kSentence;
  rigid.paperValue = {{"ratio", 1.0}, {"quote", kSentence}};
  Claim skinned{"as_fast_as_matrices_skinned", "Speed",
                "(not claimed by the paper's sentence) motors transform a skinned vertex (4 joints) as fast as 4x4 matrices"};
  skinned.paper = "(not claimed: the sentence is about the rigid vertex)";
  skinned.origin = "beyond the paper";
  std::vector<Claim> out = {scopeClaim(in, {"rigid", "rigid vertex with frame", "vertex_frame", "dense_torus"}, rigid),
                            scopeClaim(in, {"skinned", "skinned vertex (4 joints)", "skinned_vertex", "crowd"}, skinned)};
  if (!in.missing.empty())
    for (Claim& c : out) c.verdictText += "; partly not measured: " + in.missing;
  for (const char* label : {"rigid", "skinned"})
    out.push_back(rankingClaim(in.opsRanking.value(label, json()), label, in.opsRankingSource));
  return out;
}

}  // namespace mb::claims
