#include "harness/isa/isa_output.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace mb::isa {
namespace {

using nlohmann::json;

// The fixed keys of a shader row and the RADV statistic each comes from.
const std::pair<const char*, const char*> kStatKeys[] = {
    {"instructions", "Instructions"},   {"vgprs", "VGPRs"},
    {"sgprs", "SGPRs"},                 {"spilledVgprs", "Spilled VGPRs"},
    {"spilledSgprs", "Spilled SGPRs"},  {"codeSizeBytes", "Code size"},
    {"ldsBytes", "LDS size"},           {"scratchBytes", "Scratch size"},
    {"latency", "Latency"},             {"inverseThroughput", "Inverse Throughput"},
    {"subgroupsPerSimd", "Subgroups per SIMD"},
};

json statisticsObject(const ExecutableStats& e) {
  json s = json::object();
  for (const auto& [k, v] : e.statistics) s[k] = v;
  return s;
}

json programKeys(const Program& p, const std::string& stage) {
  return {{"pipeline", p.pipeline}, {"program", p.program}, {"variant", p.variant},
          {"labels", p.labels}, {"stage", stage},
          {"source", "shaders/" + (stage == "fragment" ? p.fragmentFile : p.vertexFile)},
          {"defines", defineList(p.defines)}, {"varyingSlots", p.varyingSlots},
          {"varyingComponents", p.varyingComponents}};
}

std::string cell(const ShaderStats& s) {
  return std::to_string(s.stat("Instructions")) + "/" + std::to_string(s.stat("VGPRs"));
}

}  // namespace

json toJson(const IsaRun& run) {
  json families = json::array(), shaders = json::array();
  for (const FamilyRun& f : run.families) {
    json row = {{"family", f.family.name}, {"id", f.family.id()}, {"ngg", f.family.ngg},
                {"generation", generationName(f.family.generation)}, {"device", f.device}};
    for (const ShaderStats& s : run.shaders)
      if (&run.families[s.family] == &f) {
        row[s.exe.stage == "vertex" ? "waveSize" : "fragmentWaveSize"] = s.exe.subgroupSize;
      }
    families.push_back(row);
  }
  for (const ShaderStats& s : run.shaders) {
    const Family& f = run.families[s.family].family;
    json row = programKeys(run.programs[s.program], s.exe.stage);
    row["family"] = f.name;
    row["familyId"] = f.id();
    row["ngg"] = f.ngg;
    row["generation"] = generationName(f.generation);
    row["waveSize"] = s.exe.subgroupSize;
    for (const auto& [key, stat] : kStatKeys) row[key] = s.stat(stat);
    row["wavesPerSimd"] = s.wavesPerSimd(f);
    row["statistics"] = statisticsObject(s.exe);
    shaders.push_back(row);
  }
  json out = {{"schema", "motorbench-isa/1"},
              {"tool", "motorbench isa"},
              {"driver", run.driver},
              {"method",
               "each program's GLSL (same files, #includes and #defines as the GL pipelines) compiled "
               "with glslangValidator -V -R --aml --amb, built as a Vulkan graphics pipeline on RADV's "
               "null device (RADV_FORCE_FAMILY) with VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR; "
               "statistics from VK_KHR_pipeline_executable_properties. ngg: NGG culling on. "
               "wavesPerSimd: waves of the compiled wave size per SIMD by harness/isa/families.h's "
               "rule; subgroupsPerSimd: RADV's own figure (RDNA: in units of 32 lanes)"},
              {"families", families},
              {"shaders", shaders}};
  if (run.deviceAsked) {
    json devices = json::array();
    for (const DeviceRun& d : run.devices) {
      json rows = json::array();
      for (const ShaderStats& s : d.shaders) {
        json row = programKeys(run.programs[s.program], s.exe.stage);
        row["subgroupSize"] = s.exe.subgroupSize;
        row["statistics"] = statisticsObject(s.exe);
        rows.push_back(row);
      }
      devices.push_back({{"device", d.device}, {"driver", d.driver}, {"shaders", rows}});
    }
    out["device"] = {{"seen", run.deviceNote}, {"devices", devices}};
  }
  return out;
}

std::string formatTable(const IsaRun& run) {
  std::string out;
  auto line = [&](const char* fmt, auto... a) {
    char buf[512];
    std::snprintf(buf, sizeof buf, fmt, a...);
    out += buf;
  };
  out += "AMD ISA per shader, compiled by Mesa " + run.driver.substr(run.driver.find(' ') + 1) +
         " RADV (ACO) on its null device; each cell: instructions/VGPRs.\n"
         "GLSL as the GL pipelines load it, via glslangValidator -V -R (Vulkan SPIR-V).\n";
  out += "Families:";
  for (const FamilyRun& f : run.families)
    out += " " + f.family.id() + " (" + generationName(f.family.generation) + ")";
  out += "\n";
  for (const char* stage : {"vertex", "fragment"}) {
    line("\n%s shaders\n%-10s %-34s", stage, "pipeline", "program");
    for (const FamilyRun& f : run.families) line(" %13s", f.family.id().c_str());
    out += "\n";
    for (size_t p = 0; p < run.programs.size(); ++p) {
      std::string row;
      for (const ShaderStats& s : run.shaders)
        if (s.program == p && s.exe.stage == stage) {
          char c[32];
          std::snprintf(c, sizeof c, " %13s", cell(s).c_str());
          row += c;
        }
      if (row.empty()) continue;
      line("%-10s %-34s", run.programs[p].pipeline.c_str(), run.programs[p].program.c_str());
      out += row + "\n";
    }
  }
  out += "\nwaves per SIMD (vertex shaders, our rule; harness/isa/families.h):\n";
  line("%-10s %-34s", "pipeline", "program");
  for (const FamilyRun& f : run.families) line(" %13s", f.family.id().c_str());
  out += "\n";
  for (size_t p = 0; p < run.programs.size(); ++p) {
    line("%-10s %-34s", run.programs[p].pipeline.c_str(), run.programs[p].program.c_str());
    for (const ShaderStats& s : run.shaders)
      if (s.program == p && s.exe.stage == "vertex")
        line(" %10d w%-2u", s.wavesPerSimd(run.families[s.family].family), s.exe.subgroupSize);
    out += "\n";
  }
  if (run.deviceAsked) {
    if (run.devices.empty())
      out += "\n--device: no Vulkan driver for real hardware exposes VK_KHR_pipeline_executable_properties "
             "here (seen: " + run.deviceNote + ")\n";
    for (const DeviceRun& d : run.devices) {
      out += "\n--device " + d.device + " (" + d.driver + "), vertex shaders:\n";
      for (const ShaderStats& s : d.shaders) {
        if (s.exe.stage != "vertex") continue;
        std::string stats;
        for (const auto& [k, v] : s.exe.statistics) stats += "  " + k + " " + v.dump();
        line("%-10s %-34s", run.programs[s.program].pipeline.c_str(), run.programs[s.program].program.c_str());
        out += stats + "\n";
      }
    }
  }
  return out;
}

Status writeIsaText(const IsaRun& run, const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return Status::fail(dir + ": cannot create the folder (" + ec.message() + ")");
  for (const ShaderStats& s : run.shaders) {
    const Program& p = run.programs[s.program];
    const FamilyRun& f = run.families[s.family];
    const std::string path = dir + "/" + p.pipeline + "." + p.program + "." + s.exe.stage + "." + f.family.id() + ".txt";
    std::ofstream out(path, std::ios::binary);
    out << "// " << p.pipeline << " " << p.program << " (" << p.variant << "), " << s.exe.stage << " shader, "
        << "shaders/" << (s.exe.stage == "vertex" ? p.vertexFile : p.fragmentFile);
    for (const std::string& d : defineList(p.defines)) out << " -D" << d;
    out << "\n// " << f.device << ", " << run.driver << ", wave" << s.exe.subgroupSize << "\n";
    for (const auto& [k, v] : s.exe.statistics) out << "// " << k << ": " << v.dump() << "\n";
    out << (s.exe.isaText.empty() ? "// (the driver gave no ISA text)\n" : s.exe.isaText);
    if (!out) return Status::fail(path + ": cannot write");
  }
  return {};
}

}  // namespace mb::isa
