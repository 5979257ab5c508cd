#include "harness/document/report_morph.h"

#include <cstdio>
#include <filesystem>

#include "harness/document/report_format.h"
#include "harness/document/report_isa.h"
#include "harness/figures/figure.h"

namespace mb::document {
namespace {

using nlohmann::json;

// The method's own counted kernel in report.json's ops (motor methods; matrix adds deltas only).
const char* methodKernel(const std::string& id) {
  if (id == "motor_frame") return "morphRotorFrame";
  if (id == "motor_rotor") return "morphRotorBlend";
  return nullptr;
}

const json* opsRow(const json& r, const char* list, const char* key, const std::string& pipeline,
                   const std::string& value) {
  const json& rows = at(r, {"opsPerVertex", list});  // by reference: the row outlives the loop
  if (!rows.is_array()) return nullptr;
  for (const json& v : rows)
    if (v.value("pipeline", "") == pipeline && v.value(key, "") == value) return &v;
  return nullptr;
}

const json* kernelRow(const json& r, const char* function) {
  const json& ks = at(r, {"opsPerVertex", "kernels"});
  if (!ks.is_array()) return nullptr;
  for (const json& k : ks)
    if (k.value("function", "") == function) return &k;
  return nullptr;
}

std::string figure(const json& morph, const std::string& name) {
  auto f = figures::figureNamed(morph, name);
  return f ? figures::valueText(*f) : "-";
}

std::string worstFrame(const json& morph, const std::string& name) {
  const json& w = at(morph, {"worst"});
  if (!w.is_object() || !w.contains(name) || w[name].is_null()) return "-";
  char t[32];
  std::snprintf(t, sizeof t, "%.3g", w[name].value("time", 0.0));
  const int anim = w[name].value("anim", -1);
  return std::filesystem::path(w[name].value("scene", "?")).filename().string() +
         (anim < 0 ? " at rest" : " anim " + std::to_string(anim) + " t " + t);
}

std::string isaCell(const json& r, const std::string& pipeline, const std::string& label, const std::string& family) {
  const json& isa = at(r, {"isa"});
  const json* m = isaRow(isa, pipeline, label, family);
  const json* rigid = isaRow(isa, pipeline, "rigid", family);
  if (!m) return "-";
  return fmt((*m)["instructions"], 6) + " / " + fmt((*m)["vgprs"], 6) +
         (rigid ? " (rigid " + fmt((*rigid)["instructions"], 6) + " / " + fmt((*rigid)["vgprs"], 6) + ")" : "");
}

// Where each method stops being exact: from the math of shaders/motor_transform.glsl (the
// measured side is the worst-frame column and tests/pipelines' angle test).
std::string breaksText(const std::string& id) {
  if (id == "motor_frame")
    return "re-forms the rotor from the morphed normal and tangent, matrix's frame (its image cost: the worst "
           "PSNR and max error columns); undefined only where the morphed normal vanishes or the morphed tangent "
           "is parallel to it, as for matrix";
  if (id == "motor_rotor")
    return "exact only at weights 0 and 1 of a single target: a linear blend of rotors turns the frame by "
           "2 atan2(w sin(t/2), 1-w+w cos(t/2)) instead of atan2(w sin t, 1-w+w cos t), far apart at large "
           "base-to-target turns t";
  return "the reference (glTF's sums)";
}

// "57.8 dB worst PSNR and 0.216 of 1 max error over 20 frames": the method's rigid figures, marked.
std::string worstText(const json& morph, const std::string& id) {
  const auto psnr = figures::figureNamed(morph, "morph.worst_psnr.rigid." + id);
  const auto error = figures::figureNamed(morph, "morph.max_error.rigid." + id);
  if (!psnr || !error) return "no figure (not measured)";
  return figureMark(psnr->name, figures::valueText(*psnr)) + " worst PSNR and " +
         figureMark(error->name, figures::valueText(*error)) + " max error over " + std::to_string(psnr->n) + " frames";
}

}  // namespace

std::vector<std::string> morphIsaFamilies(const json& r) {
  const json& fams = at(r, {"isa", "families"});
  if (!fams.is_array() || fams.empty()) return {};
  std::vector<std::string> out = {fams.front().value("id", "")};
  if (fams.size() > 1) out.push_back(fams.back().value("id", ""));
  return out;
}

std::vector<std::vector<std::string>> morphTable(const json& r) {
  const json morph = r.contains("morph") && r["morph"].is_object() ? r["morph"] : json::object();
  const std::vector<std::string> families = morphIsaFamilies(r);
  std::vector<std::string> header = {"method", "bytes per vertex", "bytes per target vertex",
                                     "counted ops (method kernel per vertex; + per target)",
                                     "SPIR-V whole shader (rigid)"};
  for (const std::string& f : families) header.push_back("ISA " + f + " instr / VGPRs (rigid)");
  header.insert(header.end(), {"worst PSNR vs matrix (unskinned)", "max error", "worst frame",
                               "worst PSNR vs skin reference (skinned)", "where it breaks"});
  std::vector<std::vector<std::string>> rows = {header};
  for (const json& m : morph.value("methods", json::array())) {
    const std::string id = m.value("id", ""), pipeline = m.value("pipeline", ""), label = m.value("program", "");
    std::vector<std::string> row = {id + (morph.value("motorDefault", json()) == json(id) ? " (motor default)" : "") +
                                        ": " + m.value("method", "")};
    row.push_back(figure(morph, "morph.bytes_per_vertex." + id));
    row.push_back(figure(morph, "morph.bytes_per_target_vertex." + id));
    // Per target: morph.glsl's 1 mul + 1 add per delta float (bytes per target vertex / 4).
    std::string ops;
    if (const char* k = methodKernel(id)) {
      const json* row = kernelRow(r, k);
      ops = row ? opsText((*row)["counted"]) : "-";
    } else {
      ops = "none";
    }
    if (auto b = figures::figureNamed(morph, "morph.bytes_per_target_vertex." + id); b && b->value == b->value)
      ops += "; + " + fmt(b->value / 4, 3) + " mul + " + fmt(b->value / 4, 3) + " add per target";
    row.push_back(ops);
    const json* sv = opsRow(r, "variants", "label", pipeline, label);
    const json* rv = opsRow(r, "variants", "label", pipeline, "rigid");
    row.push_back((sv && !(*sv)["spirv"].is_null() ? opsText((*sv)["spirv"]) : "-") +
                  (rv && !(*rv)["spirv"].is_null() ? " (" + opsText((*rv)["spirv"]) + ")" : ""));
    for (const std::string& f : families) row.push_back(isaCell(r, pipeline, label, f));
    const bool motor = id != "matrix";
    row.push_back(motor ? figure(morph, "morph.worst_psnr.rigid." + id) : "baseline");
    row.push_back(motor ? figure(morph, "morph.max_error.rigid." + id) : "-");
    row.push_back(motor ? worstFrame(morph, "morph.worst_psnr.rigid." + id) : "-");
    row.push_back(figure(morph, "morph.worst_psnr.skinned." + id));
    row.push_back(breaksText(id));
    rows.push_back(std::move(row));
  }
  return rows;
}

void morphSection(Document& d, const json& r) {
  d.heading(2, "Morph targets: the tangent rotor under blend shapes", "morph");
  if (!r.contains("morph") || !r["morph"].is_object()) {
    d.paragraph("Not measured in this report: run `motorbench morph SCENES --json FILE` and give the file to "
                "`motorbench report --morph-json FILE`.");
    return;
  }
  const json& morph = r["morph"];
  int scenes = 0, frames = 0;
  for (const json& s : morph.value("scenes", json::array()))
    if (!s.contains("error")) ++scenes, frames += int(s.value("frames", json::array()).size());
  const std::string def = morph.value("motorDefault", json()).is_string() ? morph["motorDefault"].get<std::string>()
                                                                           : std::string("unknown");
  d.paragraph(
      "glTF's morph deltas are position, normal and tangent deltas; the motor vertex carries a tangent rotor. "
      "Each method on " + std::to_string(scenes) + " scene(s), " + std::to_string(frames) + " frames (rest and "
      "each animation at 1/4, 1/2, 3/4), " + fmt(morph.value("size", 0), 6) + " px (`motorbench morph`). "
      "Bytes from the uploads; ops: the method's own counted kernel per morphing vertex plus morph.glsl's "
      "delta sums per target with a non-zero weight; SPIR-V and ISA of the morphing rigid vertex shader "
      "(two targets) beside the rigid one. The motor pipelines morph with " + def +
      " by default (measured: the default upload's bytes per target vertex): against matrix its worst frame reads " +
      worstText(morph, def) + ", while the rotor deltas save bytes per target but are not the rotor of the blended "
      "frame.");
  const auto rows = morphTable(r);
  std::vector<std::vector<Cell>> cells;
  for (size_t i = 1; i < rows.size(); ++i) {
    std::vector<Cell> row;
    for (const std::string& c : rows[i]) row.push_back({c});
    cells.push_back(std::move(row));
  }
  d.table(rows.front(), cells);
  std::vector<std::string> notes;
  for (const char* name : {"morph.worst_psnr.rigid.motor_frame", "morph.worst_psnr.rigid.motor_rotor",
                           "morph.worst_psnr.skinned.motor_frame"})
    if (auto f = figures::figureNamed(morph, name)) notes.push_back(name + std::string(": ") + figures::figureText(*f));
  for (const json& s : morph.value("scenes", json::array()))
    if (s.contains("error")) notes.push_back(s.value("scene", "?") + ": not measured: " + s.value("error", ""));
  d.bullets(notes);
}

}  // namespace mb::document
