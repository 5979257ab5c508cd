#include "harness/document/report_format.h"

#include <cmath>
#include <cstdio>

namespace mb::document {
namespace {
using json = nlohmann::json;
const json kNull = nullptr;
}  // namespace

std::string psnrText(const json& m) {
  if (!m.is_object()) return "-";
  if (m.value("identical", false)) return "identical";
  return fixed(m.value("psnr", json()), 1) + " dB";
}

std::string spreadText(const json& s, int digits) {
  if (!s.is_object() || s.value("n", 0) == 0) return "-";
  const std::string med = fmt(s["median"], digits), lo = fmt(s["min"], digits), hi = fmt(s["max"], digits);
  return lo == hi ? med : med + " (" + lo + ".." + hi + ")";
}

std::string noneText(const json& spread, const std::string& why) {
  const int none = spread.is_object() ? spread.value("none", 0) : 0;
  if (none == 0) return "";
  return "; none on " + std::to_string(none) + " scene" + (none == 1 ? " " : "s ") + why;
}

std::string opsText(const json& o, int decimals) {
  if (!o.is_object()) return "-";
  std::string s = fixed(o.value("mul", json()), decimals) + " mul / " + fixed(o.value("add", json()), decimals) + " add";
  for (const char* k : {"div", "sqrt", "other"}) {
    const double v = o.value(k, 0.0);
    if (v > 0) s += " + " + fixed(json(v), decimals) + " " + k;
  }
  return s;
}

const json& at(const json& j, std::initializer_list<const char*> path) {
  const json* p = &j;
  for (const char* k : path) {
    if (!p->is_object() || !p->contains(k)) return kNull;
    p = &(*p)[k];
  }
  return *p;
}

std::string dumpJson(const json& j, int indent) {
  return j.dump(indent, ' ', false, json::error_handler_t::replace);
}

std::string frameTimeOn(const nlohmann::json& gl) {
  if (!gl.is_object() || !gl.contains("renderer") || !gl["renderer"].is_string()) return "Frame time (device not recorded)";
  const bool gpu = gl.value("kind", "") == "gpu";
  return "Frame time on " + gl["renderer"].get<std::string>() +
         (gpu ? " (GPU timer queries)" : " \u2014 a CPU rasterizer (wall clock)");
}

std::string html(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string cell(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|') out += "\\|";
    else if (c == '\n') out += ' ';
    else out += c;
  }
  return out;
}

namespace {
// Control characters no figure name, value or document text holds.
constexpr char kMarkOpen = '\x02', kMarkSplit = '\x1f', kMarkClose = '\x03';

// Each mark of `s` through `write(name, text)`; the rest of `s` unchanged.
template <class Write>
std::string replaceMarks(const std::string& s, Write write) {
  std::string out;
  size_t pos = 0;
  for (size_t open; (open = s.find(kMarkOpen, pos)) != std::string::npos;) {
    const size_t split = s.find(kMarkSplit, open), close = s.find(kMarkClose, open);
    if (split == std::string::npos || close == std::string::npos || split > close) break;
    out += s.substr(pos, open - pos) + write(s.substr(open + 1, split - open - 1), s.substr(split + 1, close - split - 1));
    pos = close + 1;
  }
  return out + s.substr(pos);
}
}  // namespace

std::string figureMark(const std::string& name, const std::string& text) {
  return kMarkOpen + name + kMarkSplit + text + kMarkClose;
}

std::string figureMarksAsSpans(const std::string& s) {
  return replaceMarks(s, [](const std::string& name, const std::string& text) {
    return "<span title=\"" + html(name) + "\">" + text + "</span>";
  });
}

std::string withoutFigureMarks(const std::string& s) {
  return replaceMarks(s, [](const std::string&, const std::string& text) { return text; });
}

std::string cpuMachineText(const json& cpu, const json& cores, const json& simdTarget) {
  auto text = [](const json& v) {
    return v.is_string() ? v.get<std::string>() : v.is_number() ? std::to_string(v.get<long long>()) : std::string("unknown");
  };
  return "CPU: " + text(cpu) + ", " + text(cores) + " logical cores; SIMD kernels: Highway " + text(simdTarget);
}

}  // namespace mb::document
