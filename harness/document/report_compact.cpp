#include "harness/document/report_compact.h"

#include <algorithm>

#include "harness/document/report_format.h"
#include "harness/figures/figure.h"
#include "harness/document/report_isa.h"
#include "pipelines/registry.h"

namespace mb::document {
namespace {

using nlohmann::json;

// The counted ops of the kernel `function` (the frame decoders; harness/ops/
// vertex_kernels_fragment.cpp for the fragment frame).
std::string kernelText(const json& r, const std::string& function) {
  for (const json& k : at(r, {"opsPerVertex", "kernels"}))
    if (k.value("function", "") == function) return function + ": " + opsText(k["counted"]);
  return function + ": -";
}

// The counted ops of the kernel that unpacks the pipeline's frame (its registry entry); none
// where the vertex fetch reads the frame as it is.
std::string decodeText(const json& r, const std::string& pipeline) {
  const PipelineEntry* e = findPipeline(pipeline);
  if (!e) return "-";
  if (e->frame.decodeKernel.empty()) return "0 (" + e->frame.fetched + ")";
  return kernelText(r, e->frame.decodeKernel);
}

// Where the fragment shader shades from: the rotor (unpacked per fragment) or a normal and a tangent.
bool rotorPerFragment(const std::string& pipeline) {
  const PipelineEntry* e = findPipeline(pipeline);
  return e && e->frame.perFragment;
}

const json* rigidVariant(const json& r, const std::string& pipeline) {
  for (const json& v : at(r, {"opsPerVertex", "variants"}))
    if (v.value("pipeline", "") == pipeline && v.value("label", "") == "rigid") return &v;
  return nullptr;
}

// The worst PSNR over the frames drawing p's own vertex format: report.json's figure, marked.
std::string ownFormatPsnr(const json& r, const std::string& p) {
  const auto f = figures::figureNamed(r, "image.worst_psnr_own_format." + p);
  return f ? figureMark(f->name, figures::valueText(*f)) : "-";
}

// Frame time / the matrix pipeline: report.json's figure (the median over scenes of each scene's
// median of per-frame paired ratios), with its scene count in brackets.
std::string frameRatio(const json& r, const std::string& p, bool vertexBound) {
  const auto f = figures::figureNamed(r, std::string(vertexBound ? "frame_time_vertex_bound." : "frame_time.") + p + "_over_matrix");
  if (!f || f->n == 0) return "-";
  return fmt(f->value, 3) + " (" + std::to_string(f->n) + ")";
}

std::string isaText(const json& r, const std::string& p, const std::string& family,
                    const std::string& stage = "vertex") {
  const json* s = isaRow(at(r, {"isa"}), p, "rigid", family, stage);
  return s ? fmt((*s)["instructions"], 6) + " / " + fmt((*s)["vgprs"], 6) : "-";
}

// Where the frame is unpacked: the varyings the rigid program passes, the
// counted frame per fragment and the fragment shader's ISA.
void fragmentStageTable(Document& d, const json& r, const std::vector<std::string>& pipes,
                        const std::vector<std::string>& families) {
  d.paragraph("The frame per fragment: motor_cf passes the world tangent rotor (and the handedness in the "
              "position's w) and unpacks it in forward.fs; every other pipeline passes a normal and a tangent "
              "and re-orthogonalises them there. Varyings of the rigid program (the fragment shader's inputs "
              "in its SPIR-V: vec4 slots / components); the counted shading normal of a fragment with and without "
              "a normal map (shaders/frame_shading.glsl); AMD ISA instructions / VGPRs of the rigid program's fragment "
              "shader per family.");
  std::vector<std::string> head = {"pipeline", "varyings (slots / components)",
                                   "frame per fragment, normal-mapped (counted)", "no normal map (counted)"};
  for (const std::string& f : families) head.push_back("fragment ISA " + f);
  std::vector<std::vector<Cell>> rows;
  for (const std::string& p : pipes) {
    const json* v = families.empty() ? nullptr : isaRow(at(r, {"isa"}), p, "rigid", families.front());
    std::vector<Cell> row = {
        {p},
        {v && v->contains("varyingSlots") ? fmt((*v)["varyingSlots"], 3) + " / " + fmt((*v)["varyingComponents"], 3)
                                          : "-"},
        {kernelText(r, shadingNormalKernel(p, true))}, {kernelText(r, shadingNormalKernel(p, false))}};
    for (const std::string& f : families) row.push_back({isaText(r, p, f, "fragment")});
    rows.push_back(std::move(row));
  }
  d.table(head, rows);
}

}  // namespace

std::string shadingNormalKernel(const std::string& pipeline, bool normalMapped) {
  if (rotorPerFragment(pipeline)) return normalMapped ? "rotorShadingNormal" : "rotorSurfaceNormal";
  return normalMapped ? "tbnShadingNormal" : "tbnSurfaceNormal";
}

void compactSection(Document& d, const json& r) {
  d.heading(2, "Bytes vs image cost vs unpack cost", "compact");
  const std::vector<std::string> pipes =
      at(r, {"settings", "pipelines"}).is_array() ? r["settings"]["pipelines"].get<std::vector<std::string>>()
                                                  : std::vector<std::string>{};
  if (pipes.empty()) return;
  const json& sum = r["summary"];
  std::vector<std::string> families;
  for (const json& f : at(r, {"isa", "families"})) families.push_back(f.value("id", "?"));
  d.paragraph("Per glTF pipeline (`matrix_c`, `motor_c` and `motor_cf` are the 16-byte vertices): bytes per vertex of "
              "the normal-mapped primitives from the uploads (median over scenes); image difference against " +
              pipes.front() +
              " over the frames where both should agree and the pipeline draws its own vertex format (skinning-method "
              "frames and scenes of patches only left out): worst "
              "PSNR, largest share of pixels over 1/255 and 4/255, worst channel difference; counted ops of the "
              "frame decoding alone and of the rigid vertex shader (counted: the transform to clip; SPIR-V whole "
              "shader: the compiled shader with its main()); frame time / " +
              pipes.front() + " (median over scenes, their count in brackets; vertex-bound: the tiny viewport)" +
              (families.empty() ? "." : "; AMD ISA instructions / VGPRs of the rigid vertex shader per family."));
  std::vector<std::string> head = {"pipeline", "B/vertex (normal-mapped)", "worst PSNR", "px > 1/255", "px > 4/255",
                                   "worst pixel", "frame decode (counted)", "rigid vertex shader (counted to clip; SPIR-V whole shader)",
                                   "frame time", "vertex-bound frame time"};
  for (const std::string& f : families) head.push_back("ISA " + f);
  std::vector<std::vector<Cell>> rows;
  for (const std::string& p : pipes) {
    // Frames that draw the pipeline's own vertices (16 bytes for the compact ones), not the teapot's patches.
    const json& im = at(sum, {"vertexFormatImages", p.c_str()}).is_object() ? sum["vertexFormatImages"][p] : json();
    const bool base = p == pipes.front();
    const bool allIdentical = im.is_object() && im.value("comparedFrames", 0) > 0 &&
                              im.value("identicalFrames", 0) == im.value("comparedFrames", 0);
    const json* rigid = rigidVariant(r, p);
    std::vector<Cell> row = {
        {p},
        {fmt(at(sum, {"pipelines"}).is_object() && sum["pipelines"].contains(p)
                 ? at(sum["pipelines"][p], {"bytesPerVertexNormalMapped", "median"})
                 : json(),
             3)},
        {base ? "baseline" : allIdentical ? "identical" : ownFormatPsnr(r, p)},
        {base ? "-" : percent(at(im, {"fractionOver1", "max"}), 3)},
        {base ? "-" : percent(at(im, {"fractionOver4", "max"}), 3)},
        {base || !at(im, {"maxError", "max"}).is_number() ? "-"
                                                          : fmt(json(255.0 * im["maxError"]["max"].get<double>()), 3) + "/255"},
        {decodeText(r, p)},
        {rigid ? opsText((*rigid)["counted"]) + "; " + opsText((*rigid)["spirv"]) : "-"},
        {base ? "1" : frameRatio(r, p, false)},
        {base ? "1" : frameRatio(r, p, true)}};
    for (const std::string& f : families) row.push_back({isaText(r, p, f)});
    rows.push_back(std::move(row));
  }
  d.table(head, rows);
  fragmentStageTable(d, r, pipes, families);
}

}  // namespace mb::document
