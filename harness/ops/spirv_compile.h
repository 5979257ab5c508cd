// GLSL -> SPIR-V, spirv-opt passes and disassembly inside this process, through the libraries
// glslangValidator, spirv-opt and spirv-dis are built from (Debian's glslang-dev and spirv-tools,
// the same versions as glslang-tools' and spirv-tools' commands). A command costs ~0.25 s of CPU
// per shader before it compiles anything (glslang builds its built-in symbol tables at every
// start); here they are built once per process, so a cold SPIR-V cache fills in seconds instead
// of minutes (`motorbench ops` with an empty cache took 102 s with one command per shader).
// Each function sets exactly what its command sets for the flags it takes, so the output is the
// commands' byte for byte (tests/ops/test_spirv_compile.cpp compares them when the commands are
// installed).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "pipelines/result.h"

namespace mb::spirv {

// `glslangValidator <flags> -S <stage> -o out.spv shader.<stage>`: `stage` "vert" or "frag";
// `flags` a subset of -G (OpenGL SPIR-V), -V (Vulkan SPIR-V), -R (relaxed Vulkan rules),
// --aml, --amb, --rsb <set>. Anything else is refused. Errors carry glslang's log; `name`
// labels them.
Result<std::vector<uint32_t>> compileGlsl(const std::string& source, const std::string& stage,
                                          const std::string& flags, const std::string& name);

// `spirv-opt <passes> in.spv -o out.spv`: `passes` as on its command line ("-O", or "--pass"
// and "--pass=arg" words), the same default target environment and validation.
Result<std::vector<uint32_t>> optimiseSpirv(const std::vector<uint32_t>& words, const std::string& passes,
                                            const std::string& name);

// `spirv-dis --no-color -o out.spvasm in.spv`: the text the command writes to a file.
Result<std::string> disassembleSpirv(const std::vector<uint32_t>& words, const std::string& name);

// The versions of both libraries ("glslang 12.0.0; SPIRV-Tools v2023.1 ..."): part of every
// SPIR-V cache key (spirv_cache.h).
std::string toolchainVersion();

}  // namespace mb::spirv
