#include "harness/options/args.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace mb::options {
namespace {

// "-1", "-.5", "-" and anything not starting with '-' are words, not options.
bool looksLikeOption(const std::string& a) {
  return a.size() > 1 && a[0] == '-' && !(a[1] >= '0' && a[1] <= '9') && a[1] != '.';
}

// The accepted range as the error states it. A large upper bound (>= 1e5) is only a sanity
// cap: named when the value exceeds it, otherwise the message reads ">= min".
std::string rangeText(double min, double max, bool whole, bool overMax) {
  auto num = [whole](double v) {
    char b[32];
    std::snprintf(b, sizeof b, whole ? "%.0f" : "%g", v);
    return std::string(b);
  };
  if (max >= 1e5 && !overMax) return ">= " + num(min);
  return "in " + num(min) + ".." + num(max);
}

}  // namespace

Args::Args(const std::vector<std::string>& args, const OptionSpec& spec) {
  auto problem = [this](const std::string& m) {
    if (error_.empty()) error_ = m;
  };
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (!looksLikeOption(a)) {
      positional_.push_back(a);
      continue;
    }
    std::string key = a.substr(a[1] == '-' ? 2 : 1);
    std::optional<std::string> inlineValue;
    if (auto eq = key.find('='); eq != std::string::npos) {
      inlineValue = key.substr(eq + 1);
      key = key.substr(0, eq);
    }
    const std::string written = a.substr(0, a.find('='));
    std::string value;
    if (spec.flags.count(key)) {
      if (inlineValue) problem("option " + written + " takes no value");
      value = "1";
    } else if (spec.values.count(key)) {
      if (inlineValue) {
        value = *inlineValue;
      } else if (i + 1 >= args.size()) {
        problem("option " + written + " needs a value");
        continue;
      } else if (looksLikeOption(args[i + 1])) {
        problem("option " + written + " needs a value (found the option " + args[i + 1] +
                " after it; write " + written + "=VALUE for a value that starts with '-')");
        continue;
      } else {
        value = args[++i];
      }
    } else {
      problem("unknown option " + written);
      continue;
    }
    if (auto it = options_.find(key); it != options_.end() && spec.lists.count(key)) {
      it->second += "," + value;  // a list option: repeats add to the list
      continue;
    } else if (it != options_.end()) {
      std::string m = "option " + written + " given twice";
      if (!spec.flags.count(key)) m += " ('" + it->second + "', '" + value + "')";
      auto hint = spec.repeatHints.find(key);
      problem(m + "; " + (hint != spec.repeatHints.end() ? hint->second : "give it once"));
      continue;
    }
    options_[key] = value;
  }
}

std::optional<std::string> Args::get(const std::string& key) const {
  auto it = options_.find(key);
  if (it == options_.end()) return std::nullopt;
  return it->second;
}

std::string Args::get(const std::string& key, const std::string& fallback) const {
  auto v = get(key);
  return v ? *v : fallback;
}

long Args::integer(const std::string& key, long fallback, long min, long max) const {
  auto v = get(key);
  if (!v) return fallback;
  errno = 0;
  char* end = nullptr;
  const long n = std::strtol(v->c_str(), &end, 10);
  if (v->empty() || *end != '\0' || errno == ERANGE || n < min || n > max)
    throw OptionError("--" + key + ": expected a whole number " +
                      rangeText(double(min), double(max), true, *end == '\0' && n > max) +
                      ", got '" + *v + "'");
  return n;
}

double Args::real(const std::string& key, double fallback, double min, double max,
                  const std::string& what) const {
  auto v = get(key);
  if (!v) return fallback;
  char* end = nullptr;
  double d = std::strtod(v->c_str(), &end);
  // A fraction N/D too ("--fail 1/255": the help speaks of byte steps in /255).
  if (!v->empty() && end != v->c_str() && *end == '/') {
    char* denEnd = nullptr;
    const double den = std::strtod(end + 1, &denEnd);
    d = denEnd != end + 1 && den != 0 ? d / den : std::nan("");
    end = denEnd;
  }
  if (v->empty() || *end != '\0' || !std::isfinite(d) || d < min || d > max)
    throw OptionError("--" + key + ": expected " + what + " " + rangeText(min, max, false, *end == '\0' && d > max) +
                      ", got '" +
                      *v + "'");
  return d;
}

std::optional<std::pair<int, int>> parseSize(const std::string& text) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (text.empty() || !(text[0] >= '0' && text[0] <= '9')) return std::nullopt;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X'))
    return std::nullopt;
  if (w < 1 || h < 1 || w > Args::kMaxSize || h > Args::kMaxSize) return std::nullopt;
  return std::make_pair(w, h);
}

std::pair<int, int> Args::size(const std::string& key, int width, int height) const {
  auto v = get(key);
  if (!v) return {width, height};
  auto wh = parseSize(*v);
  if (!wh)
    throw OptionError("--" + key + ": expected WIDTHxHEIGHT, both whole numbers in 1.." +
                      std::to_string(kMaxSize) + " (e.g. 640x480; a square is 640x640), got '" + *v + "'");
  return *wh;
}

}  // namespace mb::options
