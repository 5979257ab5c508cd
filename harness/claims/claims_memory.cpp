// Memory claims, measured from what each pipeline actually uploads: the built-in normal-mapped
// torus (position + normal + tangent + uv, the paper's 12-float case) and the skinned tube are
// rendered once per pipeline and PipelineStats is read (bytes summed from the GL upload calls).
#include <cmath>
#include <cstdio>
#include <map>

#include "harness/claims/claims_sources.h"
#include "harness/render/render_frame.h"
#include "pipelines/scene/loader.h"

namespace mb::claims {
namespace {

const char* kRigidScene = "normal_torus";
const char* kSkinnedScene = "skinned_tube";

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

// PipelineStats of `pipeline` on built-in `scene`, or the error.
Result<PipelineStats> uploads(const std::string& scene, const std::string& pipeline) {
  auto s = loadScene(scene);
  if (!s) return Result<PipelineStats>::fail(s.error());
  FrameSettings settings;
  settings.width = settings.height = 32;  // the uploads do not depend on the image size
  if (!s->animations.empty()) settings.anim.anim = 0;
  auto f = renderFrame(*s, pipeline, settings);
  if (!f) return Result<PipelineStats>::fail(f.error());
  return f->stats;
}

Claim notMeasurable(Claim c, const std::string& why) {
  c.verdict = Verdict::NotMeasurable;
  c.verdictText = "not measurable here: " + why;
  c.measured = "-";
  c.measuredValue = nullptr;
  return c;
}

// Matrix vs motor value of a stat, judged against the paper's pair.
Claim pairClaim(Claim c, double paperMatrix, double paperMotor, double matrix, double motor,
                const std::string& unit) {
  c.paper = num(paperMatrix) + " vs " + num(paperMotor) + " " + unit + " (" +
            num(std::round(100.0 * (paperMotor - paperMatrix) / paperMatrix)) + " %)";
  c.paperValue = {{"matrix", paperMatrix}, {"motor", paperMotor}};
  c.measured = num(matrix) + " vs " + num(motor) + " " + unit;
  if (matrix > 0) c.measured += " (" + num(std::round(1000.0 * (motor - matrix) / matrix) / 10.0) + " %)";
  c.measuredValue = {{"matrix", matrix}, {"motor", motor}};
  const bool same = matrix == paperMatrix && motor == paperMotor;
  c.verdict = same ? Verdict::Reproduced : Verdict::Differs;
  c.verdictText = same ? "reproduced" : "differs: measured " + num(matrix) + " vs " + num(motor) +
                                            " instead of " + num(paperMatrix) + " vs " + num(paperMotor);
  return c;
}

}  // namespace

std::vector<Claim> memoryClaims() {
  std::map<std::string, Result<PipelineStats>> rigid, skinned;
  for (const char* p : {"matrix", "motor"}) {
    rigid.emplace(p, uploads(kRigidScene, p));
    skinned.emplace(p, uploads(kSkinnedScene, p));
  }
  const std::string section = "Memory";
  std::vector<Claim> out;
  Claim fpv{"floats_per_vertex", section, "vertex with tangent-space normal mapping: 12 floats (3 position, 3 normal, "
            "4 tangent, 2 uv) vs 9 (3 position, 4 tangent rotor, 2 uv)"};
  fpv.method = std::string("PipelineStats.floatsPerVertex (shading-attribute bytes uploaded / vertices / 4) of "
                           "each pipeline on the built-in ") + kRigidScene + " (normal-mapped, tangents generated)";
  Claim fpt{"floats_per_transform", section, "floats per transform: 4x4 model matrix (+ normal matrix) vs 8-float motor"};
  fpt.method = std::string("PipelineStats.floatsPerTransform (per-draw transform uniforms uploaded, in floats) on ") +
               kRigidScene + "; the paper's table counts one 4x4 matrix per transform (16 + 16 with the "
               "normal matrix the Sample Viewer also uploads)";
  Claim vps{"vertices_per_storage", section, "conclusion: an extra 33 % vertices in the same storage"};
  vps.method = "matrix bytes per vertex / motor bytes per vertex - 1, from the same uploads as floats_per_vertex";
  Claim fpj{"floats_per_joint", section, "(not claimed by the paper) floats per skin joint uploaded per frame"};
  fpj.method = std::string("PipelineStats.floatsPerJoint on the built-in ") + kSkinnedScene +
               " (joint palette bytes of one frame / joints / 4)";
  if (!rigid.at("matrix") || !rigid.at("motor")) {
    const std::string why = !rigid.at("matrix") ? rigid.at("matrix").error() : rigid.at("motor").error();
    out = {notMeasurable(fpv, why), notMeasurable(fpt, why), notMeasurable(vps, why)};
  } else {
    const PipelineStats &m = *rigid.at("matrix"), &q = *rigid.at("motor");
    out.push_back(pairClaim(fpv, 12, 9, m.floatsPerVertex, q.floatsPerVertex, "floats/vertex"));
    // The paper: 32 for the matrix side (model + normal matrix in the Sample Viewer), 8 for a motor.
    out.push_back(pairClaim(fpt, 32, 8, m.floatsPerTransform, q.floatsPerTransform, "floats/transform"));
    const double bm = m.vertices ? double(m.vertexBytes) / double(m.vertices) : 0;
    const double bq = q.vertices ? double(q.vertexBytes) / double(q.vertices) : 0;
    vps.paper = "+33 %";
    vps.paperValue = 1.0 / 3.0;
    if (bq > 0) {
      const double extra = bm / bq - 1.0;
      vps.measured = num(std::round(1000.0 * extra) / 10.0) + " % (" + num(bm) + " vs " + num(bq) + " bytes/vertex)";
      vps.measuredValue = extra;
      const bool same = std::fabs(extra - 1.0 / 3.0) < 0.005;
      vps.verdict = same ? Verdict::Reproduced : Verdict::Differs;
      vps.verdictText = same ? "reproduced" : "differs: +" + num(std::round(1000.0 * extra) / 10.0) + " % instead of +33 %";
      out.push_back(vps);
    } else {
      out.push_back(notMeasurable(vps, "no vertices uploaded"));
    }
  }
  if (skinned.at("matrix") && skinned.at("motor")) {
    const double a = skinned.at("matrix")->floatsPerJoint, b = skinned.at("motor")->floatsPerJoint;
    fpj.paper = "-";
    fpj.measured = num(a) + " vs " + num(b) + " floats/joint";
    fpj.measuredValue = {{"matrix", a}, {"motor", b}};
    fpj.verdict = Verdict::Baseline;
    fpj.verdictText = "baseline: the motor palette is " + num(a > 0 ? std::round(100.0 * b / a) : 0) + " % of the matrix palette";
    out.push_back(fpj);
  } else {
    out.push_back(notMeasurable(fpj, !skinned.at("matrix") ? skinned.at("matrix").error() : skinned.at("motor").error()));
  }
  return out;
}

}  // namespace mb::claims
