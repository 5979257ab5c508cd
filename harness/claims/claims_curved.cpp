// Curved space: the paper's question on S3 and H3, where a motor has no scale or
// shear to excuse: floats per instance (uploads), ops per vertex (counted + SPIR-V), frame
// time motor / matrix (normal and vertex-bound viewport, one run), camera drift. No paper
// figure exists: verdict "baseline", except floats per instance (the expected 16 vs 8).
#include <cmath>
#include <cstdio>

#include "harness/claims/claims_device.h"
#include "harness/claims/claims_sources.h"
#include "harness/claims/claims_uploads.h"
#include "harness/ops/ops_vertex.h"
#include "harness/timing/report_timing.h"
#include "pipelines/curved/curved_drift.h"
#include "pipelines/scene/curved_space.h"
#include "pipelines/scene/loader.h"

namespace mb::claims {
namespace {

using nlohmann::json;

std::string num(double v, const char* fmt = "%g") {
  char b[64];
  std::snprintf(b, sizeof b, fmt, v);
  return b;
}

Claim baseline(Claim c) {
  c.paper = "-";
  c.paperValue = nullptr;
  c.verdict = Verdict::Baseline;
  c.verdictText = "baseline (no paper figure)";
  return c;
}

Claim failed(Claim c, const std::string& why) {
  c.verdict = Verdict::NotMeasurable;
  c.verdictText = "not measurable here: " + why;
  c.measured = "-";
  c.measuredValue = nullptr;
  return c;
}

const char* kSpaces[2][3] = {{"S3", "s3_tiling", "s3_"}, {"H3", "h3_tiling", "h3_"}};

const std::string kSection = "Curved space";

// Floats per instance, from the uploads of one frame of each pipeline: reproduced when every
// space uploads 16 (matrix) vs 8 (motor).
Claim floatsPerInstanceClaim(const Uploads& uploads) {
  Claim fpi{"curved_floats_per_instance", kSection,
            "floats per instance: O(4) / O(3,1) mat4 vs 8-float motor (S3: quaternion pair)"};
  fpi.paper = "16 vs 8";
  fpi.paperValue = {{"matrix", 16}, {"motor", 8}};
  fpi.method = "PipelineStats.floatsPerTransform (instance-buffer bytes uploaded / instances / 4) of "
               "s3_matrix, s3_motor on s3_tiling and h3_matrix, h3_motor on h3_tiling; uploads: " + uploads.source();
  json fpiValue = json::object();
  std::string fpiText, fpiError;
  bool fpiSame = true;
  for (auto& sp : kSpaces) {
    double v[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
      auto f = uploads.of(sp[1], std::string(sp[2]) + (k ? "motor" : "matrix"));
      if (!f) { fpiError = f.error(); break; }
      v[k] = f->floatsPerTransform;
    }
    if (!fpiError.empty()) break;
    fpiValue[sp[0]] = {{"matrix", v[0]}, {"motor", v[1]}};
    fpiText += std::string(fpiText.empty() ? "" : "; ") + sp[0] + ": " + num(v[0]) + " vs " + num(v[1]);
    fpiSame = fpiSame && v[0] == 16 && v[1] == 8;
  }
  if (!fpiError.empty()) return failed(fpi, fpiError);
  fpi.measured = fpiText + " floats/instance";
  fpi.measuredValue = fpiValue;
  fpi.verdict = fpiSame ? Verdict::Reproduced : Verdict::Differs;
  fpi.verdictText = fpiSame ? "reproduced" : "differs";
  return fpi;
}

// Ops per vertex: counted transforms and the whole vertex shaders in SPIR-V, every curved
// pipeline (a baseline row).
Claim opsPerVertexClaim() {
  Claim opv = baseline({"curved_ops_per_vertex", kSection,
                        "ops per vertex (position + normal by camera * instance): matrix vs motor"});
  opv.method = "counted: curvedMatrixVertex / curvedMotorVertex (shaders/curved_transform.glsl) on "
               "mb::Counted; SPIR-V: curved_matrix.vs / curved_motor.vs per space, spirv-opt -O, incl. "
               "the projection (16 mul, 12 add) both sides share (motorbench ops)";
  const opsv::VertexOps ops = opsv::measureVertexOps();
  json value = json::object();
  std::string text;
  for (auto& sp : kSpaces)
    for (const char* side : {"matrix", "motor"}) {
      const std::string p = std::string(sp[2]) + side;
      for (const opsv::VariantRow& v : ops.variants) {
        if (v.variant.pipeline != p) continue;
        value[p] = {{"counted", opsJson(v.counted)},
                    {"spirv", v.shader ? json{{"mul", v.shader->mul}, {"add", v.shader->add}} : json()}};
        text += std::string(text.empty() ? "" : "; ") + p + " " + std::to_string(v.counted.mul) + "/" +
                std::to_string(v.counted.add) + " counted, " +
                (v.shader ? std::to_string(v.shader->mul) + "/" + std::to_string(v.shader->add) + " SPIR-V"
                          : std::string("no SPIR-V (") + ops.toolsProblem + ")");
      }
    }
  opv.measured = text + " (mul/add)";
  opv.measuredValue = value;
  return opv;
}

// The report's own timing of curved scene `id` when it has one with a paired ratio (one
// figure, the report's, not a second timing at another size); null otherwise.
json reportedTiming(const json& reportScenes, const std::string& id) {
  if (!reportScenes.is_array()) return nullptr;
  for (const json& s : reportScenes)
    if (s.value("id", "") == id && s.value("timing", json()).is_object() &&
        s["timing"].value("paired_ratio_motor_matrix", json()).is_number())
      return s["timing"];
  return nullptr;
}

// A timing's motor / matrix ratio: paired per frame where recorded, else of the medians; null
// when it has neither.
json motorMatrixRatio(const json& c) {
  if (!c.is_object()) return nullptr;
  for (const char* key : {"paired_ratio_motor_matrix", "ratio_motor_matrix"})
    if (c.contains(key) && c[key].is_number()) return c[key];
  return nullptr;
}

// Frame time, motor / matrix, both viewports in one run per scene: the report's timing of both
// curved scenes where it has them, else timed here (not with --no-run); a baseline row.
Claim frameTimeClaim(bool runTiming, int frames, const json& reportScenes) {
  Claim ft = baseline({"curved_frame_time", kSection, "frame time motor / matrix (< 1: motor faster)"});
  ft.method = "report::timeScene per curved scene: " + std::to_string(frames) +
              " frames per pipeline at 512x512 and at 64x64 (vertex-bound: >= 10 drawn vertices per "
              "pixel), pipelines interleaved, median of the paired per-frame ratios";
  const bool fromReport = !reportedTiming(reportScenes, kSpaces[0][1]).is_null() &&
                          !reportedTiming(reportScenes, kSpaces[1][1]).is_null();
  if (fromReport)
    ft.method = "the report's timing of each curved scene (report.json scenes[].timing, motorbench report's frames and "
                "size; vertex-bound at 64x64 where >= 10 drawn vertices per pixel), the median of the paired per-frame "
                "ratios: the figure the report prints";
  if (!runTiming && !fromReport)
    return failed(ft, reportScenes.is_array() ? "the report has no timing of s3_tiling and h3_tiling (claims "
                                                "times nothing beside a report)"
                                              : "--no-run");
  json value = json::object();
  std::string text, error, device;
  for (auto& sp : kSpaces) {
    json t = reportedTiming(reportScenes, sp[1]);
    if (t.is_null()) {
      auto scene = loadScene(sp[1]);
      if (!scene) { error = scene.error(); break; }
      t = report::timeScene(*scene, {std::string(sp[2]) + "matrix", std::string(sp[2]) + "motor"}, frames, 512, 512);
    }
    const json normal = motorMatrixRatio(t), tiny = motorMatrixRatio(t.value("vertexBound", json()));
    if (normal.is_null()) { error = t.value("error", json("no ratio")).dump(); break; }
    // The device that drew them (both spaces: one process, one device).
    device = timingDevice(json{{"gl", t.value("gl", json())}}).label() + ", " +
             t.value("frameTimeSource", std::string("wall-clock"));
    value[sp[0]] = {{"normal", normal}, {"vertexBound", tiny}};
    text += std::string(text.empty() ? "" : "; ") + sp[0] + ": " + num(normal.get<double>(), "%.2f") +
            " (64x64: " + (tiny.is_null() ? std::string("-") : num(tiny.get<double>(), "%.2f")) + ")";
  }
  if (!error.empty()) return failed(ft, error);
  ft.measured = text + "; device: " + device;
  value["device"] = device;
  ft.measuredValue = value;
  return ft;
}

// Drift of an accumulated camera over 10^6 float steps in S3 and H3, raw and renormalised,
// matrix vs motor (a baseline row).
Claim driftClaim() {
  Claim dr = baseline({"curved_drift", kSection,
                       "camera accumulated over 10^6 float steps: distance from the group, raw and "
                       "renormalised every step"});
  dr.method = "pipelines/curved/curved_drift.h (motorbench drift): matrix max|M^T eta M - eta| vs motor "
              "max|M~M - 1| (S3 pair: ||L|^2 - 1|, ||R|^2 - 1|); renormalisation: Gram-Schmidt in the "
              "space's form vs normalize_pair (S3) / normalize_m_k (H3), counted";
  json value = json::object();
  std::string text;
  for (int k : {1, -1}) {
    const curved::DriftResult r = curved::measureDrift(k, 1000000);
    const char* s = k > 0 ? "S3" : "H3";
    value[s] = {{"matrix", {{"raw", r.matrix.raw}, {"renormalised", r.matrix.renormalised},
                            {"renormOps", opsJson(r.matrix.renormOps)}}},
                {"motor", {{"raw", r.motor.raw}, {"renormalised", r.motor.renormalised},
                           {"renormOps", opsJson(r.motor.renormOps)}}}};
    text += std::string(text.empty() ? "" : "; ") + s + ": matrix " + num(r.matrix.raw, "%.2g") + " -> " +
            num(r.matrix.renormalised, "%.2g") + " (" + opsText(r.matrix.renormOps) + "), motor " +
            num(r.motor.raw, "%.2g") + " -> " + num(r.motor.renormalised, "%.2g") + " (" +
            opsText(r.motor.renormOps) + ")";
  }
  dr.measured = text;
  dr.measuredValue = value;
  return dr;
}

}  // namespace

std::vector<Claim> curvedClaims(bool runTiming, int frames, const json& reportScenes, const Uploads& uploads) {
  std::vector<Claim> out;
  out.push_back(floatsPerInstanceClaim(uploads));
  out.push_back(opsPerVertexClaim());
  out.push_back(frameTimeClaim(runTiming, frames, reportScenes));
  out.push_back(driftClaim());
  return out;
}

}  // namespace mb::claims
