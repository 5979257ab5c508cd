// Minimal argument parsing for subcommands: "--key value", "--key=value", "--flag", positionals.
#pragma once
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace mb {

class Args {
public:
  // `flags`: options that take no value. Everything else starting with "--" (or "-o") takes one.
  Args(const std::vector<std::string>& args, std::set<std::string> flags = {});

  bool has(const std::string& key) const { return options_.count(key) > 0; }
  std::optional<std::string> get(const std::string& key) const;
  std::string get(const std::string& key, const std::string& fallback) const;
  double number(const std::string& key, double fallback) const;  // throws on bad number
  const std::vector<std::string>& positional() const { return positional_; }
  // Options given but not in `known`, for "unknown option" errors. Empty when all known.
  std::vector<std::string> unknown(const std::set<std::string>& known) const;
  // Non-empty when parsing failed (e.g. option without value).
  const std::string& error() const { return error_; }

private:
  std::map<std::string, std::string> options_;
  std::vector<std::string> positional_;
  std::string error_;
};

}  // namespace mb
