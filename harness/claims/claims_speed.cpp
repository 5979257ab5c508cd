// "PGA motors can be just as fast as 4x4 matrices to transform your mesh vertices": judged from
// measured time, not from op counts: the vertex-with-frame kernel pair of `motorbench bench`
// (items/s, in and out of cache) and the frame-time ratios of the pipelines (llvmpipe).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "harness/claims/claims_sources.h"
#include "harness/timing/frame_timing.h"

namespace mb::claims {
namespace {

using json = nlohmann::json;

// "As fast" = within this fraction (or faster): run-to-run noise of both measurements on a
// shared 2-core machine is a few per cent.
constexpr double kTolerance = 0.10;

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

}  // namespace

std::vector<Claim> speedClaims(const SpeedInputs& in) {
  Claim c{"as_fast_as_matrices", "Speed",
          "motors transform mesh vertices (with tangent frame) as fast as 4x4 matrices"};
  c.paper = "as fast (47/38 vs 48/36 ops per vertex)";
  c.paperValue = {{"ratio", 1.0}};
  c.method = "CPU: motorbench bench pair vertex_frame (position + normal + tangent with model and normal "
             "matrices vs position + tangent rotor with one motor, both compiled from the shaders' GLSL "
             "through the shim), items/s motor / matrix, in cache and out of cache (>= 256 MiB); source: " +
             (in.kernelSource.empty() ? std::string("none") : in.kernelSource) +
             ". GPU (llvmpipe): frame time motor / matrix per scene (the median of the per-frame ratios, both "
             "pipelines rendering each frame back to back), and in a vertex-bound "
             "configuration (64x64 viewport, scenes drawing >= " +
             std::to_string(timing::kVertexBoundVerticesPerPixel) + " vertices per pixel there); source: " +
             (in.frameSource.empty() ? std::string("none") : in.frameSource) +
             ". Verdict: reproduced when the motor side is at most " + std::to_string(int(kTolerance * 100)) +
             " % slower in every measurement.";
  json value = json::object();
  std::string text, slower;
  auto judge = [&](const std::string& label, double speedRatio) {  // > 1: motor faster
    text += (text.empty() ? "" : "; ") + label + " " + x2(speedRatio);
    if (speedRatio < 1.0 - kTolerance) slower += (slower.empty() ? "" : ", ") + label + " motor " + pct(1.0 / speedRatio) + " time";
  };
  if (in.kernelPairs.is_array())
    for (const json& p : in.kernelPairs)
      if (p.value("kernel", "") == "vertex_frame" && p["ratio_motor_matrix"].is_number()) {
        const std::string label = "kernel vertex_frame/" +
                                  (p["size"].is_string() ? p["size"].get<std::string>() : "?") + " throughput";
        value[label] = p["ratio_motor_matrix"];
        judge(label, p["ratio_motor_matrix"].get<double>());
      }
  std::vector<double> frame, vbound;
  if (in.frameTimes.is_array())
    for (const json& f : in.frameTimes) {
      if (f["ratio"].is_number()) frame.push_back(f["ratio"].get<double>());
      if (f.contains("vertexBound") && f["vertexBound"].is_number()) vbound.push_back(f["vertexBound"].get<double>());
    }
  if (!frame.empty()) {
    const double m = median(frame);
    value["frame time ratio (median over " + std::to_string(frame.size()) + " scenes)"] = m;
    text += (text.empty() ? "" : "; ") + std::string("frame time motor/matrix ") + x2(m) + " (median of " +
            std::to_string(frame.size()) + " scenes, " + x2(*std::min_element(frame.begin(), frame.end())) + ".." +
            x2(*std::max_element(frame.begin(), frame.end())) + ")";
    if (m > 1.0 + kTolerance) slower += (slower.empty() ? "" : ", ") + std::string("frame time ") + pct(m);
  }
  if (!vbound.empty()) {
    const double m = median(vbound);
    value["vertex-bound frame time ratio (median)"] = m;
    text += "; vertex-bound frame time " + x2(m);
    if (m > 1.0 + kTolerance) slower += (slower.empty() ? "" : ", ") + std::string("vertex-bound frame time ") + pct(m);
  }
  if (value.empty()) {
    c.measured = "-";
    c.measuredValue = nullptr;
    c.verdict = Verdict::NotMeasurable;
    c.verdictText = "not measurable here: " + (in.missing.empty() ? std::string("no bench or timing data") : in.missing);
    return {c};
  }
  c.measured = text + " (kernel: > 1 = motor faster; frame time: < 1 = motor faster)";
  c.measuredValue = value;
  c.verdict = slower.empty() ? Verdict::Reproduced : Verdict::Differs;
  c.verdictText = slower.empty() ? "reproduced (within " + std::to_string(int(kTolerance * 100)) + " % or faster)"
                                 : "differs: " + slower;
  if (!in.missing.empty()) c.verdictText += "; partly not measured: " + in.missing;
  return {c};
}

}  // namespace mb::claims
