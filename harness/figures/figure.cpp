#include "harness/figures/figure.h"

#include <cmath>

#include "harness/figures/number_text.h"

namespace mb::figures {

using json = nlohmann::json;

namespace {

std::string withUnit(double v, const std::string& unit) {
  if (!std::isfinite(v)) return "-";
  if (unit == "x") return sig3(v) + "x";
  // A count (a whole number of draws, vertices, files) reads as the integer it is.
  const bool count = v == std::floor(v) && std::fabs(v) >= 1000 && std::fabs(v) < 1e15;
  const std::string text = count ? std::to_string(static_cast<long long>(v)) : sig3(v);
  return unit.empty() ? text : text + " " + unit;
}

json number(double v) { return std::isfinite(v) ? json(v) : json(); }

}  // namespace

Figure withQuartiles(Figure f, const Quartiles& q) {
  f.n = q.n;
  if (q.n == 0) {
    f.value = std::nan("");
    if (f.why.empty()) f.why = "no samples";
    return f;
  }
  f.value = q.median;
  f.q1 = q.q1, f.q3 = q.q3;
  return f;
}

json toJson(const Figure& f) {
  json j = {{"value", number(f.value)}, {"unit", f.unit}, {"kind", f.kind}, {"statistic", f.statistic}, {"scope", f.scope},
            {"device", f.device}, {"n", f.n}, {"tolerance", f.tolerance}, {"definition", f.definition},
            {"disturbed", f.disturbed}, {"text", valueText(f)}};
  j["spread"] = f.q1 && f.q3 ? json{{"q1", number(*f.q1)}, {"q3", number(*f.q3)}, {"kind", "interquartile range"}}
                             : json();
  if (!f.why.empty()) j["why"] = f.why;
  return j;
}

bool isDisturbed(const Figure& f) { return f.disturbed.is_object() && f.disturbed.value("disturbed", false); }

double numberOrNaN(const json& v) { return v.is_number() ? v.get<double>() : std::nan(""); }

Figure figureFromJson(const std::string& name, const json& j) {
  Figure f;
  f.name = name;
  if (!j.is_object()) {
    f.value = std::nan(""), f.why = "not a figure";
    return f;
  }
  const json& v = j.value("value", json());
  f.value = numberOrNaN(v);
  f.unit = j.value("unit", "");
  f.kind = j.value("kind", "");
  f.statistic = j.value("statistic", "");
  f.scope = j.value("scope", "");
  f.device = j.value("device", "");
  f.n = j.value("n", 0);
  f.tolerance = j.value("tolerance", "");
  f.definition = j.value("definition", "");
  f.why = j.value("why", "");
  f.disturbed = j.value("disturbed", json());
  const json& s = j.value("spread", json());
  if (s.is_object() && s.value("q1", json()).is_number() && s.value("q3", json()).is_number())
    f.q1 = s["q1"].get<double>(), f.q3 = s["q3"].get<double>();
  return f;
}

void put(json& figures, const Figure& f) {
  if (!figures.is_object()) figures = json::object();
  figures[f.name] = toJson(f);
}

std::optional<Figure> figureNamed(const json& runOrFigures, const std::string& name) {
  if (!runOrFigures.is_object()) return std::nullopt;
  const json& figures = runOrFigures.contains("figures") ? runOrFigures["figures"] : runOrFigures;
  if (!figures.is_object() || !figures.contains(name)) return std::nullopt;
  return figureFromJson(name, figures[name]);
}

std::string valueText(const Figure& f) { return withUnit(f.value, f.unit); }

std::string figureText(const Figure& f) {
  if (!std::isfinite(f.value)) return "- (" + (f.why.empty() ? std::string("not measured") : f.why) + ")";
  std::string s = valueText(f);
  if (f.q1 && f.q3) s += " [IQR " + sig3(*f.q1) + ".." + sig3(*f.q3) + "]";
  std::string d = f.statistic;
  auto add = [&](const std::string& label, const std::string& v) {
    if (!v.empty()) d += (d.empty() ? "" : "; ") + label + v;
  };
  add("n = ", f.n > 0 ? std::to_string(f.n) : "");
  add("", f.scope);
  add("", f.device);
  add("tolerance ", f.tolerance);
  // Timed on shared cores (harness/timing/disturbance.h): printed, marked, not a verdict input.
  const std::string mark = isDisturbed(f)
                               ? " [disturbed: " + f.disturbed.value("reason", "") + "]"
                               : "";
  return (d.empty() ? s : s + " (" + d + ")") + mark;
}

}  // namespace mb::figures
