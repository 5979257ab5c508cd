#include "harness/document/report_gpu_evidence.h"

#include "harness/document/report_document.h"
#include "harness/document/report_format.h"
#include "harness/document/report_layout_common.h"

namespace mb::document {

using namespace layout;

void gpuEvidenceSection(Document& d, const json& r) {
  std::vector<std::vector<Cell>> rows;
  std::string model;
  for (const json& s : r.value("scenes", json::array())) {
    if (!isEuclidean(s)) continue;
    const std::vector<std::string> pipes = pipelinesOf(r, s);
    const json& base = at(s, {"pipelines", pipes.empty() ? "" : pipes[0].c_str(), "vertexFetch", "bytesFetchedPerFrame"});
    bool first = true;
    for (const std::string& p : pipes) {
      const json& f = at(s, {"pipelines", p.c_str(), "vertexFetch"});
      if (!f.is_object()) continue;
      if (model.empty()) model = str(f["model"], "");
      const json& stride = f["strideBytes"];
      const json& bytes = f["bytesFetchedPerFrame"];
      const bool comparable = base.is_number() && base.get<double>() > 0 && bytes.is_number();
      rows.push_back({{first ? str(s["id"]) : "", "", first ? "#scene-" + str(s["id"]) : ""}, {p},
                      {str(stride["normalMapped"]) + " / " + str(stride["other"])},
                      {str(bytes)},
                      {comparable ? ratio(json(bytes.get<double>() / base.get<double>())) : "-"},
                      {fixed(f["overfetch"], 3)}, {fixed(f["bytesFetchedPerVertex"], 1)},
                      {str(f["verticesTransformedPerFrame"])}, {fixed(f["acmr"], 3)}, {fixed(f["atvr"], 3)},
                      {first ? fixed(at(s, {"overdraw", "overdraw"}), 3) : ""},
                      {f.value("skippedPrimitives", 0) ? str(f["skippedPrimitives"]) : ""}});
      first = false;
    }
  }
  d.heading(2, "GPU-relevant evidence (modelled by meshoptimizer on the mesh and layout, not timed)", kGpuEvidenceAnchor);
  if (rows.empty()) {
    d.paragraph("Not in this report.json (made by an older motorbench, or no Euclidean scene drew).");
    return;
  }
  d.paragraph("What one frame would make a GPU's vertex stage read and run in meshoptimizer's model (modelled, "
              "not measured on a GPU): its analyzers on each "
              "drawn primitive's index buffer (times its instances) with each pipeline's own interleaved vertex "
              "stride as uploaded (normal-mapped / other primitives: the matrix pipeline adds a tangent only on "
              "the former). Skin and optional streams are the same for every pipeline and left out. Model: " +
              model + ". Overfetch: bytes fetched / bytes of the vertices referenced (1 = each byte once). "
              "ACMR: vertex shader invocations per triangle; ATVR: per vertex referenced (1 = each vertex once); "
              "both depend on the index order only, so they are the same for every pipeline. Overdraw: the mesh "
              "alone (meshopt_analyzeOverdraw). No GPU was timed for these figures.");
  d.table({"scene", "pipeline", "stride B (normal-mapped / other)", "bytes fetched per frame",
           "fetched vs " + str(at(r, {"settings", "baseline"}), "baseline") + " (< 1: cheaper)", "overfetch",
           "bytes fetched per vertex", "vertex shader invocations per frame", "ACMR", "ATVR", "overdraw",
           "primitives not analysed"},
          rows);
}

}  // namespace mb::document
