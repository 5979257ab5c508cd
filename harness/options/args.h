// The one option parser of every `motorbench` command: "--key value", "--key=value", "-o value",
// flags and positionals, checked against what the command accepts, with the error a user sees
// for a malformed line, and typed readers (numbers, sizes) whose errors name the option.
#pragma once
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace mb::options {

// What a command accepts. Keys are written without dashes ("size", "o"); on the line a key is
// given as --key or -key (the usual short form: -o).
struct OptionSpec {
  std::set<std::string> values;  // options that take one value
  std::set<std::string> flags;   // options that take none
  // Added to the "given twice" error of an option (why it is one value only, what to do).
  std::map<std::string, std::string> repeatHints;
  // Value options that may be given more than once: the values are joined with ',' (so
  // "--anim a --anim b" reads as "--anim a,b"; splitList takes them apart).
  std::set<std::string> lists;
};

// A bad option value: what() is a message for the user that names the option, e.g.
// "--frames: expected a whole number >= 1, got 'abc'". main() prints it and exits 2.
struct OptionError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

class Args {
public:
  // Parses `args` against `spec`. The first problem in the order of the line becomes error():
  //   "unknown option --no-bnech"                    (a key the spec lacks, wherever it stands)
  //   "option --size needs a value (found -o ...)"   (never swallows the next option)
  //   "option --size needs a value"                  (at the end of the line)
  //   "option --update takes no value"               (--flag=value)
  //   "option --time given twice ('0.5', '1'); ..."  (every option but spec.lists at most once)
  // A word starting with '-' followed by a digit or '.' (e.g. -1, -.5) is a value or a
  // positional, never an option, so a negative value reaches the range check that rejects it;
  // a value that itself starts with '-' and a letter is written --key=value.
  Args(const std::vector<std::string>& args, const OptionSpec& spec);

  bool has(const std::string& key) const { return options_.count(key) > 0; }
  std::optional<std::string> get(const std::string& key) const;
  std::string get(const std::string& key, const std::string& fallback) const;
  const std::vector<std::string>& positional() const { return positional_; }
  // Empty when the line parsed; else the first problem (see the constructor).
  const std::string& error() const { return error_; }

  // --key as a whole number in [min, max] (`fallback` when absent). Throws OptionError:
  // "--frames: expected a whole number >= 1, got 'abc'" / "... in 1..256, got '0'".
  long integer(const std::string& key, long fallback, long min, long max) const;
  // --key as a finite number, or a fraction N/D ("1/255"), in [min, max]; `what` names the quantity in the error
  // ("a time in seconds" -> "--time: expected a time in seconds >= 0, got '-1'").
  double real(const std::string& key, double fallback, double min, double max,
              const std::string& what = "a number") const;
  // --key as WxH, both whole numbers in 1..kMaxSize ("640x480"; a single number is rejected:
  // write 640x640). Every command reads sizes through this one rule. Throws OptionError.
  std::pair<int, int> size(const std::string& key, int width, int height) const;
  static constexpr int kMaxSize = 16384;

private:
  std::map<std::string, std::string> options_;
  std::vector<std::string> positional_;
  std::string error_;
};

// "WxH" -> (W, H) under Args::size's rule; std::nullopt when malformed or out of range.
std::optional<std::pair<int, int>> parseSize(const std::string& text);

}  // namespace mb::options
