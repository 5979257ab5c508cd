#include "harness/document/report_isa.h"

#include <algorithm>
#include <set>

#include "harness/document/report_format.h"

namespace mb::document {

using nlohmann::json;

const json* isaRow(const json& isa, const std::string& pipeline, const std::string& label,
                   const std::string& family, const std::string& stage) {
  if (!isa.contains("shaders") || !isa["shaders"].is_array()) return nullptr;
  for (const json& s : isa["shaders"]) {  // by reference: the row outlives the loop
    if (s.value("stage", "") != stage || s.value("pipeline", "") != pipeline ||
        s.value("familyId", "") != family)
      continue;
    const json labels = s.value("labels", json::array({s.value("variant", "")}));
    if (std::find(labels.begin(), labels.end(), json(label)) != labels.end()) return &s;
  }
  return nullptr;
}

void isaSection(Document& d, const json& r) {
  d.heading(2, "AMD ISA per vertex shader (RADV)", "isa");
  const json& isa = r.contains("isa") ? r["isa"] : json();
  if (!isa.is_object() || !isa.contains("shaders")) {
    d.paragraph("Not measured in this report: run `motorbench isa --json FILE` and give the file to "
                "`motorbench report --isa-json FILE`.");
    return;
  }
  std::vector<std::string> families;
  for (const json& f : isa.value("families", json::array()))
    families.push_back(f.value("id", "?") + " (" + f.value("generation", "?") + ")");
  d.paragraph("Each pipeline's vertex-shader variants as the GL pipelines load them, compiled by " +
              isa.value("driver", std::string("Mesa")) +
              " RADV (ACO) on its null device (no AMD hardware: statistics of the compiler, not timings). "
              "Per family: ISA instructions / VGPRs / waves per SIMD (our occupancy rule from the "
              "register counts, harness/isa/families.h; it agrees with RADV's own figure). navi21 is "
              "compiled with NGG culling off (nonggc) and on (its default), which adds the culling code "
              "to every vertex shader. Counted and SPIR-V ops (mul/add) as in the ops section.");
  const json& ops = r["opsPerVertex"];
  std::vector<std::string> pipelines;
  for (const json& v : ops.value("variants", json::array()))
    if (std::find(pipelines.begin(), pipelines.end(), v.value("pipeline", "")) == pipelines.end())
      pipelines.push_back(v.value("pipeline", ""));
  std::vector<std::string> header = {"variant", "counted", "SPIR-V"};
  for (const std::string& f : families) header.push_back(f);
  for (const std::string& p : pipelines) {
    std::vector<std::vector<Cell>> rows;
    for (const json& v : ops.value("variants", json::array())) {
      if (v.value("pipeline", "") != p) continue;
      std::vector<Cell> row = {{v.value("label", "")}, {opsText(v["counted"])}, {opsText(v["spirv"])}};
      for (const json& f : isa.value("families", json::array())) {
        const json* s = isaRow(isa, p, v.value("label", ""), f.value("id", ""));
        row.push_back({s ? fmt((*s)["instructions"], 6) + " / " + fmt((*s)["vgprs"], 6) + " / " +
                               fmt((*s)["wavesPerSimd"], 6) + "w"
                         : "-"});
      }
      rows.push_back(std::move(row));
    }
    d.heading(3, "ISA: " + p);
    d.table(header, rows);
  }
}

}  // namespace mb::document
