// motorbench diff A.png B.png [idiff thresholds] [--flip-mean M] [--flip-max X] [--out DIR]: one
// image against another with idiff's verdict and defaults (harness/render/thresholds.h: any
// difference fails unless a threshold allows it; WARNING when pixels over --fail are allowed by
// --failpercent but the warn thresholds are exceeded), plus LDR-FLIP thresholds (A is FLIP's
// reference). Prints the measured differences (as compare) and one verdict line; --out DIR writes
// diff.png, diff_legend.png, flip.png and metrics.json. Exit 0 pass or warning, 1 a fail or FLIP
// threshold exceeded, 2 an error: a file that cannot be read or is not 8 bits per channel, sizes
// or channel counts that differ, a bad option (idiff: 0 pass, 1 warning, 2 failure, also for sizes
// or channels that differ, which it compares with what one image lacks read as 0; 4 a file error).
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "harness/check/junit.h"
#include "harness/cli/command.h"
#include "harness/cli/output_paths.h"
#include "harness/options/args.h"
#include "harness/render/flip.h"
#include "harness/render/frame_options.h"
#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "harness/render/thresholds.h"

namespace mb {
namespace {

using json = nlohmann::json;
using check::JunitCase;
using check::writeJunit;

struct DiffInput {
  std::string path;
  RgbaImage image;
  ImageFileInfo info;
};

// Reads both images and refuses what idiff would not compare (sizes or channel counts that
// differ) and what 8-bit metrics would misjudge (more than 8 bits per channel).
Result<std::vector<DiffInput>> readDiffInputs(const std::string& a, const std::string& b) {
  using R = Result<std::vector<DiffInput>>;
  std::vector<DiffInput> in(2);
  for (size_t i = 0; i < 2; ++i) {
    in[i].path = i == 0 ? a : b;
    auto image = readImage(in[i].path, &in[i].info);
    if (!image) return R::fail(image.error());
    in[i].image = image.take();
    if (in[i].info.pixelType != "uint8")
      return R::fail(in[i].path + ": " + in[i].info.pixelType + " pixels; diff compares 8-bit images (convert it, "
                     "e.g. oiiotool " + in[i].path + " -d uint8 -o out.png)");
  }
  auto size = [](const DiffInput& d) { return std::to_string(d.image.width) + "x" + std::to_string(d.image.height); };
  if (size(in[0]) != size(in[1]))
    return R::fail(a + " is " + size(in[0]) + ", " + b + " is " + size(in[1]) + ": the sizes differ, nothing compared");
  if (in[0].info.channels != in[1].info.channels)
    return R::fail(a + " has " + std::to_string(in[0].info.channels) + " channels, " + b + " has " +
                   std::to_string(in[1].info.channels) + ": the channel counts differ, nothing compared");
  return in;
}

// "1/255 (0.003922 of full scale)", or "none" for no limit.
std::string limitText(double v) { return std::isinf(v) ? "none" : differenceText(v); }

// A FLIP threshold: "0.01", or "none".
std::string flipLimitText(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return std::isinf(v) ? "none" : b;
}

std::string thresholdsLine(const IdiffThresholds& t, const FlipThresholds& f) {
  char b[512];
  std::snprintf(b, sizeof b,
                "thresholds: fail over %s on more than %g %% of pixels or hardfail %s; warn over %s on more than %g %% "
                "or hardwarn %s; FLIP mean %s, max %s",
                differenceText(t.fail.fail).c_str(), t.fail.failPercent, limitText(t.fail.hardFail).c_str(),
                differenceText(t.warn.fail).c_str(), t.warn.failPercent, limitText(t.warn.hardFail).c_str(),
                flipLimitText(f.mean).c_str(), flipLimitText(f.max).c_str());
  return b;
}

json thresholdsJson(const IdiffThresholds& t, const FlipThresholds& f) {
  return {{"units", "fail, hardfail, warn, hardwarn: channel difference / 255 (0..1); failpercent, warnpercent: % of "
                    "pixels; flipMean, flipMax: LDR-FLIP (0..1); null: none"},
          {"fail", t.fail.fail},
          {"failpercent", t.fail.failPercent},
          {"hardfail", thresholdJson(t.fail.hardFail)},
          {"warn", t.warn.fail},
          {"warnpercent", t.warn.failPercent},
          {"hardwarn", thresholdJson(t.warn.hardFail)},
          {"flipMean", thresholdJson(f.mean)},
          {"flipMax", thresholdJson(f.max)}};
}

// Writes the maps and metrics.json into `dir` (already checked writable).
Status writeDiffFolder(const std::string& dir, const std::vector<DiffInput>& in, const FlipResult& flip,
                       const json& metricsJson) {
  namespace fs = std::filesystem;
  const auto file = [&](const char* name) { return (fs::path(dir) / name).string(); };
  if (Status s = writeImage(file("diff.png"), diffHeatmap(in[0].image, in[1].image)); !s) return s;
  std::string legendWarning;
  if (Status s = writeImage(file("diff_legend.png"), heatLegend(&legendWarning)); !s) return s;
  if (!legendWarning.empty()) commandNotes("diff", {"warning: " + legendWarning});
  if (Status s = writeImage(file("flip.png"), flipErrorImage(flip)); !s) return s;
  return writeTextFile(file("metrics.json"), metricsJson.dump(2) + "\n");
}

// The one JUnit case of a diff: classname "diff", name "A vs B".
Status writeDiffJunit(const std::string& path, const std::string& a, const std::string& b, JunitCase::Kind kind,
                      const std::string& message, const std::string& detail) {
  if (path.empty()) return {};
  return writeJunit(path, "motorbench diff", {{"diff", a + " vs " + b, 0, kind, message, detail}});
}

int runDiff(const std::vector<std::string>& argv) {
  auto fail = [](const std::string& message) { return commandError("diff", message); };
  const options::Args args(argv, {{"fail", "failpercent", "hardfail", "warn", "warnpercent", "hardwarn", "flip-mean", "flip-max",
                          "out", "junit"},
                         {"quiet"},
                         {},
                         {}});
  if (!args.error().empty()) return fail(args.error());
  if (args.positional().size() != 2) return fail("expected two images, A and B (e.g. motorbench diff a.png b.png)");
  // Every option and the output folder before the images are read.
  const IdiffThresholds t = idiffThresholds(args);
  const FlipThresholds flipLimits = flipThresholds(args);
  const bool quiet = args.has("quiet");
  const std::string dir = args.get("out", ""), junitPath = args.get("junit", "");
  if (!dir.empty())
    if (Status ok = prepareOutputFolder("--out", dir, "diff.png, diff_legend.png, flip.png, metrics.json"); !ok)
      return fail(ok.error());
  if (!junitPath.empty())
    if (Status ok = prepareOutputFile("--junit", junitPath); !ok) return fail(ok.error());
  const std::string& a = args.positional()[0];
  const std::string& b = args.positional()[1];
  // An error after the options is the JUnit file's error case as well.
  auto error = [&](const std::string& message) {
    if (Status j = writeDiffJunit(junitPath, a, b, JunitCase::Kind::Error, message, ""); !j) fail(j.error());
    return fail(message);
  };
  auto in = readDiffInputs(a, b);
  if (!in) return error(in.error());
  auto metrics = compareImages((*in)[0].image, (*in)[1].image);
  if (!metrics) return error(metrics.error());
  auto flip = computeFlip((*in)[0].image, (*in)[1].image);
  if (!flip) return error(flip.error());
  const IdiffVerdict v = judgeIdiff((*in)[0].image, (*in)[1].image, t);
  const std::string flipReason = flipFailure(*flip, flipLimits);
  const bool failed = v.outcome == IdiffOutcome::Failure || !flipReason.empty();
  const bool warned = !failed && v.outcome == IdiffOutcome::Warning;
  std::string reason = v.outcome == IdiffOutcome::Failure ? v.fail.reason : "";
  if (!flipReason.empty()) reason += (reason.empty() ? "" : "; ") + flipReason;

  if (!dir.empty()) {
    const json j = {
        {"schema", "motorbench-diff/1"},
        {"images", {a, b}},
        {"input", {{"channels", (*in)[0].info.channels}, {"pixelType", (*in)[0].info.pixelType}}},
        {"diff", "diff.png"},
        {"diffLegend", heatLegendJson()},
        {"flipMap", "flip.png"},  // magma: black 0 .. light yellow 1; A is the reference
        {"metrics", toJson(*metrics, *flip)},
        {"thresholds", thresholdsJson(t, flipLimits)},
        {"verdict", {{"text", failed ? "fail" : warned ? "warning" : "pass"},
                     {"idiff", outcomeText(v.outcome)},
                     {"failed", failed},
                     {"failPercent", v.fail.failPercent},
                     {"warnPercent", v.warn.failPercent},
                     {"reason", failed ? json(reason) : json(nullptr)},
                     {"warning", warned ? json(v.warn.reason) : json(nullptr)},
                     {"exit", failed ? 1 : 0}}}};
    if (Status w = writeDiffFolder(dir, *in, *flip, j); !w) return error(w.error());
  }
  std::vector<std::string> measured = differenceLines(*metrics);
  char flipLine[256];
  std::snprintf(flipLine, sizeof flipLine, "%s (LDR-FLIP, 0..1, %.0f pixels per degree%s)", flipText(*flip).c_str(),
                flip->pixelsPerDegree, dir.empty() ? "" : "; map: flip.png");
  measured.push_back(flipLine);
  measured.push_back(thresholdsLine(t, flipLimits));
  if (!quiet) {
    std::printf("%s vs %s, %dx%d\n", a.c_str(), b.c_str(), metrics->width, metrics->height);
    for (const std::string& line : measured) std::printf("  %s\n", line.c_str());
  }
  std::string detail;
  for (const std::string& line : measured) detail += (detail.empty() ? "" : "\n") + line;
  if (Status w = writeDiffJunit(junitPath, a, b, failed ? JunitCase::Kind::Fail : JunitCase::Kind::Pass, reason, detail); !w)
    return fail(w.error());
  if (failed)
    std::printf("%s vs %s -> FAIL (%s)\n", a.c_str(), b.c_str(), reason.c_str());
  else if (warned)
    std::printf("%s vs %s -> WARNING (%.4f%% of pixels over --fail, allowed; but %s; exit 0)\n", a.c_str(), b.c_str(),
                v.fail.failPercent, v.warn.reason.c_str());
  else
    std::printf("%s vs %s -> PASS (within the thresholds)\n", a.c_str(), b.c_str());
  return failed ? 1 : 0;
}

}  // namespace
}  // namespace mb

MB_COMMAND(diff, "diff",
           "A B [--fail F] [--failpercent P] [--hardfail H] [--warn W] [--warnpercent Q] [--hardwarn HW] "
           "[--flip-mean M] [--flip-max X] [--out DIR] [--junit FILE] [--quiet]",
           "one image against another with idiff's thresholds and defaults (any difference fails unless allowed) and "
           "LDR-FLIP's; exit 0 pass or warning, 1 a threshold exceeded, 2 an unreadable file or sizes that differ",
           mb::runDiff);
MB_COMMAND_HELP(diff, "diff",
               "  A B                two images (PNG or any format OpenImageIO reads, 8 bits per channel, the same size\n"
               "                     and channel count); A is FLIP's reference\n"
               "  --fail F           a pixel fails when some channel differs by more than F: a fraction of full scale\n"
               "                     below 1 or byte steps N/255 (2/255); a plain 1 or more is refused (did you mean\n"
               "                     1/255?) (default 1e-6: any difference). No pixel over F: PASS, whatever follows\n"
               "  --failpercent P    FAIL when more than P % of pixels fail (0..100, default 0)\n"
               "  --hardfail H       FAIL when some channel differs by more than H (>= F, as F; default none)\n"
               "  --warn W, --warnpercent Q, --hardwarn HW   the same for WARNING, once some pixel is over F but\n"
               "                     the fail thresholds allow it (defaults 1e-6, 0, none)\n"
               "  --flip-mean M      FAIL when the LDR-FLIP mean exceeds M (0..1, default none)\n"
               "  --flip-max X       FAIL when the largest pixel's LDR-FLIP exceeds X (0..1, default none)\n"
               "  --out DIR          a folder (created): diff.png, diff_legend.png, flip.png, metrics.json (default:\n"
               "                     nothing written)\n"
               "  --junit FILE       JUnit XML: one test case (classname diff, name 'A vs B'), its failure or error with\n"
               "                     the reason (default: none written)\n"
               "  --quiet            print only the verdict line (errors still on stderr)\n"
               "  Exit, with idiff's code for the same case in brackets: 0 PASS [0], or WARNING printed [1]; 1 FAIL: a\n"
               "  fail or FLIP threshold exceeded [2]; 2 an error: a file that cannot be read [4] or is not 8-bit, sizes\n"
               "  or channel counts that differ [2: idiff compares them, counting what one image lacks as 0], a bad option.\n",
                "motorbench diff tests/golden/crowd.rest.matrix.png tests/golden/crowd.rest.motor.png --fail 2/255 --out out/diff",
                false);
