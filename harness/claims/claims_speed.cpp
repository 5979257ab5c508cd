// "PGA motors can be just as fast as 4x4 matrices to transform your mesh vertices", judged on
// every kind of evidence (issue 18): ops per vertex (rigid, and skinned with both pipelines in
// the same configuration), the CPU vertex_frame and skinned_vertex kernels, the fastest motor
// against the fastest matrix implementation measured (shim, GLM or SIMD; issue 13), and llvmpipe frame time in vertex-bound scenes, one rigid
// normal-mapped (dense_torus) and one skinned (crowd). "reproduced" only when every kind agrees
// within 10 %; "differs" when none does; otherwise "inconclusive", naming what disagrees.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "harness/bench/fastest_sides.h"
#include "harness/claims/claims_sources.h"
#include "harness/ops/ops_vertex.h"
#include "harness/timing/frame_timing.h"

namespace mb::claims {
namespace {

using json = nlohmann::json;

constexpr double kTolerance = kTimeTolerance;

std::string pct(double r) {
  char b[32];
  std::snprintf(b, sizeof b, "%+.0f %%", 100.0 * (r - 1.0));
  return b;
}

std::string x2(double r) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2fx", r);
  return b;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// One kind of evidence: motor cost / matrix cost (time or ops; < 1: motor cheaper).
struct Evidence {
  std::string kind, detail;
  double costRatio = -1;  // < 0: not measured
  std::string why;        // not measured: why; or a caveat
};

OpCounts countedFunction(const std::string& fn) {
  for (const opsv::VertexKernel& k : opsv::vertexKernels())
    if (k.function == fn) return opsv::countVertexKernel(k);
  return {};
}

double opsRatio(const OpCounts& motor, const OpCounts& matrix) {
  const double a = double(motor.mul + motor.add + motor.div + motor.sqrt + motor.other);
  const double b = double(matrix.mul + matrix.add + matrix.div + matrix.sqrt + matrix.other);
  return b > 0 ? a / b : -1;
}

}  // namespace

std::vector<Claim> speedClaims(const SpeedInputs& in) {
  Claim c{"as_fast_as_matrices", "Speed",
          "motors transform mesh vertices (with tangent frame) as fast as 4x4 matrices"};
  c.paper = "as fast (47/38 vs 48/36 ops per vertex)";
  c.paperValue = {{"ratio", 1.0}};
  std::vector<Evidence> ev;

  // Ops per vertex, counted (every op weighs 1: mul, add, div, sqrt, other call).
  ev.push_back({"ops per vertex, rigid with frame", "motorRigidVertex / matrixRigidVertex (counted)",
                opsRatio(countedFunction("motorRigidVertex"), countedFunction("matrixRigidVertex")), ""});
  ev.push_back({"ops per vertex, skinned (both as the references do)",
                "motorSkinnedVertexReference / matrixSkinnedVertex (counted)",
                opsRatio(countedFunction("motorSkinnedVertexReference"), countedFunction("matrixSkinnedVertex")), ""});
  ev.push_back({"ops per vertex, skinned (both with a world-space palette)",
                "motorSkinnedVertex / matrixSkinnedVertexWorld (counted)",
                opsRatio(countedFunction("motorSkinnedVertex"), countedFunction("matrixSkinnedVertexWorld")), ""});

  // CPU kernels: the fastest motor implementation against the fastest matrix implementation
  // measured (shim, GLM or SIMD; report_bench's fastest_* fields), for the rigid vertex with
  // frame and the skinned vertex, in and out of cache; the shim motor is named beside it.
  for (const char* kernel : {"vertex_frame", "skinned_vertex"}) {
    std::vector<double> worst;
    std::string detail;
    if (in.kernelPairs.is_array())
      for (const json& p : in.kernelPairs) {
        if (p.value("kernel", "") != kernel) continue;
        const bench::FastestSides f = bench::fastestSides(p);
        if (f.costRatio() < 0) continue;
        const double shimMotor = p.contains("motor") ? p["motor"].value("items_per_second", 0.0) : 0.0;
        worst.push_back(f.costRatio());
        detail += (detail.empty() ? "" : "; ") + (p["size"].is_string() ? p["size"].get<std::string>() : std::string("?")) +
                  ": fastest motor " + f.motorSide + " / fastest matrix " + f.matrixSide + " time " + x2(f.costRatio()) +
                  (shimMotor > 0 && f.motorSide != "motor" ? " (the shim motor: time " + x2(f.matrix / shimMotor) + " of the fastest matrix)" : "");
      }
    Evidence e{std::string("CPU kernel ") + kernel + " vs the fastest matrix code measured", detail, -1, ""};
    if (!worst.empty()) e.costRatio = *std::max_element(worst.begin(), worst.end());
    else e.why = std::string("no ") + kernel + " bench pair";
    ev.push_back(e);
  }

  // Frame time, vertex-bound, per scene kind.
  auto frameEvidence = [&](const std::string& kind, const std::string& scene) {
    Evidence e{kind, scene + " at 64x64 (paired per-frame ratio)", -1, ""};
    if (in.frameTimes.is_array())
      for (const json& f : in.frameTimes)
        if (f.value("scene", "") == scene) {
          if (f.contains("vertexBound") && f["vertexBound"].is_number()) e.costRatio = f["vertexBound"].get<double>();
          const std::string space = f.value("skinSpace", "-");
          if (space != "-") e.detail += "; skinning: " + space;
          if (space.find("defaults") != std::string::npos) e.why = "asymmetric: the pipelines' default skinning configurations differ";
        }
    if (e.costRatio < 0 && e.why.empty()) e.why = "no vertex-bound timing of " + scene;
    ev.push_back(e);
  };
  frameEvidence("llvmpipe frame time, vertex-bound rigid normal-mapped", "dense_torus");
  frameEvidence("llvmpipe frame time, vertex-bound skinned", "crowd");

  json value = json::object();
  // Informational: frame time at 512x512 (fragment-bound on llvmpipe), not a verdict input.
  std::string info;
  std::vector<double> frame;
  if (in.frameTimes.is_array())
    for (const json& f : in.frameTimes)
      if (f["ratio"].is_number()) frame.push_back(f["ratio"].get<double>());
  if (!frame.empty()) {
    value["frame time ratio (median over " + std::to_string(frame.size()) + " scenes)"] = median(frame);
    info = "frame time motor/matrix at 512x512 " + x2(median(frame)) + " (median of " + std::to_string(frame.size()) +
           " scenes, " + x2(*std::min_element(frame.begin(), frame.end())) + ".." +
           x2(*std::max_element(frame.begin(), frame.end())) + "; fragment-bound, not a verdict input)";
  }

  c.method = "Every kind of evidence as motor cost / matrix cost (< 1: motor cheaper): ops per vertex counted through "
             "the shim (rigid; skinned with both pipelines in the same configuration, both configurations); CPU: "
             "motorbench bench pairs vertex_frame and skinned_vertex, the fastest motor implementation's time per item "
             "against the fastest matrix implementation measured (shim-compiled shader, GLM or the Highway SIMD "
             "kernels of kernels/simd), in and out of cache, the worse of the two; source: " +
             (in.kernelSource.empty() ? std::string("none") : in.kernelSource) +
             ". GPU (llvmpipe): paired per-frame ratio at a 64x64 viewport of dense_torus (rigid, normal-mapped, "
             ">= " + std::to_string(timing::kVertexBoundVerticesPerPixel) + " vertices per pixel) and crowd (skinned); "
             "source: " + (in.frameSource.empty() ? std::string("none") : in.frameSource) +
             ". Verdict: reproduced when every kind agrees (cost ratio <= " + x2(1.0 + kTolerance) +
             "); differs when none does; inconclusive when they disagree or some kind is missing or asymmetric.";
  std::string text, agree, disagree, missing;
  for (const Evidence& e : ev) {
    json j = {{"detail", e.detail}, {"costRatio", e.costRatio >= 0 ? json(e.costRatio) : json(nullptr)}};
    if (!e.why.empty()) j["caveat"] = e.why;
    value[e.kind] = j;
    text += (text.empty() ? "" : "; ") + e.kind + " " + (e.costRatio >= 0 ? x2(e.costRatio) : std::string("-")) +
            (e.detail.empty() ? "" : " (" + e.detail + ")");
    const bool usable = e.costRatio >= 0 && e.why.empty();
    if (!usable) missing += (missing.empty() ? "" : "; ") + e.kind + ": " + (e.why.empty() ? "not measured" : e.why);
    else if (e.costRatio <= 1.0 + kTolerance) agree += (agree.empty() ? "" : ", ") + e.kind;
    else disagree += (disagree.empty() ? "" : ", ") + e.kind + " (motor " + pct(e.costRatio) + ")";
  }
  if (agree.empty() && disagree.empty()) {
    c.measured = "-";
    c.measuredValue = nullptr;
    c.verdict = Verdict::NotMeasurable;
    c.verdictText = "not measurable here: " + (in.missing.empty() ? missing : in.missing);
    return {c};
  }
  c.measured = text + (info.empty() ? "" : "; " + info) + " (cost ratios motor / matrix: < 1 = motor cheaper)";
  c.measuredValue = value;
  if (disagree.empty() && missing.empty()) {
    c.verdict = Verdict::Reproduced;
    c.verdictText = "reproduced: every kind of evidence within " + std::to_string(int(kTolerance * 100)) +
                    " % or faster (" + agree + ")";
  } else if (agree.empty() && missing.empty()) {
    c.verdict = Verdict::Differs;
    c.verdictText = "differs: every kind of evidence has the motor more than " + std::to_string(int(kTolerance * 100)) +
                    " % slower (" + disagree + ")";
  } else {
    c.verdict = Verdict::Inconclusive;
    c.verdictText = "inconclusive: agree (within " + std::to_string(int(kTolerance * 100)) + " %): " +
                    (agree.empty() ? std::string("none") : agree) + "; disagree: " +
                    (disagree.empty() ? std::string("none") : disagree) + (missing.empty() ? "" : "; not usable: " + missing);
  }
  if (!in.missing.empty()) c.verdictText += "; partly not measured: " + in.missing;
  return {c};
}

}  // namespace mb::claims
