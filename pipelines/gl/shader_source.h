// GLSL source assembly: `#include "file"` expansion, `#define` variants, and mapping of the
// driver's line numbers back to files. Pure text (no GL), so it is unit-testable on its own.
//
// Expansion rules:
//  - The top file must start (after comments/blank lines) with `#version`; the defines are
//    injected right after it, then a `#line` directive restores the file's numbering.
//  - `#include "name"` is resolved relative to the including file's folder, then the shader
//    directory. Each file is expanded at most once per program stage (like #pragma once); an
//    include cycle is an error naming the chain. Includes are textual and unconditional (they
//    are expanded before the GLSL preprocessor runs, even inside #if blocks).
//  - Every file gets a GLSL source-string number (0 = top file, 1.. = includes in order of
//    first inclusion); `#line L N` directives around each include let the driver report
//    positions as N:L, which mapLog() turns back into file:line.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "pipelines/result.h"

namespace mb::gl {

using Defines = std::vector<std::pair<std::string, std::string>>;  // name, value ("" = none)

struct ExpandedSource {
  std::string text;                // what glShaderSource receives
  std::vector<std::string> files;  // files[n] = path of GLSL source-string number n
};

// The shader folder: $MB_SHADER_DIR when set, else the repository's shaders/ (compiled in).
std::string shaderDir();

// `path` is absolute, or relative to shaderDir(). Errors name the file (and the including
// file:line for a missing include).
Result<ExpandedSource> expandShaderFile(const std::string& path, const Defines& defines = {});

// Rewrites a compile log so positions read "file:line:" instead of "N:L(C):" (Mesa) or
// "N(L) :" (NVIDIA style). Lines it cannot map are kept as they are.
std::string mapLog(const std::string& log, const std::vector<std::string>& files);

}  // namespace mb::gl
