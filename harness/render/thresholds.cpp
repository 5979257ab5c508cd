#include "harness/render/thresholds.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <tuple>

namespace mb {
namespace {

const char* const kChannelDifferenceWhat = "a channel difference as a fraction of full scale (1/255 = one byte step)";

// "did you mean 2/255?" for a whole number of byte steps 1..255, else "".
std::string byteStepHint(double value) {
  if (value != std::floor(value) || value < 1 || value > 255) return "";
  char b[64];
  std::snprintf(b, sizeof b, " Did you mean %.0f/255 (%.4g)?", value, value / 255);
  return b;
}

// The refusal of a value >= 1 written as a plain number (`shown` as the user wrote it), in the
// parser's form: "--fail: expected ..., got '1': ...".
std::string byteStepRefusal(const std::string& where, const std::string& shown, double value) {
  return where + ": expected " + kChannelDifferenceWhat + " in 0..1 or byte steps N/255, got '" + shown + "': " +
         shown + " reads as byte steps, but as a fraction it is " + (value == 1 ? "255/255" : "over 255/255") +
         ", a difference no image exceeds (every image would pass)." + byteStepHint(value);
}

}  // namespace

double channelDifference(const options::Args& args, const std::string& key, double fallback) {
  const auto text = args.get(key);
  if (!text) return fallback;
  if (text->find('/') == std::string::npos) {  // a plain number: >= 1 is the byte-step trap
    char* end = nullptr;
    const double d = std::strtod(text->c_str(), &end);
    if (!text->empty() && *end == '\0' && std::isfinite(d) && d >= 1)
      throw options::OptionError(byteStepRefusal("--" + key, *text, d));
  }
  return args.real(key, fallback, 0.0, 1.0, kChannelDifferenceWhat);
}

double pixelPercent(const options::Args& args, const std::string& key, double fallback) {
  return args.real(key, fallback, 0.0, 100.0, "a percentage of pixels");
}

std::string channelDifferenceError(const std::string& where, double value) {
  if (std::isfinite(value) && value >= 0 && value < 1) return "";
  char shown[64];
  std::snprintf(shown, sizeof shown, "%g", value);
  if (std::isfinite(value) && value >= 1) return byteStepRefusal(where, shown, value);
  return where + ": expected " + kChannelDifferenceWhat + " in 0..1, got '" + shown + "'";
}

bool failThresholdGiven(const options::Args& args) {
  return args.has("fail") || args.has("failpercent") || args.has("hardfail");
}

Thresholds compareThresholds(const options::Args& args) {
  Thresholds t;
  t.fail = channelDifference(args, "fail", t.fail);
  t.failPercent = pixelPercent(args, "failpercent", args.has("fail") || !args.has("hardfail") ? 0.0 : 100.0);
  t.hardFail = channelDifference(args, "hardfail", t.hardFail);
  return t;
}

IdiffThresholds idiffThresholds(const options::Args& args) {
  IdiffThresholds t;  // Thresholds' defaults are idiff's: 1e-6, 0 %, none
  t.fail.fail = channelDifference(args, "fail", t.fail.fail);
  t.fail.failPercent = pixelPercent(args, "failpercent", t.fail.failPercent);
  t.fail.hardFail = channelDifference(args, "hardfail", t.fail.hardFail);
  t.warn.fail = channelDifference(args, "warn", t.warn.fail);
  t.warn.failPercent = pixelPercent(args, "warnpercent", t.warn.failPercent);
  t.warn.hardFail = channelDifference(args, "hardwarn", t.warn.hardFail);
  for (auto [hard, soft, limits] : {std::tuple{"hardfail", "fail", &t.fail}, std::tuple{"hardwarn", "warn", &t.warn}})
    if (args.has(soft) && limits->hardFail < limits->fail)  // (below the 1e-6 default no byte step lies)
      throw options::OptionError(std::string("--") + hard + " " + args.get(hard, "") + " is below --" + soft + " " +
                        differenceText(limits->fail) + ": a difference between them would pass (idiff judges --" +
                        hard + " only when some pixel is over --" + soft + "); give --" + hard + " >= --" + soft);
  return t;
}

IdiffVerdict judgeIdiff(const RgbaImage& a, const RgbaImage& b, const IdiffThresholds& t) {
  IdiffVerdict v;
  v.fail = judge(a, b, t.fail);
  v.warn = judge(a, b, t.warn);
  const bool anyPixelOverFail = v.fail.failPercent > 0;
  v.outcome = !anyPixelOverFail ? IdiffOutcome::Pass
              : v.fail.failed   ? IdiffOutcome::Failure
              : v.warn.failed   ? IdiffOutcome::Warning
                                : IdiffOutcome::Pass;
  return v;
}

const char* outcomeText(IdiffOutcome outcome) {
  switch (outcome) {
    case IdiffOutcome::Pass: return "PASS";
    case IdiffOutcome::Warning: return "WARNING";
    case IdiffOutcome::Failure: return "FAILURE";
  }
  return "PASS";
}

bool FlipThresholds::given() const { return std::isfinite(mean) || std::isfinite(max); }

FlipThresholds flipThresholds(const options::Args& args) {
  FlipThresholds t;
  t.mean = args.real("flip-mean", t.mean, 0.0, 1.0, "a FLIP error (0 = no visible difference .. 1)");
  t.max = args.real("flip-max", t.max, 0.0, 1.0, "a FLIP error (0 = no visible difference .. 1)");
  return t;
}

std::string flipFailure(const FlipResult& flip, const FlipThresholds& t) {
  char b[2][160] = {"", ""};
  if (flip.mean > t.mean) std::snprintf(b[0], sizeof b[0], "FLIP mean %.4g exceeds --flip-mean %g", flip.mean, t.mean);
  if (flip.max > t.max)
    std::snprintf(b[1], sizeof b[1], "FLIP max %.4g at (%d,%d) exceeds --flip-max %g", flip.max, flip.maxX, flip.maxY,
                  t.max);
  const std::string mean = b[0], max = b[1];
  return mean + (!mean.empty() && !max.empty() ? "; " : "") + max;
}

nlohmann::json thresholdJson(double value) { return std::isinf(value) ? nlohmann::json(nullptr) : nlohmann::json(value); }

}  // namespace mb
