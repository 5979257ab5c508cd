// motorbench compare SCENE [--pipelines A,B] [frame options] [--fail F --failpercent P
//   --hardfail H] -o DIR: renders both, writes DIR/A.png, DIR/B.png, DIR/diff.png,
// DIR/diff_legend.png, DIR/flip.png (the LDR-FLIP error map) and DIR/metrics.json, prints the
// measured differences (PSNR, FLIP...) and one summary line; exit 1 when the idiff
// thresholds are exceeded (or the drawn-pixel check fails). Units: --fail and --hardfail are
// channel differences as a fraction of full scale (0..1; 1/255 = one byte step), --failpercent
// a percentage of pixels (0..100).
// Only the thresholds given judge: --hardfail alone fails only on the largest difference.
// Before any threshold, the drawn-pixel check (harness/render/drawn_check.h) fails a frame one
// pipeline left empty or drawn-pixel counts more than 1 % apart, with or without thresholds.
// A skinned frame of two pipelines that blend joints by different methods is judged by each
// pipeline's own method (harness/render/skin_judgement.h): a motor-blend pipeline's drawn pixels
// and thresholds against the motor-blend reference, a linear-blend one's against matrix; the
// figures against matrix are printed beside them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "harness/check/junit.h"
#include "harness/cli/command.h"
#include "harness/cli/output_paths.h"
#include "harness/options/args.h"
#include "harness/render/counter_glossary.h"
#include "harness/render/drawn_check.h"
#include "harness/render/flip.h"
#include "harness/render/frame_notes.h"
#include "harness/render/gpu_option.h"
#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "harness/render/skin_judgement.h"
#include "harness/render/thresholds.h"
#include "harness/report/report_sources.h"

namespace mb {
namespace {

using json = nlohmann::json;
using check::JunitCase;
using check::writeJunit;

// What decides compare's exit: the drawn-pixel check and the thresholds given, on the two images;
// on a skinned frame of pipelines of different skinning methods, each pipeline against its own
// method's reference instead (skin_judgement.h), when every such reference could be made.
struct PairVerdict {
  DrawnCheck shape;  // the check that decides (the first failed; else the last judged)
  std::vector<SkinnedFrameJudgement> skin;  // the pipelines judged by their own method (not matrix)
  bool skinApplies = false;  // skinned frame, methods differ
  bool byOwnMethod = false;  // skinApplies and every reference made
  bool failed = false;
  double failPercent = 0;
  std::string reason;
};

// Each pipeline of the pair but matrix (the linear blend's reference itself) judged by its own
// method: matrix's frame (rendered when neither is matrix) and the motor-blend reference.
Result<std::vector<SkinnedFrameJudgement>> judgeByOwnMethod(Scene& scene, const FrameSettings& settings,
                                                            const std::vector<std::string>& names,
                                                            const std::vector<Frame>& frames, const Thresholds* t) {
  using R = Result<std::vector<SkinnedFrameJudgement>>;
  const std::string matrix = kMatrixReference;
  RgbaImage matrixImage;
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == matrix) matrixImage = frames[i].image;
  if (matrixImage.rgba.empty()) {
    auto m = renderFrame(scene, matrix, settings);
    if (!m) return R::fail(m.error());
    matrixImage = m->image;
  }
  MotorBlendFrames own;
  for (const std::string& n : names)
    if (std::string(skinReferenceOf(n)) == kMotorBlendReference && own.images.empty() && own.why.empty())
      own = motorBlendReferenceFrames(scene, {settings});
  std::vector<SkinnedFrameJudgement> out;
  for (size_t i = 0; i < names.size(); ++i) {
    if (names[i] == matrix) continue;
    auto j = judgeSkinnedFrame(names[i], frames[i].image, matrixImage, own.images.empty() ? nullptr : &own.images[0],
                               own.why, t);
    if (!j) return R::fail(j.error());
    out.push_back(j.take());
  }
  return out;
}

PairVerdict judgePair(Scene& scene, const FrameSettings& settings, const std::vector<std::string>& names,
                      const std::vector<Frame>& frames, const Thresholds* t) {
  PairVerdict v;
  const bool skinned = drawsSkinned(scene), differ = skinMethodsDiffer(names[0], names[1]);
  v.shape = checkDrawn(names[0], frames[0].image, names[1], frames[1].image, skinned, differ);
  v.skinApplies = skinned && differ && v.shape.kind != DrawnCheck::Kind::NothingDrawn;
  if (v.skinApplies) {
    auto judged = judgeByOwnMethod(scene, settings, names, frames, t);
    if (!judged) {
      v.reason = judged.error();  // an error, not a verdict: the caller exits 2
      return v;
    }
    v.skin = judged.take();
    v.byOwnMethod = std::all_of(v.skin.begin(), v.skin.end(), [](const SkinnedFrameJudgement& j) { return j.judged; });
  }
  if (v.byOwnMethod) {
    for (const SkinnedFrameJudgement& j : v.skin) {
      if (j.failed) v.reason += (v.reason.empty() ? "" : "; ") + j.reason;
      v.failPercent = std::max(v.failPercent, j.thresholds.failPercent);
    }
    v.failed = !v.reason.empty();
    v.shape = v.skin.back().vsReference.drawn;
    for (auto j = v.skin.rbegin(); j != v.skin.rend(); ++j)
      if (j->vsReference.drawn.failed) v.shape = j->vsReference.drawn;  // the first failed
    v.shape.skinningMethodNote = !v.shape.failed;
    return v;
  }
  // Not skinned, one method, or an own reference not made: the two images against each other.
  const Verdict thresholds = t ? judge(frames[0].image, frames[1].image, *t) : Verdict{};
  v.failPercent = thresholds.failPercent;
  v.failed = v.shape.failed || thresholds.failed;
  v.reason = v.shape.reason;  // the drawn-pixel check first, then the thresholds'
  if (thresholds.failed) v.reason += (v.reason.empty() ? "" : "; ") + thresholds.reason;
  return v;
}

// "matrix blends joints with linear blend skinning, motor by motor blending" and how the frame is
// judged: by each pipeline's own method, or (an own reference not made) the images against each
// other, a difference taken for the methods' only while both drew and their drawn pixels agree
// within 1 %.
std::string skinningMethodNote(const PairVerdict& v, const std::string& a, const std::string& b) {
  if (!v.skinApplies) return "";
  const std::string which = "skinned scene: " + a + " blends joints by " + report::skinBlendOf(a) + ", " + b + " by " +
                            report::skinBlendOf(b) + "; the two methods pose a skinned mesh differently by design (LBS "
                            "loses volume where joints turn far apart)";
  if (v.byOwnMethod)
    return which + ", so each is judged against its own method's reference, with the thresholds given (below, beside "
                   "its figures against matrix)";
  std::string why;
  for (const SkinnedFrameJudgement& j : v.skin)
    if (!j.judged) why = j.pipeline + "'s own method's reference could not be made (" + j.why + "), so it is judged "
                         "against " + a + " (the strict reading)";
  if (v.shape.failed)
    return which + "; " + why + ": a difference is taken for the methods' only while both images drew and their drawn "
                   "pixels agree within 1 %; here they do not, so it fails (look for a wrong pose, scale or a missing "
                   "mesh in the images)";
  return which + "; " + why + ": differences there are the methods' expected difference, not an error";
}

// The decisive drawn-pixel failure: the own method's judgement's reason, else the pair's.
std::string drawnFailure(const PairVerdict& v) {
  if (v.byOwnMethod)
    for (const SkinnedFrameJudgement& j : v.skin)
      if (j.vsReference.drawn.failed) return j.reason;
  return v.shape.reason;
}

json judgedJson(const PairVerdict& v) {
  json pipelines = json::array();
  for (const SkinnedFrameJudgement& j : v.skin) pipelines.push_back(toJson(j));
  return {{"applies", v.skinApplies}, {"byOwnMethod", v.byOwnMethod}, {"pipelines", pipelines}};
}

// "rest" or "anim 0 'Walk' t=0.500": the frame compared, for the JUnit case's name.
std::string frameName(const Scene& scene, const FrameSettings& settings) {
  if (settings.anim.anim < 0 || size_t(settings.anim.anim) >= scene.animations.size()) return "rest";
  char b[64];
  std::snprintf(b, sizeof b, "' t=%.3f", double(settings.anim.time));
  return "anim " + std::to_string(settings.anim.anim) + " '" + scene.animations[size_t(settings.anim.anim)].name + b;
}

int compareError(const std::string& message) { return commandError("compare", message); }

// --pipelines, when given: exactly two different registered names.
Status checkComparePipelines(const options::Args& args) {
  if (!args.has("pipelines")) return {};
  const std::vector<std::string> given = splitList(args.get("pipelines", ""));
  if (given.size() != 2) return Status::fail("--pipelines needs exactly two names, e.g. matrix,motor");
  if (given[0] == given[1]) return Status::fail("--pipelines " + given[0] + "," + given[1] + ": two different pipelines");
  return checkPipelineNames("--pipelines", given);
}

// The outputs before the (slow) load and render: -o not a file, --size well formed, the scene's
// name (cheap), then the folder created and --junit's place writable.
Status prepareCompareOutputs(const options::Args& args, const std::string& junitPath) {
  namespace fs = std::filesystem;
  const std::string dir = args.get("o", args.get("output", ""));
  std::error_code ec;
  if (!dir.empty() && fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    return Status::fail("-o " + dir + ": is a file; compare writes a folder (images, diff, metrics.json)");
  args.size("size", 512, 512);  // a malformed --size is refused before the folder is made
  if (args.positional().size() == 1)
    if (Status ok = checkSceneSpec(args.positional()[0]); !ok) return ok;
  if (!dir.empty())
    if (Status ok = prepareOutputFolder("-o", dir, "A.png, B.png, diff.png, diff_legend.png, flip.png, metrics.json"); !ok)
      return ok;
  if (!junitPath.empty())
    if (Status ok = prepareOutputFile("--junit", junitPath); !ok) return ok;
  return {};
}

// One compare run's reporting: the notes on stderr (not with --quiet) and the JUnit file's one
// case (classname the scene, name "A vs B <frame>"; an error after the options is its error case).
struct CompareRun {
  bool quiet = false;
  std::string junitPath;  // --junit (empty: none written)
  JunitCase junit{"compare", "", 0, JunitCase::Kind::Error, "", ""};
};

void compareNotes(const CompareRun& run, const std::vector<std::string>& lines) {
  if (!run.quiet) commandNotes("compare", lines);
}

int writeCase(const CompareRun& run) {
  if (Status w = run.junitPath.empty() ? Status{} : writeJunit(run.junitPath, "motorbench compare", {run.junit}); !w)
    return compareError(w.error());
  return 0;
}

// An error after the options: the JUnit case's error, then on stderr (exit 2).
int runError(CompareRun& run, const std::string& message) {
  run.junit.kind = JunitCase::Kind::Error;
  run.junit.message = message;
  writeCase(run);
  return compareError(message);
}

// --pipelines, else the paper's pair in the scene's space (matrix,motor; s3_matrix,s3_motor;
// h3_...): the first two registered names (the registry lists the variants after them).
std::vector<std::string> comparedPipelines(const options::Args& args, const Scene& scene) {
  if (args.has("pipelines")) return splitList(args.get("pipelines", ""));
  std::vector<std::string> pair = pipelineNames(scene.curved.space);
  pair.resize(2);
  return pair;
}

// Both frames, each pipeline's fallbacks noted as it is drawn.
Result<std::vector<Frame>> renderPair(const CompareRun& run, const Scene& scene, const std::vector<std::string>& names,
                                      const FrameSettings& settings) {
  std::vector<Frame> frames;
  for (const std::string& name : names) {
    auto frame = renderFrame(scene, name, settings);
    if (!frame) return Result<std::vector<Frame>>::fail(frame.error());
    compareNotes(run, pipelineFallbackLines(name, frame->stats));
    frames.push_back(frame.take());
  }
  return frames;
}

// The two images measured against each other (the first pipeline is FLIP's reference).
struct PairFigures {
  ImageMetrics metrics;
  FlipResult flip;
  int64_t drawn[2] = {0, 0};
};

Result<PairFigures> measurePair(const std::vector<Frame>& frames) {
  auto metrics = compareImages(frames[0].image, frames[1].image);
  if (!metrics) return Result<PairFigures>::fail(metrics.error());
  auto flip = computeFlip(frames[0].image, frames[1].image);
  if (!flip) return Result<PairFigures>::fail(flip.error());
  return PairFigures{*metrics, flip.take(), {drawnPixels(frames[0].image), drawnPixels(frames[1].image)}};
}

// DIR/<a>.png, DIR/<b>.png, diff.png, diff_legend.png (its warning noted) and flip.png.
Status writeCompareImages(const CompareRun& run, const std::string& dir, const std::vector<std::string>& names,
                          const std::vector<Frame>& frames, const FlipResult& flip) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return Status::fail(dir + ": cannot create folder: " + ec.message());
  for (size_t i = 0; i < 2; ++i)
    if (Status s = writeImage((fs::path(dir) / (names[i] + ".png")).string(), frames[i].image); !s) return s;
  if (Status d = writeImage((fs::path(dir) / "diff.png").string(), diffHeatmap(frames[0].image, frames[1].image)); !d)
    return d;
  std::string legendWarning;
  if (Status legend = writeImage((fs::path(dir) / "diff_legend.png").string(), heatLegend(&legendWarning)); !legend)
    return legend;
  if (!legendWarning.empty()) compareNotes(run, {"warning: " + legendWarning});
  return writeImage((fs::path(dir) / "flip.png").string(), flipErrorImage(flip));
}

// Per pipeline judged, the image it was judged against.
json judgedAgainstJson(const PairVerdict& verdict, const std::vector<std::string>& names) {
  json judgedAgainst = json::object();
  if (verdict.byOwnMethod)
    for (const SkinnedFrameJudgement& j : verdict.skin) judgedAgainst[j.pipeline] = j.reference;
  else
    judgedAgainst[names[1]] = names[0];
  return judgedAgainst;
}

json animationJson(const Scene& scene, const FrameSettings& settings) {
  if (settings.anim.anim < 0) return json(nullptr);
  const auto& a = scene.animations[size_t(settings.anim.anim)];
  return {{"index", settings.anim.anim}, {"name", a.name}, {"duration", a.duration}, {"time", settings.anim.time}};
}

json appliedThresholdsJson(const Thresholds& t, bool given) {
  return {{"applied", given},
          {"units", "fail, hardfail: channel difference / 255 (0..1); failpercent: % of pixels"},
          {"fail", t.fail},
          {"failpercent", t.failPercent},
          {"hardfail", std::isinf(t.hardFail) ? json(nullptr) : json(t.hardFail)}};
}

json verdictJson(const PairVerdict& verdict, const std::vector<std::string>& names, bool thresholdsGiven) {
  const bool nothingDrawn = verdict.shape.kind == DrawnCheck::Kind::NothingDrawn;
  const bool failed = verdict.failed;
  return {{"judged", (thresholdsGiven || verdict.shape.failed) && !nothingDrawn},
          {"text", nothingDrawn ? "nothing drawn" : failed ? "fail" : !thresholdsGiven ? "no threshold given" : "pass"},
          {"failed", failed || (thresholdsGiven && nothingDrawn)},
          {"failPercent", verdict.failPercent},
          {"judgedAgainst", judgedAgainstJson(verdict, names)},  // pipeline: the image it was judged against
          {"reason", nothingDrawn ? json("neither image drew any pixel")
                     : failed || thresholdsGiven ? json(verdict.reason) : json(nullptr)}};
}

// DIR/metrics.json: the frame, both images' figures, the checks and the verdict.
json compareMetricsJson(const Scene& scene, const FrameSettings& settings, const std::vector<std::string>& names,
                 const std::vector<Frame>& frames, const PairFigures& fig, const PairVerdict& verdict,
                 const Thresholds& t, bool thresholdsGiven) {
  const DrawnCheck& shape = verdict.shape;
  return {{"scene", scene.source},
          {"pipelines", names},
          {"images", {names[0] + ".png", names[1] + ".png"}},
          {"diff", "diff.png"},
          {"diffLegend", heatLegendJson()},
          {"flipMap", "flip.png"},  // magma: black 0 .. light yellow 1
          {"settings", toJson(settings)},
          {"animation", animationJson(scene, settings)},
          {"loaderFallbacks", loaderFallbackJson(scene)},
          {"view", toJson(frames[0].view)},
          {"gl", toJson(frames[0].gl)},  // both images: one device (the equivalence figures)
          {"metrics", toJson(fig.metrics, fig.flip)},
          {"drawnPixels",
           {{names[0], fig.drawn[0]}, {names[1], fig.drawn[1]}, {"total", int64_t(fig.metrics.width) * fig.metrics.height}}},
          {"skinningMethods", {{names[0], report::skinBlendOf(names[0])}, {names[1], report::skinBlendOf(names[1])},
                               {"methodsDiffer", verdict.skinApplies},
                               {"differByDesign", verdict.skinApplies && shape.skinningMethodNote}}},
          {"skinJudgement", judgedJson(verdict)},
          {"drawnCheck", toJson(shape)},
          {"thresholds", appliedThresholdsJson(t, thresholdsGiven)},
          {"verdict", verdictJson(verdict, names, thresholdsGiven)},
          {"stats", {toJson(frames[0].stats), toJson(frames[1].stats)}}};  // in --pipelines order
}

// What was measured, one line each: drawn pixels, the differences, FLIP, the skinning note and
// each own-method judgement.
std::vector<std::string> measuredLines(const std::vector<std::string>& names, const PairFigures& fig,
                                       const PairVerdict& verdict, const std::string& skinning) {
  std::vector<std::string> measured;
  char line[256];
  std::snprintf(line, sizeof line, "drawn pixels (not background): %s %lld, %s %lld of %lld", names[0].c_str(),
                (long long)fig.drawn[0], names[1].c_str(), (long long)fig.drawn[1],
                (long long)fig.metrics.width * fig.metrics.height);
  measured.push_back(line);
  for (const std::string& l : differenceLines(fig.metrics)) measured.push_back(l);
  std::snprintf(line, sizeof line, "%s (LDR-FLIP, 0..1, %.0f pixels per degree; map: flip.png)", flipText(fig.flip).c_str(),
                fig.flip.pixelsPerDegree);
  measured.push_back(line);
  if (!skinning.empty()) measured.push_back("note: " + skinning);
  for (const SkinnedFrameJudgement& j : verdict.skin)
    for (const std::string& l : judgementLines(j)) measured.push_back(l);
  return measured;
}

// The verdict line's tail: " -> PASS (...)", " -> FAIL (why)" or not judged.
std::string verdictText(const PairVerdict& verdict, bool thresholdsGiven) {
  std::string judgedBy;  // "motor against the motor-blend reference"
  for (const SkinnedFrameJudgement& j : verdict.skin)
    if (verdict.byOwnMethod)
      judgedBy += (judgedBy.empty() ? "" : ", ") + j.pipeline + " against " +
                  (j.reference == kMatrixReference ? j.reference : "the " + j.reference);
  if (verdict.failed)
    return " -> FAIL (" + verdict.reason +
           (verdict.skinApplies && !verdict.byOwnMethod && verdict.shape.skinningMethodNote
                ? "; the skinning methods differ by design, see the note" : "") + ")";
  if (thresholdsGiven) return " -> PASS (" + (judgedBy.empty() ? std::string() : judgedBy + ": ") + "within the thresholds given)";
  if (verdict.byOwnMethod)
    return " -> no threshold given (" + judgedBy + ": drawn pixels within 1 %; --fail/--failpercent/--hardfail "
           "judge the pixels; exit 0)";
  return " -> no threshold given, not judged (--fail/--failpercent/--hardfail judge; exit 0)";
}

// The end of a run: the measured lines (not with --quiet), the drawn-pixel failure, the verdict
// line and the JUnit case; two background-only frames are said, and with a threshold an error.
int reportVerdict(CompareRun& run, const Scene& scene, const std::vector<std::string>& names,
                  const std::vector<std::string>& measured, const PairFigures& fig, const PairVerdict& verdict,
                  bool thresholdsGiven) {
  const char* source = scene.source.c_str();
  const bool nothingDrawn = verdict.shape.kind == DrawnCheck::Kind::NothingDrawn;
  if (!run.quiet) {
    std::printf("%s: %s vs %s, %dx%d\n", source, names[0].c_str(), names[1].c_str(), fig.metrics.width, fig.metrics.height);
    for (const std::string& l : measured) std::printf("  %s\n", l.c_str());
  }
  for (const std::string& l : measured) run.junit.detail += (run.junit.detail.empty() ? "" : "\n") + l;
  // Two background-only frames agree trivially: nothing was compared.
  if (nothingDrawn && !thresholdsGiven) {  // nothing judged, but said
    compareNotes(run, {"warning: neither " + names[0] + " nor " + names[1] + " drew any pixel (both images are "
                "background only): nothing was compared"});
  } else if (nothingDrawn) {
    std::printf("%s: %s vs %s -> NOT COMPARED\n", source, names[0].c_str(), names[1].c_str());
    return runError(run, "neither " + names[0] + " nor " + names[1] + " drew any pixel (both images are background only: the " +
                    "scene is off screen, empty or scaled to zero at this pose); nothing was compared, so it cannot pass");
  }
  if (verdict.shape.failed && !run.quiet) std::printf("  drawn-pixel check: FAIL: %s\n", drawnFailure(verdict).c_str());
  std::printf("%s: %s vs %s%s\n", source, names[0].c_str(), names[1].c_str(), verdictText(verdict, thresholdsGiven).c_str());
  run.junit.kind = verdict.failed ? JunitCase::Kind::Fail : nothingDrawn ? JunitCase::Kind::Skipped : JunitCase::Kind::Pass;
  run.junit.message = verdict.failed ? verdict.reason : nothingDrawn ? "neither image drew any pixel: nothing compared" : "";
  if (writeCase(run) != 0) return 2;
  return verdict.failed ? 1 : 0;
}

int runCompare(const std::vector<std::string>& argv) {
  options::Args args(argv, sceneCommandOptions({"pipelines", "fail", "failpercent", "hardfail", "junit"}, {"quiet"}));
  if (!args.error().empty()) return compareError(args.error());
  CompareRun run;
  run.quiet = args.has("quiet");
  run.junitPath = args.get("junit", "");
  // Everything about the options is checked before the (slow) load and render.
  if (Status ok = checkComparePipelines(args); !ok) return compareError(ok.error());
  const bool thresholdsGiven = failThresholdGiven(args);
  const Thresholds t = compareThresholds(args);  // harness/render/thresholds.h: the byte-step trap refused
  if (Status ok = prepareCompareOutputs(args, run.junitPath); !ok) return compareError(ok.error());
  if (!args.positional().empty()) run.junit.classname = args.positional()[0];

  auto cmd = parseSceneCommand(args, "DIR");
  if (!cmd) return runError(run, cmd.error());
  Scene& scene = cmd->scene;
  const FrameSettings& settings = cmd->settings;
  const std::vector<std::string> names = comparedPipelines(args, scene);
  if (names.size() != 2) return runError(run, "--pipelines needs exactly two names, e.g. matrix,motor");
  run.junit.name = names[0] + " vs " + names[1] + " " + frameName(scene, settings);
  compareNotes(run, cmd->notes);
  compareNotes(run, loaderFallbackLines(scene));
  compareNotes(run, unsupportedLines(scene));
  compareNotes(run, describeFrame(scene, settings));

  auto frames = renderPair(run, scene, names, settings);
  if (!frames) return runError(run, frames.error());
  compareNotes(run, {"drawn on " + describeGl((*frames)[0].gl) + " (both pipelines: one process, one device)"});
  auto fig = measurePair(*frames);
  if (!fig) return runError(run, fig.error());
  const PairVerdict verdict = judgePair(scene, settings, names, *frames, thresholdsGiven ? &t : nullptr);
  if (verdict.skinApplies && verdict.skin.empty()) return runError(run, verdict.reason);  // a reference frame's error
  const std::string skinning = skinningMethodNote(verdict, names[0], names[1]);

  const std::string& dir = cmd->output;
  if (Status ok = writeCompareImages(run, dir, names, *frames, fig->flip); !ok) return runError(run, ok.error());
  const json metrics = compareMetricsJson(scene, settings, names, *frames, *fig, verdict, t, thresholdsGiven);
  const std::string jsonPath = (std::filesystem::path(dir) / "metrics.json").string();
  if (Status w = writeTextFile(jsonPath, metrics.dump(2) + "\n"); !w) return runError(run, w.error());
  return reportVerdict(run, scene, names, measuredLines(names, *fig, verdict, skinning), *fig, verdict, thresholdsGiven);
}

}  // namespace
}  // namespace mb

MB_COMMAND(compare, "compare",
           "SCENE [--pipelines matrix,motor] [--anim A] [--time T] [--anim2 B --time2 T2 --blend W] "
           "[--camera C] [--size WxH] [--instances N] [--fail F(0..1)] [--failpercent P(0..100)] [--hardfail H(0..1)] "
           "[--gpu auto|llvmpipe|N] [--junit FILE] [--quiet] -o DIR",
           "render a scene with two pipelines; write both images, diff.png, diff_legend.png, flip.png and "
           "metrics.json (PSNR, LDR-FLIP); exit 1 when a threshold given is exceeded (F, H: channel difference / 255) or one image "
           "is empty or the drawn pixels differ by more than 1 % (skinned frames of two skinning methods: each pipeline against its "
           "own method's reference)",
           mb::runCompare);
MB_COMMAND_HELP(compare, "compare",
               "  SCENE              a .gltf/.glb file or a built-in scene name\n"
               "  -o, --output DIR   a folder (created): A.png, B.png, diff.png, diff_legend.png, flip.png, metrics.json\n"
               "  --pipelines A,B    the two pipelines (default matrix,motor; curved scenes: their space's pair)\n"
               "  --fail F           a channel difference: a fraction of full scale below 1 or byte steps N/255 (2/255);\n"
               "                     a plain 1 or more is refused (did you mean 1/255?) (default 1e-6: any difference;\n"
               "                     with none of --fail, --failpercent, --hardfail given, nothing is judged)\n"
               "  --failpercent P    % of pixels (0..100) allowed over F (default 0; with --hardfail alone 100)\n"
               "  --hardfail H       the largest channel difference allowed anywhere, as F (default none)\n"
               "  --anim A, --time T, --anim2 B, --time2 T2, --blend W, --camera C, --size WxH   as render\n"
               MB_INSTANCES_OPTION_HELP MB_GPU_OPTION_HELP
               "  --junit FILE       JUnit XML: one test case (classname the scene, name 'A vs B <frame>'), its failure\n"
               "                     or error with the reason (default: none written)\n"
               "  --quiet            print only the verdict line (errors still on stderr)\n"
               "  Skinned frame, pipelines of two skinning methods: each judged against its own method's reference (a\n"
               "  motor-blend pipeline: the motor-blend reference, the pose skinned on the CPU by the motor blend and drawn\n"
               "  by matrix; a linear-blend one: matrix), with the same thresholds; its figures against matrix beside them.\n"
               "  Exit 0 pass (or not judged), 1 a threshold exceeded, one image empty or drawn pixels more than 1 % apart\n"
               "  (with or without a threshold), 2 an error, or a threshold given and nothing drawn in either image.\n",
                "motorbench compare textured_box --failpercent 0.1 -o out/box", true);
