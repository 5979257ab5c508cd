#include "harness/isa/programs.h"

#include <cctype>
#include <map>
#include <tuple>

#include "harness/ops/ops_vertex.h"
#include "harness/ops/spirv_count.h"

namespace mb::isa {

std::string programId(const std::string& label) {
  std::string id;
  for (char c : label) {
    if (std::isalnum(static_cast<unsigned char>(c))) id += char(std::tolower(static_cast<unsigned char>(c)));
    else if (!id.empty() && id.back() != '_') id += '_';
  }
  while (!id.empty() && id.back() == '_') id.pop_back();
  if (id.rfind("bezier_patch", 0) == 0) id = "patch" + id.substr(12);
  if (id == "s3_instance" || id == "h3_instance") id = "curved";
  return id;
}

std::vector<std::string> defineList(const gl::Defines& d) {
  std::vector<std::string> out;
  for (const auto& [name, value] : d) out.push_back(value.empty() ? name : name + "=" + value);
  return out;
}

std::vector<Program> allPrograms() {
  std::vector<Program> out;
  std::map<std::tuple<std::string, std::string, std::vector<std::string>>, size_t> seen;
  for (const opsv::ShaderVariant& v : opsv::shaderVariants()) {
    auto [it, fresh] = seen.try_emplace({v.pipeline, v.file, defineList(v.defines)}, out.size());
    if (!fresh) {
      out[it->second].labels.push_back(v.label);
      continue;
    }
    out.push_back({v.pipeline, programId(v.label), v.label, {v.label}, v.file, v.fragment, v.defines});
  }
  return out;
}

Result<CompiledProgram> compileProgram(const Program& p) {
  using R = Result<CompiledProgram>;
  CompiledProgram c;
  struct Stage { const std::string& file; const char* stage; const char* flags; StageModule& out; };
  for (Stage s : {Stage{p.vertexFile, "vert", "-V -R --aml --amb", c.vertex},
                  Stage{p.fragmentFile, "frag", "-V -R --aml --amb --rsb 1", c.fragment}}) {
    auto expanded = gl::expandShaderFile(s.file, p.defines);
    if (!expanded) return R::fail(expanded.error());
    const std::string name = s.file + " (" + p.pipeline + " " + p.program + ")";
    auto words = spirv::compileToBinary(expanded->text, s.stage, s.flags, name);
    if (!words) return R::fail(words.error());
    auto iface = readInterface(*words, name);
    if (!iface) return R::fail(iface.error());
    s.out.spirv = words.take();
    s.out.interface = iface.take();
  }
  return c;
}

}  // namespace mb::isa
