#include "harness/options/args.h"

#include <stdexcept>

namespace mb {

Args::Args(const std::vector<std::string>& args, std::set<std::string> flags) {
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.size() > 1 && a[0] == '-' && !(a[1] >= '0' && a[1] <= '9') && a[1] != '.') {
      std::string key = a.substr(a[1] == '-' ? 2 : 1);
      auto eq = key.find('=');
      if (eq != std::string::npos) {
        options_[key.substr(0, eq)] = key.substr(eq + 1);
      } else if (flags.count(key)) {
        options_[key] = std::string("1");  // not operator=(const char*): GCC 12 -Wrestrict false positive (PR 105329)
      } else if (i + 1 < args.size()) {
        options_[key] = args[++i];
      } else {
        error_ = "option " + a + " needs a value";
      }
    } else {
      positional_.push_back(a);
    }
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

double Args::number(const std::string& key, double fallback) const {
  auto v = get(key);
  if (!v) return fallback;
  size_t used = 0;
  double d = std::stod(*v, &used);
  if (used != v->size()) throw std::invalid_argument("--" + key + ": not a number: " + *v);
  return d;
}

std::vector<std::string> Args::unknown(const std::set<std::string>& known) const {
  std::vector<std::string> out;
  for (const auto& [k, v] : options_)
    if (!known.count(k)) out.push_back("--" + k);
  return out;
}

}  // namespace mb
