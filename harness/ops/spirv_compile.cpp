#include "harness/ops/spirv_compile.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <glslang/build_info.h>
#include <spirv-tools/libspirv.h>
#include <spirv-tools/optimizer.hpp>

#include <mutex>
#include <sstream>

namespace mb::spirv {
namespace {

// The part of glslangValidator's command line motorbench uses (StandAlone.cpp of glslang 12:
// -G/-V pick the client and its default version, -V adds the Vulkan rules, -R relaxes them).
struct GlslOptions {
  bool opengl = false, vulkan = false, relaxed = false, autoLocations = false, autoBindings = false;
  std::vector<std::string> resourceSetBinding;  // --rsb <set>: every stage's resources in <set>
};

Result<GlslOptions> parseFlags(const std::string& flags) {
  GlslOptions o;
  std::istringstream in(flags);
  for (std::string w; in >> w;) {
    if (w == "-G") o.opengl = true;
    else if (w == "-V") o.vulkan = true;
    else if (w == "-R") o.relaxed = true;
    else if (w == "--aml") o.autoLocations = true;
    else if (w == "--amb") o.autoBindings = true;
    else if (w == "--rsb" && in >> w) o.resourceSetBinding = {w};
    else return Result<GlslOptions>::fail("glslang flags '" + flags + "': '" + w + "' is not supported here");
  }
  if (o.opengl == o.vulkan) return Result<GlslOptions>::fail("glslang flags '" + flags + "': give one of -G and -V");
  return o;
}

std::vector<std::string> words(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

}  // namespace

Result<std::vector<uint32_t>> compileGlsl(const std::string& source, const std::string& stage,
                                          const std::string& flags, const std::string& name) {
  using R = Result<std::vector<uint32_t>>;
  auto o = parseFlags(flags);
  if (!o) return R::fail(name + ": " + o.error());
  if (stage != "vert" && stage != "frag") return R::fail(name + ": stage '" + stage + "' is not vert or frag");
  const EShLanguage lang = stage == "vert" ? EShLangVertex : EShLangFragment;
  static std::once_flag initialised;
  std::call_once(initialised, [] { glslang::InitializeProcess(); });

  glslang::TShader shader(lang);
  const char* text = source.c_str();
  const std::string file = "shader." + stage;
  const char* fileName = file.c_str();
  shader.setStringsWithLengthsAndNames(&text, nullptr, &fileName, 1);
  shader.setResourceSetBinding(o->resourceSetBinding);
  if (o->autoBindings) shader.setAutoMapBindings(true);
  if (o->autoLocations) shader.setAutoMapLocations(true);
  const glslang::EShClient client = o->vulkan ? glslang::EShClientVulkan : glslang::EShClientOpenGL;
  shader.setEnvInput(glslang::EShSourceGlsl, lang, client, 100);
  shader.setEnvClient(client, o->vulkan ? glslang::EShTargetVulkan_1_0 : glslang::EShTargetOpenGL_450);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
  if (o->relaxed) shader.setEnvInputVulkanRulesRelaxed();
  const EShMessages messages = EShMessages(int(EShMsgSpvRules) | (o->vulkan ? int(EShMsgVulkanRules) : 0));
  glslang::TShader::ForbidIncluder noIncludes;  // the text arrives with its #includes expanded
  if (!shader.parse(GetDefaultResources(), 100, false, messages, noIncludes))
    return R::fail(name + ": glslang failed:\n" + shader.getInfoLog() + shader.getInfoDebugLog());
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages) || !program.mapIO())
    return R::fail(name + ": glslang could not link the stage:\n" + program.getInfoLog());
  std::vector<unsigned int> spirv;
  spv::SpvBuildLogger logger;
  glslang::SpvOptions options;  // glslangValidator's defaults without -g, -Od or -Os
  glslang::GlslangToSpv(*program.getIntermediate(lang), spirv, &logger, &options);
  if (spirv.empty()) return R::fail(name + ": glslang wrote no SPIR-V:\n" + logger.getAllMessages());
  return std::vector<uint32_t>(spirv.begin(), spirv.end());
}

Result<std::vector<uint32_t>> optimiseSpirv(const std::vector<uint32_t>& words_, const std::string& passes,
                                            const std::string& name) {
  using R = Result<std::vector<uint32_t>>;
  spvtools::Optimizer optimizer(SPV_ENV_UNIVERSAL_1_6);  // spirv-opt's default environment
  std::string log;
  optimizer.SetMessageConsumer([&log](spv_message_level_t, const char*, const spv_position_t&, const char* m) {
    log += std::string(m) + "\n";
  });
  if (!optimizer.RegisterPassesFromFlags(words(passes))) return R::fail(name + ": spirv-opt passes refused:\n" + log);
  std::vector<uint32_t> out;
  if (!optimizer.Run(words_.data(), words_.size(), &out, spvtools::OptimizerOptions()))
    return R::fail(name + ": spirv-opt failed:\n" + log);
  return out;
}

Result<std::string> disassembleSpirv(const std::vector<uint32_t>& words_, const std::string& name) {
  // spirv-dis's defaults when writing a file: indented, friendly names, the header, no colour.
  spv_context context = spvContextCreate(SPV_ENV_UNIVERSAL_1_5);
  spv_text text = nullptr;
  spv_diagnostic diagnostic = nullptr;
  const uint32_t options = SPV_BINARY_TO_TEXT_OPTION_INDENT | SPV_BINARY_TO_TEXT_OPTION_FRIENDLY_NAMES;
  const spv_result_t rc = spvBinaryToText(context, words_.data(), words_.size(), options, &text, &diagnostic);
  spvContextDestroy(context);
  std::string out, why = diagnostic && diagnostic->error ? diagnostic->error : "";
  if (rc == SPV_SUCCESS && text) out.assign(text->str, text->length);
  spvTextDestroy(text);
  spvDiagnosticDestroy(diagnostic);
  if (rc != SPV_SUCCESS) return Result<std::string>::fail(name + ": spirv-dis failed: " + why);
  return out;
}

std::string toolchainVersion() {
  return "glslang " + std::to_string(GLSLANG_VERSION_MAJOR) + "." + std::to_string(GLSLANG_VERSION_MINOR) + "." +
         std::to_string(GLSLANG_VERSION_PATCH) + GLSLANG_VERSION_FLAVOR + "; " + spvSoftwareVersionDetailsString();
}

}  // namespace mb::spirv
