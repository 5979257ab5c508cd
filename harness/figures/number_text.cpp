#include "harness/figures/number_text.h"

#include <cmath>
#include <cstdio>

namespace mb::figures {

using json = nlohmann::json;

std::string fmt(double v, int digits) {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  // %g switches to exponents past `digits` digits (3240 -> 3.24e+03): integers (counts) are
  // printed whole, whatever `digits` says.
  if (std::fabs(v) < 1e15 && v == std::floor(v)) std::snprintf(buf, sizeof buf, "%.0f", v);
  else std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string sig3(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

std::string fmt(const json& v, int digits) { return v.is_number() ? fmt(v.get<double>(), digits) : "-"; }

std::string fixed(const json& v, int decimals) {
  if (!v.is_number() || !std::isfinite(v.get<double>())) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v.get<double>());
  return buf;
}

std::string ratio(const json& v) { return v.is_number() ? fixed(v, 2) + "x" : "-"; }

std::string percent(const json& f, int decimals) {
  if (!f.is_number()) return "-";
  return fixed(100.0 * f.get<double>(), decimals) + " %";
}

std::string positiveOrDash(const json& v, const char* format) {
  if (!v.is_number() || !(v.get<double>() > 0)) return "-";
  char b[32];
  std::snprintf(b, sizeof b, format, v.get<double>());
  return b;
}

}  // namespace mb::figures
