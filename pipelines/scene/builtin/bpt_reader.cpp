#include "pipelines/scene/builtin/bpt_reader.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

namespace mb {
namespace {

// Splits `text` into lines (\n, \r\n or \r), numbered from 1, and reads them in order.
class Lines {
public:
  explicit Lines(const std::string& text) : text_(text) {}
  // The next non-blank line (its tokens), false at the end.
  bool next(std::vector<std::string_view>& tokens) {
    while (at_ < text_.size()) {
      size_t end = text_.find_first_of("\r\n", at_);
      if (end == std::string::npos) end = text_.size();
      std::string_view line(text_.data() + at_, end - at_);
      at_ = end;
      if (at_ < text_.size() && text_[at_] == '\r') ++at_;
      if (at_ < text_.size() && text_[at_] == '\n') ++at_;
      ++number_;
      tokens = split(line);
      if (!tokens.empty()) return true;
    }
    return false;
  }
  int number() const { return number_; }
  // Non-blank lines after the current one (an upper bound for the patches left to read).
  long long remainingNonBlank() const {
    long long n = 0;
    bool content = false;
    for (size_t i = at_; i < text_.size(); ++i) {
      char c = text_[i];
      if (c == '\n' || c == '\r') {
        n += content;
        content = false;
      } else if (c != ' ' && c != '\t') {
        content = true;
      }
    }
    return n + content;
  }

private:
  static std::vector<std::string_view> split(std::string_view line) {
    std::vector<std::string_view> out;
    size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
      size_t j = i;
      while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
      if (j > i) out.push_back(line.substr(i, j - i));
      i = j;
    }
    return out;
  }
  const std::string& text_;
  size_t at_ = 0;
  int number_ = 0;
};

// Printable, short form of a token for messages.
std::string shown(std::string_view t) {
  std::string s;
  for (char c : t.substr(0, 40)) s += (c >= 32 && c < 127) ? c : '?';
  return t.size() > 40 ? s + "..." : s;
}

bool parseInt(std::string_view t, long long& v) {
  auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  return r.ec == std::errc() && r.ptr == t.data() + t.size();
}

// A finite float, or the reason it is not one.
std::string parseCoordinate(std::string_view t, float& v) {
  double d = 0.0;
  auto r = std::from_chars(t.data(), t.data() + t.size(), d);
  if (r.ec == std::errc::result_out_of_range) return "'" + shown(t) + "' is out of range";
  if (r.ec != std::errc() || r.ptr != t.data() + t.size()) return "'" + shown(t) + "' is not a number";
  if (!std::isfinite(d)) return "non-finite coordinate '" + shown(t) + "'";
  if (std::fabs(d) > 3.4e38) return "'" + shown(t) + "' is beyond float range";
  v = float(d);
  return {};
}

}  // namespace

Result<std::vector<glm::vec3>> parseBpt(const std::string& text, const std::string& name) {
  using R = Result<std::vector<glm::vec3>>;
  Lines lines(text);
  auto fail = [&](const std::string& why) { return R::fail(name + ": line " + std::to_string(lines.number()) + ": " + why); };
  std::vector<std::string_view> tok;
  if (!lines.next(tok)) return R::fail(name + ": empty file (expected the patch count on the first line)");
  long long count = 0;
  if (tok.size() != 1 || !parseInt(tok[0], count))
    return fail("expected the patch count (one integer), found '" + shown(tok[0]) + (tok.size() > 1 ? " ...'" : "'"));
  if (count < 1) return fail("patch count " + std::to_string(count) + " (must be at least 1)");
  if (count > kMaxBptPatches)
    return fail(std::to_string(count) + " patches claimed; the limit is " + std::to_string(kMaxBptPatches));
  const long long room = lines.remainingNonBlank();
  if (count * 17 > room)
    return fail(std::to_string(count) + " patches claimed, but the file has " + std::to_string(room) +
                " more lines (17 per patch): truncated, or the count is wrong");
  std::vector<glm::vec3> points;
  points.reserve(size_t(count) * 16);  // bounded: the lines are there
  for (long long p = 1; p <= count; ++p) {
    const std::string which = "patch " + std::to_string(p) + " of " + std::to_string(count);
    if (!lines.next(tok)) return fail("file ends before " + which);
    long long du = 0, dv = 0;
    if (tok.size() != 2 || !parseInt(tok[0], du) || !parseInt(tok[1], dv))
      return fail(which + ": expected the degrees \"3 3\", found '" + shown(tok[0]) + (tok.size() > 1 ? " ...'" : "'"));
    if (du != 3 || dv != 3)
      return fail(which + ": degrees " + std::to_string(du) + " " + std::to_string(dv) +
                  " not supported (only bicubic patches, \"3 3\")");
    for (int k = 1; k <= 16; ++k) {
      const std::string point = which + ", control point " + std::to_string(k) + " of 16";
      if (!lines.next(tok)) return fail("file ends inside " + point);
      if (tok.size() != 3)
        return fail(point + ": expected 3 numbers (x y z), found " + std::to_string(tok.size()) + " fields");
      glm::vec3 v;
      for (int c = 0; c < 3; ++c)
        if (std::string why = parseCoordinate(tok[size_t(c)], v[c]); !why.empty()) return fail(point + ": " + why);
      points.push_back(v);
    }
  }
  if (lines.next(tok)) return fail("unexpected content after the last patch ('" + shown(tok[0]) + "')");
  return points;
}

Result<Scene> loadBptFile(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return Result<Scene>::fail(path + ": no such file");
  auto size = fs::file_size(path, ec);
  if (ec || size > uint64_t(kMaxBptBytes)) return Result<Scene>::fail(path + ": cannot read (size)");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) return Result<Scene>::fail(path + ": read error");
  auto points = parseBpt(text.str(), path);
  if (!points) return Result<Scene>::fail(points.error());
  return sceneFromPatches(points.take(), path);
}

Scene sceneFromPatches(std::vector<glm::vec3> points, const std::string& name) {
  Scene s;
  s.source = name;
  Material m;
  m.name = "bpt";
  m.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
  m.metallicFactor = 0.0f;
  m.roughnessFactor = 0.5f;
  m.doubleSided = true;
  s.materials.push_back(m);
  Primitive p;
  p.material = 0;
  p.patchPoints = std::move(points);
  Mesh mesh;
  mesh.name = "bpt";
  mesh.primitives.push_back(std::move(p));
  s.meshes.push_back(std::move(mesh));
  Node n;
  n.name = "bpt";
  n.local.rotation = glm::angleAxis(-1.57079632679f, glm::vec3(1, 0, 0));  // +Z up -> +Y up
  n.mesh = 0;
  s.nodes.push_back(n);
  s.roots.push_back(0);
  return s;
}

}  // namespace mb
