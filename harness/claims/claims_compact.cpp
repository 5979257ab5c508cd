// The smallest motor vertex against the smallest matrix vertex: motor_c (4-byte
// tangent rotor) and matrix_c (octahedral normal + diamond tangent), both 16 bytes with int16
// positions and half uvs. Bytes from the uploads, image cost from renders compared with matrix,
// ops counted through the shim, ISA from a `motorbench isa` JSON when one is given.
#include <algorithm>
#include <cmath>

#include "harness/claims/claims_sources.h"
#include "harness/claims/claims_uploads.h"
#include "harness/claims/claims_vertex_ops.h"
#include "harness/document/report_isa.h"
#include "harness/ops/pipeline_ops.h"
#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "pipelines/registry.h"
#include "pipelines/scene/loader.h"

namespace mb::claims {
namespace {

// The pipelines these claims compare, by their registry traits: a family's smallest vertex (the
// first registered with the fewest bytes) and its baseline (its first), and the pipeline that
// passes the rotor to the fragment shader.
std::string smallestVertex(PipelineFamily family) {
  const PipelineEntry* best = nullptr;
  for (const PipelineEntry& e : registeredPipelines())
    if (e.space == Space::Euclidean && e.family == family && e.vertexBytes > 0 &&
        (!best || e.vertexBytes < best->vertexBytes))
      best = &e;
  return best ? best->name : "";
}

std::string baselineOf(PipelineFamily family) {
  for (const PipelineEntry& e : registeredPipelines())
    if (e.space == Space::Euclidean && e.family == family) return e.name;
  return "";
}

std::string fragmentRotorPipeline() {
  for (const PipelineEntry& e : registeredPipelines())
    if (e.frame.perFragment) return e.name;
  return "";
}

const std::string kMotor = smallestVertex(PipelineFamily::Motor), kMatrix = smallestVertex(PipelineFamily::Matrix);
const std::string kMotorBase = baselineOf(PipelineFamily::Motor), kMatrixBase = baselineOf(PipelineFamily::Matrix);
const std::string kRotor = fragmentRotorPipeline();

Claim row(const std::string& id, const std::string& statement, const std::string& method) {
  Claim c{id, "Compact vertices", statement};
  c.paper = "- (not claimed by the paper)";
  c.method = method;
  c.origin = "compact";
  return c;
}

void notMeasurable(Claim& c, const std::string& why) {
  c.verdict = Verdict::NotMeasurable;
  c.verdictText = "not measurable here: " + why;
  c.measured = "-";
}

// Worst PSNR against `base` over the scenes at rest (skinned meshes in their bind pose, where
// both skinning methods agree), per pipeline of `pipelines`; 1e300 where every image is identical.
Result<std::vector<double>> worstPsnr(const std::vector<std::string>& scenes, const std::string& base,
                                      const std::vector<std::string>& pipelines) {
  using R = Result<std::vector<double>>;
  std::vector<double> worst(pipelines.size(), 1e300);
  for (const std::string& name : scenes) {
    auto scene = loadScene(name);
    if (!scene) return R::fail(scene.error());
    FrameSettings s;
    s.width = s.height = 128;
    auto baseFrame = renderFrame(*scene, base, s);
    if (!baseFrame) return R::fail(baseFrame.error());
    for (size_t i = 0; i < pipelines.size(); ++i) {
      auto f = renderFrame(*scene, pipelines[i], s);
      if (!f) return R::fail(f.error());
      auto m = compareImages(baseFrame->image, f->image);
      if (!m) return R::fail(m.error());
      if (std::isfinite(m->psnr)) worst[i] = std::min(worst[i], m->psnr);
    }
  }
  return worst;
}

// The same from a report.json's summary (its frames where both should agree), when it has
// every pipeline of `pipelines`; fails otherwise.
Result<std::vector<double>> reportWorstPsnr(const nlohmann::json& report, const std::vector<std::string>& pipelines) {
  using R = Result<std::vector<double>>;
  std::vector<double> worst;
  for (const std::string& p : pipelines) {
    const nlohmann::json* im = nullptr;
    if (report.is_object() && report.contains("summary") && report["summary"].contains("images") &&
        report["summary"]["images"].contains(p))
      im = &report["summary"]["images"][p];
    if (!im || im->value("comparedFrames", 0) == 0) return R::fail("no image summary for " + p);
    const bool identical = im->value("identicalFrames", 0) == im->value("comparedFrames", 0);
    const nlohmann::json psnr = im->contains("psnr") ? (*im)["psnr"].value("min", nlohmann::json()) : nlohmann::json();
    if (!identical && !psnr.is_number()) return R::fail("no PSNR for " + p);
    worst.push_back(identical ? 1e300 : psnr.get<double>());
  }
  return worst;
}

// The counted ops of the shader function `function` (one of `motorbench ops`' kernels).
OpCounts countedKernel(const std::string& function) {
  for (const opsv::KernelRow& k : vertexOps().kernels)
    if (k.kernel.function == function) return k.counted;
  return {};
}

std::string psnrText(double v) { return v > 1e299 ? std::string("identical") : fmt("%.1f dB", v); }

// "instructions / VGPRs" of a pipeline's rigid vertex shader on one family of the isa JSON.
std::string isaCell(const nlohmann::json& isa, const std::string& pipeline, const std::string& family) {
  const nlohmann::json* s = report::isaRow(isa, pipeline, "rigid", family);
  return s ? s->value("instructions", nlohmann::json()).dump() + " / " + s->value("vgprs", nlohmann::json()).dump()
           : "-";
}

// The paper's suggestion (section "Fragment Shader"): pass the tangent rotor itself to the
// fragment shader, which saves the vertex stage's extraction, one varying and the fragment
// stage's orthogonalisation. motor_cf against motor_c (the same 16 bytes, the frame unpacked per
// vertex): counted ops of the rigid vertex and of a normal-mapped fragment's shading normal,
// the varyings from the isa JSON's SPIR-V, and what the interpolated rotor does to the image.
Claim fragmentRotorClaim(const nlohmann::json& isa, const std::vector<std::string>& scenes, const nlohmann::json& report,
                         const std::string& reportSource) {
  Claim c{"fragment_rotor", "Compact vertices",
          "passing the tangent rotor to the fragment shader saves the vertex extraction, one varying and the "
          "fragment orthogonalisation"};
  c.paper = "fewer ops per vertex, one varying less, no orthogonalisation per fragment (not counted)";
  c.origin = "compact";
  c.method = "motor_cf vs motor_c (both 16-byte vertices): rigid vertex to clip counted; the shading normal of a "
             "normal-mapped fragment counted (rotorShadingNormal vs tbnShadingNormal, shaders/frame_shading.glsl); "
             "varyings = the rigid program's fragment inputs in SPIR-V (isa JSON); image: worst PSNR against motor_c at "
             "rest, built-in normal_torus, textured_box, skinned_tube, dense_torus and crowd at 128x128";
  std::string zero;
  const std::map<std::string, double> rigid = opsPerPipeline("rigid", false, zero);
  // Normal-mapped; without a normal map.
  const OpCounts frag[2] = {countedKernel("rotorShadingNormal"), countedKernel("tbnShadingNormal")};
  const OpCounts plain[2] = {countedKernel("rotorSurfaceNormal"), countedKernel("tbnSurfaceNormal")};
  // With a report: its worst PSNR of each against matrix (the figure the report prints; it
  // compares with matrix only), never a render here.
  const bool fromReport = report.is_object();
  auto image = fromReport ? reportWorstPsnr(report, {kRotor, kMotor}) : worstPsnr(scenes, kMotor, {kRotor});
  if (fromReport && image)
    c.method.replace(c.method.find("image: "), std::string::npos,
                     "image: the report's worst PSNR against matrix of motor_cf and of motor_c (" + reportSource +
                         " summary.images, its frames where both should agree)");
  if (!rigid.count(kRotor) || !rigid.count(kMotor) || !image) {
    c.verdict = Verdict::NotMeasurable;
    c.verdictText = "not measurable here: " + (image ? "no counted rigid variant " + zero : image.error());
    c.measured = "-";
    return c;
  }
  const double vf = rigid.at(kRotor), vc = rigid.at(kMotor);
  const uint64_t ff = opsv::total(frag[0]), fc = opsv::total(frag[1]);
  const nlohmann::json* rf = isa.is_object() && !isa.value("families", nlohmann::json::array()).empty()
                                 ? report::isaRow(isa, kRotor, "rigid", isa["families"][0].value("id", ""))
                                 : nullptr;
  const nlohmann::json* rc = rf ? report::isaRow(isa, kMotor, "rigid", isa["families"][0].value("id", "")) : nullptr;
  const bool slots = rf && rc && rf->contains("varyingSlots") && rc->contains("varyingSlots");
  c.measured = "vertex " + fmt("%g", vf) + " vs " + fmt("%g", vc) + " ops; fragment " + opsText(frag[0]) + " vs " +
               opsText(frag[1]) + (slots ? "; varyings " + (*rf)["varyingSlots"].dump() + " vs " +
                                               (*rc)["varyingSlots"].dump() + " vec4 slots"
                                         : "") +
               (fromReport ? "; image vs matrix " + psnrText(image->front()) + " vs " + psnrText(image->back())
                           : "; image vs motor_c " + psnrText(image->front()));
  c.measuredValue = {{"vertexOps", {{kRotor, vf}, {kMotor, vc}}},
                     {"fragmentOps", {{kRotor, opsJson(frag[0])}, {kMotor, opsJson(frag[1])}}},
                     {"fragmentOpsNoNormalMap", {{kRotor, opsJson(plain[0])}, {kMotor, opsJson(plain[1])}}},
                     {fromReport ? "worstPsnrAgainstMatrix" : "worstPsnrAgainstMotorC",
                      image->front() > 1e299 ? nlohmann::json() : nlohmann::json(image->front())}};
  if (fromReport) c.measuredValue["worstPsnrAgainstMatrixMotorC"] = image->back() > 1e299 ? nlohmann::json() : nlohmann::json(image->back());
  if (slots)
    c.measuredValue["varyingSlots"] = {{kRotor, (*rf)["varyingSlots"]}, {kMotor, (*rc)["varyingSlots"]}};
  const bool vertexSaves = vf < vc, fragmentSaves = ff < fc;
  // What the claim leaves out, measured beside it.
  const std::string caveat = "; without a normal map the fragment pays " + fmt("%g", double(opsv::total(plain[0]))) +
                             " vs " + fmt("%g", double(opsv::total(plain[1]))) +
                             " ops, and the interpolated rotor is a different frame inside a triangle (the normal "
                             "map must be baked for it: README, motor_cf)";
  const bool varyingSaves = slots && (*rf)["varyingSlots"].get<int>() < (*rc)["varyingSlots"].get<int>();
  if (!slots) {
    c.verdict = Verdict::Inconclusive;
    c.verdictText = "inconclusive: no isa JSON for the varyings; vertex " + std::string(vertexSaves ? "saves" : "does not save") +
                    ", fragment " + (fragmentSaves ? "saves" : "does not save");
  } else if (vertexSaves && fragmentSaves && varyingSaves) {
    c.verdict = Verdict::Reproduced;
    c.verdictText = "reproduced for normal-mapped fragments: fewer ops in both stages and one vec4 varying less" + caveat;
  } else {
    c.verdict = Verdict::Differs;
    c.verdictText = std::string("differs: the vertex stage ") + (vertexSaves ? "saves" : "does not save") +
                    ", the fragment stage " + (fragmentSaves ? "saves" : "does not save (the rotor is normalised and "
                                                                         "unpacked there instead)") +
                    ", varyings " + (varyingSaves ? "fewer" : "not fewer") + caveat;
  }
  return c;
}

// The built-in scenes the image row renders when there is no report.
const std::vector<std::string> kCompactScenes = {"normal_torus", "textured_box", "skinned_tube", "dense_torus", "crowd"};

// Bytes per normal-mapped vertex of motor_c and matrix_c on normal_torus, beside motor and
// matrix (a baseline row).
Claim compactBytesRow(const Uploads& uploads) {
  Claim bytes = row("compact_bytes_per_vertex",
                    "the smallest motor vertex vs the smallest matrix vertex: bytes per normal-mapped vertex",
                    "PipelineStats.normalMappedVertexBytes / normalMappedVertices of motor_c and matrix_c on the "
                    "built-in normal_torus (int16x4 position, 4-byte frame, half2 uv), beside motor and matrix; uploads: " +
                        uploads.source());
  double b[4] = {0, 0, 0, 0};
  std::string error;
  const std::string names[4] = {kMotor, kMatrix, kMotorBase, kMatrixBase};
  for (int i = 0; i < 4 && error.empty(); ++i) {
    auto f = uploads.of("normal_torus", names[i]);
    if (!f) error = f.error();
    else if (f->normalMappedVertices)
      b[i] = double(f->normalMappedVertexBytes) / double(f->normalMappedVertices);
  }
  if (!error.empty()) {
    notMeasurable(bytes, error);
    return bytes;
  }
  bytes.measured = fmt("%g", b[0]) + " vs " + fmt("%g", b[1]) + " bytes/vertex (motor " + fmt("%g", b[2]) +
                   ", matrix " + fmt("%g", b[3]) + ")";
  bytes.measuredValue = {{kMotor, b[0]}, {kMatrix, b[1]}, {kMotorBase, b[2]}, {kMatrixBase, b[3]}};
  bytes.verdict = Verdict::Baseline;
  bytes.verdictText = b[0] == b[1] ? "baseline: at their smallest both sides need the same bytes; only the frame's "
                                     "encoding and its unpacking differ"
                                   : std::string("baseline: the ") + (b[0] < b[1] ? "motor" : "matrix") +
                                         " vertex is smaller";
  return bytes;
}

// The worst PSNR against matrix of motor_c and matrix_c: from the report's summary, else (no
// report) rendered here over kCompactScenes (a baseline row).
Claim compactImageRow(const nlohmann::json& report, const std::string& reportSource) {
  Claim image = row("compact_image_cost", "image cost of the smallest vertices: worst PSNR against matrix",
                    "renders at rest (skinned meshes in their bind pose: no skinning-method difference) of the "
                    "built-in normal_torus, textured_box, skinned_tube, dense_torus and crowd at 128x128, "
                    "compared with matrix (OpenImageIO); the worst scene per pipeline");
  Result<std::vector<double>> w = reportWorstPsnr(report, {kMotor, kMatrix});
  if (w) {
    image.method = "the report's summary (" + reportSource + "): worst PSNR against matrix over its frames where "
                   "both should agree (skinning-method frames apart), " +
                   std::to_string(report["settings"].value("width", 0)) + "x" +
                   std::to_string(report["settings"].value("height", 0)) + ", its scenes";
  } else if (!report.is_object()) {  // a report without both: not rendered here
    w = worstPsnr(kCompactScenes, kMatrixBase, {kMotor, kMatrix});
  }
  if (!w) {
    notMeasurable(image, w.error());
    return image;
  }
  const double motorPsnr = (*w)[0], matrixPsnr = (*w)[1];
  image.measured = psnrText(motorPsnr) + " vs " + psnrText(matrixPsnr);
  image.measuredValue = {{kMotor, motorPsnr > 1e299 ? nlohmann::json() : nlohmann::json(motorPsnr)},
                         {kMatrix, matrixPsnr > 1e299 ? nlohmann::json() : nlohmann::json(matrixPsnr)}};
  image.verdict = Verdict::Baseline;
  image.verdictText = std::string("baseline: ") +
                      (std::abs(motorPsnr - matrixPsnr) < 1.0 ? "within 1 dB of each other"
                       : motorPsnr > matrixPsnr                ? "the 4-byte rotor costs less image"
                                                             : "the octahedral frame costs less image");
  return image;
}

// Counted ops of the frame decode and of the rigid vertex to clip, motor_c vs matrix_c (a
// baseline row).
Claim compactOpsRow() {
  Claim ops = row("compact_ops", "ops per vertex of the smallest vertices: frame decode and rigid vertex to clip",
                  "counted through the shim (shaders/compact_frame.glsl, motor_transform.glsl, affine_transform.glsl): "
                  "compactRotor vs compactMatrixFrame, and the rigid shader variant object to clip");
  const OpCounts decode[2] = {countedKernel("compactRotor"), countedKernel("compactMatrixFrame")};
  std::string zero;
  const std::map<std::string, double> rigid = opsPerPipeline("rigid", false, zero);
  if (!rigid.count(kMotor) || !rigid.count(kMatrix)) {
    notMeasurable(ops, "no counted rigid variant" + (zero.empty() ? "" : " (" + zero + ")"));
    return ops;
  }
  ops.measured = "decode " + opsText(decode[0]) + " vs " + opsText(decode[1]) + "; rigid to clip " +
                 fmt("%g", rigid.at(kMotor)) + " vs " + fmt("%g", rigid.at(kMatrix)) + " ops/vertex";
  ops.measuredValue = {{"decode", {{kMotor, opsJson(decode[0])}, {kMatrix, opsJson(decode[1])}}},
                       {"rigidToClip", {{kMotor, rigid.at(kMotor)}, {kMatrix, rigid.at(kMatrix)}}}};
  const uint64_t dm = opsv::total(decode[0]), dx = opsv::total(decode[1]);
  ops.verdict = Verdict::Baseline;
  ops.verdictText = "baseline: the frame decode costs " + fmt("%g", double(dm)) + " vs " + fmt("%g", double(dx)) +
                    " ops; the whole rigid vertex to clip is " +
                    (rigid.at(kMotor) < rigid.at(kMatrix) ? "cheaper" : "dearer") + " on the motor side";
  return ops;
}

// The AMD ISA of the rigid vertex shaders of motor_c and matrix_c per family (a baseline row;
// not measurable without an isa JSON).
Claim compactIsaRow(const nlohmann::json& isa, const std::string& isaSource) {
  Claim isaRow = row("compact_isa", "AMD ISA of the smallest vertices' rigid vertex shader: instructions / VGPRs",
                     "`motorbench isa` (RADV/ACO on its null device) of the rigid variants of motor_c and matrix_c, "
                     "per family; the vertex fetch's format conversion is not in these (the typed fetch does it)");
  if (!isa.is_object()) {
    notMeasurable(isaRow, "no isa JSON (claims --isa FILE, or a report with --isa-json)");
    return isaRow;
  }
  std::string text;
  nlohmann::json values = nlohmann::json::object();
  for (const nlohmann::json& f : isa.value("families", nlohmann::json::array())) {
    const std::string id = f.value("id", "");
    const std::string m = isaCell(isa, kMotor, id), x = isaCell(isa, kMatrix, id);
    text += (text.empty() ? "" : "; ") + id + " " + m + " vs " + x;
    values[id] = {{kMotor, m}, {kMatrix, x}};
  }
  isaRow.measured = text.empty() ? "-" : text;
  isaRow.measuredValue = values;
  isaRow.method += " (" + isaSource + ")";
  isaRow.verdict = Verdict::Baseline;
  isaRow.verdictText = "baseline: motor_c vs matrix_c per family";
  return isaRow;
}

}  // namespace

std::vector<Claim> compactClaims(const nlohmann::json& isa, const std::string& isaSource,
                                 const nlohmann::json& report, const std::string& reportSource) {
  const Uploads uploads = report.is_object() ? Uploads(report.value("scenes", nlohmann::json()), reportSource) : Uploads();
  std::vector<Claim> out;
  out.push_back(compactBytesRow(uploads));
  out.push_back(compactImageRow(report, reportSource));
  out.push_back(compactOpsRow());
  out.push_back(compactIsaRow(isa, isaSource));
  out.push_back(fragmentRotorClaim(isa, kCompactScenes, report, reportSource));
  return out;
}

}  // namespace mb::claims
