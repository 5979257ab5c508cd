#include "pipelines/gl/shader_source.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace mb::gl {
namespace fs = std::filesystem;

namespace {

// The lines of `in` without their "\n" or "\r\n".
std::vector<std::string> splitLines(std::istream& in) {
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

// The lines of file `p`; false when it cannot be opened.
bool readLines(const fs::path& p, std::vector<std::string>& lines) {
  std::ifstream in(p, std::ios::binary);
  lines = splitLines(in);
  return in.is_open();
}

// The quoted name of an `#include "name"` line, or "" when the line is no include.
std::string includeTarget(const std::string& line) {
  static const std::regex re(R"(^\s*#\s*include\s+"([^"]+)\"\s*(//.*)?$)");
  std::smatch m;
  return std::regex_match(line, m, re) ? m[1].str() : "";
}

bool isVersionLine(const std::string& line) {
  static const std::regex re(R"(^\s*#\s*version\b.*)");
  return std::regex_match(line, re);
}

struct Expander {
  ExpandedSource out;
  std::vector<std::string> stack;  // files being expanded, for cycle detection
  std::string error;

  // Appends the body of `file` (source-string number `id`, already read as `lines`) starting at
  // its line `first` (0-based).
  bool expand(const std::string& file, size_t id, const std::vector<std::string>& lines, size_t first) {
    stack.push_back(file);
    for (size_t i = first; i < lines.size(); ++i) {
      std::string target = includeTarget(lines[i]);
      if (target.empty()) {
        // #version belongs to the top file only; an include's copy becomes a blank line.
        out.text += (stack.size() > 1 && isVersionLine(lines[i])) ? "" : lines[i];
        out.text += '\n';
        continue;
      }
      std::string where = file + ":" + std::to_string(i + 1);
      fs::path local = fs::path(file).parent_path() / target;
      fs::path found = fs::exists(local) ? local : fs::path(shaderDir()) / target;
      std::string name = fs::weakly_canonical(found).string();
      if (std::find(stack.begin(), stack.end(), name) != stack.end()) {
        error = where + ": #include cycle: \"" + target + "\" is already being included";
        return false;
      }
      if (std::find(out.files.begin(), out.files.end(), name) != out.files.end()) {
        // Included before: once-only, keep line numbering with a blank line
        out.text += "\n";
        continue;
      }
      std::vector<std::string> body;
      if (!readLines(found, body)) {
        error = where + ": cannot open #include \"" + target + "\" (looked in " +
                local.parent_path().string() + " and " + shaderDir() + ")";
        return false;
      }
      const size_t included = out.files.size();
      out.files.push_back(name);
      out.text += "#line 1 " + std::to_string(included) + "\n";
      if (!expand(name, included, body, 0)) return false;
      out.text += "#line " + std::to_string(i + 2) + " " + std::to_string(id) + "\n";
    }
    stack.pop_back();
    return true;
  }
};

}  // namespace

std::string shaderDir() {
  const char* env = std::getenv("MB_SHADER_DIR");
  return env && *env ? env : MB_SHADER_DIR;  // the macro: shaders/CMakeLists.txt defines it
}

Result<ExpandedSource> expandShaderFile(const std::string& path, const Defines& defines) {
  using R = Result<ExpandedSource>;
  fs::path p = fs::path(path).is_absolute() ? fs::path(path) : fs::path(shaderDir()) / path;
  std::vector<std::string> lines;
  if (!readLines(p, lines)) return R::fail(p.string() + ": cannot open shader source");
  std::string file = fs::weakly_canonical(p).string();
  // Find #version: only blank lines and // comments may precede it.
  static const std::regex blankOrComment(R"(^[ \t]*(//|$))");
  size_t v = 0;
  for (; v < lines.size() && !isVersionLine(lines[v]); ++v)
    if (!std::regex_search(lines[v], blankOrComment))
      return R::fail(file + ":" + std::to_string(v + 1) + ": expected #version before any code");
  if (v == lines.size()) return R::fail(file + ": no #version line");

  Expander e;
  e.out.files.push_back(file);
  for (size_t i = 0; i <= v; ++i) e.out.text += lines[i] + "\n";
  for (const auto& [name, value] : defines)
    e.out.text += "#define " + name + (value.empty() ? "" : " " + value) + "\n";
  e.out.text += "#line " + std::to_string(v + 2) + " 0\n";
  if (!e.expand(file, 0, lines, v + 1)) return R::fail(e.error);
  return e.out;
}

std::string mapLog(const std::string& log, const std::vector<std::string>& files) {
  // Mesa: "0:12(5): error: ..."; NVIDIA: "0(12) : error ...".
  static const std::regex mesa(R"(^(\d+):(\d+)\((\d+)\):\s*(.*)$)");
  static const std::regex nvidia(R"(^(\d+)\((\d+)\)\s*:\s*(.*)$)");
  std::string out;
  std::istringstream in(log);
  for (const std::string& line : splitLines(in)) {
    std::smatch m;
    std::string mapped = line;
    if (std::regex_match(line, m, mesa) || std::regex_match(line, m, nvidia)) {
      const size_t id = std::stoul(m[1].str());
      if (id < files.size())  // Mesa's has a column, m[3]
        mapped = files[id] + ":" + m[2].str() + (m.size() == 5 ? ":" + m[3].str() : "") + ": " + m[m.size() - 1].str();
    }
    out += mapped + "\n";
  }
  return out;
}

}  // namespace mb::gl
