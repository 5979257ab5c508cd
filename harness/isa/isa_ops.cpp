#include "harness/isa/isa_ops.h"

#include <cstdio>

namespace mb::isa {

const ShaderStats* vertexRow(const IsaRun& run, const opsv::ShaderVariant& v, size_t family) {
  for (const ShaderStats& s : run.shaders) {
    const Program& p = run.programs[s.program];
    if (s.family == family && s.exe.stage == "vertex" && p.pipeline == v.pipeline &&
        p.vertexFile == v.file && p.defines == v.defines)
      return &s;
  }
  return nullptr;
}

std::string formatIsaBesideOps(const opsv::VertexOps& ops, const IsaRun& run) {
  std::string out = "\nWhole vertex-shader variants: counted and SPIR-V ops (mul/add/div/sqrt/other) beside\n"
                    "AMD ISA instructions/VGPRs, compiled by " + run.driver +
                    " RADV on its null device (motorbench isa):\n\n";
  char buf[256];
  std::snprintf(buf, sizeof buf, "%-9s %-34s %-14s %-14s", "pipeline", "variant", "counted", "SPIR-V");
  out += buf;
  for (const FamilyRun& f : run.families) {
    std::snprintf(buf, sizeof buf, " %13s", f.family.id().c_str());
    out += buf;
  }
  out += "\n";
  for (const opsv::VariantRow& v : ops.variants) {
    const OpCounts& c = v.counted;
    const std::string counted = std::to_string(c.mul) + "/" + std::to_string(c.add) + "/" +
                                std::to_string(c.div) + "/" + std::to_string(c.sqrt) + "/" + std::to_string(c.other);
    std::snprintf(buf, sizeof buf, "%-9s %-34s %-14s %-14s", v.variant.pipeline.c_str(), v.variant.label.c_str(),
                  counted.c_str(), v.shader ? spirv::shortText(*v.shader).c_str() : "-");
    out += buf;
    for (size_t f = 0; f < run.families.size(); ++f) {
      const ShaderStats* s = vertexRow(run, v.variant, f);
      const std::string cell = s ? std::to_string(s->stat("Instructions")) + "/" + std::to_string(s->stat("VGPRs")) : "-";
      std::snprintf(buf, sizeof buf, " %13s", cell.c_str());
      out += buf;
    }
    out += "\n";
  }
  return out;
}

nlohmann::json isaBesideOpsJson(const opsv::VertexOps& ops, const IsaRun& run) {
  nlohmann::json families = nlohmann::json::array(), variants = nlohmann::json::array();
  for (const FamilyRun& f : run.families) families.push_back(f.family.id());
  for (const opsv::VariantRow& v : ops.variants) {
    nlohmann::json per = nlohmann::json::object();
    for (size_t f = 0; f < run.families.size(); ++f)
      if (const ShaderStats* s = vertexRow(run, v.variant, f))
        per[run.families[f].family.id()] = {{"instructions", s->stat("Instructions")}, {"vgprs", s->stat("VGPRs")},
                                            {"wavesPerSimd", s->wavesPerSimd(run.families[f].family)}};
    variants.push_back({{"pipeline", v.variant.pipeline}, {"variant", v.variant.label}, {"perFamily", per}});
  }
  return {{"driver", run.driver}, {"families", families}, {"variants", variants}};
}

}  // namespace mb::isa
