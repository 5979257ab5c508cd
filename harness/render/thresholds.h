// Image thresholds from the command line, one reading for every command that judges images
// (compare, diff; check's golden.json through channelDifferenceError): idiff's --fail,
// --failpercent, --hardfail, --warn, --warnpercent, --hardwarn and FLIP's --flip-mean, --flip-max.
//
// A channel difference is written as a fraction of full scale (0..1, "0.004") or in byte steps
// N/255 ("2/255"). A plain number >= 1 reads as byte steps but would mean a fraction >= 255/255,
// a threshold no image exceeds: it is refused with the hint "did you mean N/255?" (255/255 written
// as a fraction is taken as written).
#pragma once
#include <limits>
#include <string>

#include "harness/options/args.h"
#include "harness/render/flip.h"
#include "harness/render/image_metrics.h"

namespace mb {

// --key as a channel difference under the rule above; `fallback` when absent. Throws OptionError
// naming the option ("--fail 1: ... did you mean 1/255?").
double channelDifference(const options::Args& args, const std::string& key, double fallback);
// --key as a percentage of pixels, 0..100; `fallback` when absent. Throws OptionError.
double pixelPercent(const options::Args& args, const std::string& key, double fallback);

// The rule on a value already read as a number (golden.json's "fail": 1): "" when it is a
// fraction in 0..1 below 1, else the message, naming `where` ("golden.json normal_torus exact fail").
std::string channelDifferenceError(const std::string& where, double value);

// True when --fail, --failpercent or --hardfail is on the line.
bool failThresholdGiven(const options::Args& args);
// compare's reading: only the thresholds given judge. --fail alone: any pixel over it fails;
// --failpercent alone: that % of pixels may differ at all; --hardfail alone: only the largest
// difference is judged.
Thresholds compareThresholds(const options::Args& args);

// idiff's reading, with idiff's defaults: fail 1e-6, failpercent 0, hardfail none; warn 1e-6,
// warnpercent 0, hardwarn none (so with no option any difference fails, as idiff).
struct IdiffThresholds {
  Thresholds fail;  // --fail, --failpercent, --hardfail
  Thresholds warn;  // --warn, --warnpercent, --hardwarn
};
// Throws OptionError when --hardfail is below --fail (a difference between them would pass:
// idiff's hardfail judges only pairs with a pixel over fail) or --hardwarn below --warn.
IdiffThresholds idiffThresholds(const options::Args& args);

// idiff's verdict on two images of the same size, as idiff decides it (OpenImageIO 2.4 and
// later): PASS when no pixel is over the fail threshold; else FAILURE when more than failpercent %
// of the pixels are, or some difference is over hardfail; else WARNING when more than
// warnpercent % of the pixels are over the warn threshold, or some difference is over hardwarn;
// else PASS. (So the warn thresholds and hardfail only judge pairs with a pixel over fail.)
enum class IdiffOutcome { Pass, Warning, Failure };
struct IdiffVerdict {
  IdiffOutcome outcome = IdiffOutcome::Pass;
  Verdict fail, warn;  // each judged on its own (warn.reason says why it warned)
};
IdiffVerdict judgeIdiff(const RgbaImage& a, const RgbaImage& b, const IdiffThresholds& t);
// "PASS", "WARNING", "FAILURE" (idiff's words).
const char* outcomeText(IdiffOutcome outcome);

// --flip-mean M, --flip-max X (each 0..1; absent: not judged): the images fail when the FLIP
// mean or the largest pixel's FLIP exceeds them.
struct FlipThresholds {
  double mean = std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool given() const;
};
FlipThresholds flipThresholds(const options::Args& args);
// "" when within, else which threshold and by how much ("FLIP mean 0.0123 exceeds --flip-mean 0.01").
std::string flipFailure(const FlipResult& flip, const FlipThresholds& t);

// A threshold for JSON: the number, or null for "none" (infinity).
nlohmann::json thresholdJson(double value);

}  // namespace mb
