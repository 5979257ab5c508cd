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

int runCompare(const std::vector<std::string>& argv) {
  auto fail = [](const std::string& message) { return commandError("compare", message); };
  Args args(argv, sceneCommandOptions({"pipelines", "fail", "failpercent", "hardfail", "junit"}, {"quiet"}));
  if (!args.error().empty()) return fail(args.error());
  const bool quiet = args.has("quiet");
  const std::string junitPath = args.get("junit", "");
  auto notes = [quiet](const std::vector<std::string>& lines) {
    if (!quiet) commandNotes("compare", lines);
  };
  // Everything about the options is checked before the (slow) load and render.
  if (args.has("pipelines")) {
    const std::vector<std::string> given = splitList(args.get("pipelines", ""));
    if (given.size() != 2) return fail("--pipelines needs exactly two names, e.g. matrix,motor");
    if (given[0] == given[1]) return fail("--pipelines " + given[0] + "," + given[1] + ": two different pipelines");
    if (Status ok = checkPipelineNames("--pipelines", given); !ok) return fail(ok.error());
  }
  const bool thresholdsGiven = failThresholdGiven(args);
  const Thresholds t = compareThresholds(args);  // harness/render/thresholds.h: the byte-step trap refused
  {
    namespace fs = std::filesystem;
    const std::string dir = args.get("o", args.get("output", ""));
    std::error_code ec;
    if (!dir.empty() && fs::exists(dir, ec) && !fs::is_directory(dir, ec))
      return fail("-o " + dir + ": is a file; compare writes a folder (images, diff, metrics.json)");
    args.size("size", 512, 512);  // a malformed --size is refused before the folder is made
    // The scene's name first (cheap), then the folder: created now, before the renders.
    if (args.positional().size() == 1)
      if (Status ok = checkSceneSpec(args.positional()[0]); !ok) return fail(ok.error());
    if (!dir.empty())
      if (Status ok = prepareOutputFolder("-o", dir, "A.png, B.png, diff.png, diff_legend.png, flip.png, metrics.json"); !ok)
        return fail(ok.error());
    if (!junitPath.empty())
      if (Status ok = prepareOutputFile("--junit", junitPath); !ok) return fail(ok.error());
  }
  // The JUnit file's one case: classname the scene, name "A vs B <frame>"; an error after the
  // options is its error case.
  JunitCase junit{"compare", "", 0, JunitCase::Kind::Error, "", ""};
  if (!args.positional().empty()) junit.classname = args.positional()[0];
  auto writeCase = [&]() {
    if (Status w = junitPath.empty() ? Status{} : writeJunit(junitPath, "motorbench compare", {junit}); !w)
      return fail(w.error());
    return 0;
  };
  auto error = [&](const std::string& message) {
    junit.kind = JunitCase::Kind::Error;
    junit.message = message;
    writeCase();
    return fail(message);
  };
  auto cmd = parseSceneCommand(args, "DIR");
  if (!cmd) return error(cmd.error());
  const std::string& dir = cmd->output;
  const Scene& scene = cmd->scene;
  const FrameSettings& settings = cmd->settings;
  // Default: the paper's pair in the scene's space (matrix,motor; s3_matrix,s3_motor; h3_...),
  // the first two registered names (the registry lists the variants after them).
  std::vector<std::string> pair = pipelineNames(scene.curved.space);
  pair.resize(2);
  std::vector<std::string> names = args.has("pipelines") ? splitList(args.get("pipelines", "")) : pair;
  if (names.size() != 2) return error("--pipelines needs exactly two names, e.g. matrix,motor");
  junit.name = names[0] + " vs " + names[1] + " " + frameName(scene, settings);
  notes(cmd->notes);
  notes(loaderFallbackLines(scene));
  notes(unsupportedLines(scene));
  notes(describeFrame(scene, settings));

  std::vector<Frame> frames;
  for (const std::string& name : names) {
    auto frame = renderFrame(scene, name, settings);
    if (!frame) return error(frame.error());
    notes(pipelineFallbackLines(name, frame->stats));
    frames.push_back(frame.take());
  }
  notes({"drawn on " + describeGl(frames[0].gl) + " (both pipelines: one process, one device)"});
  auto metrics = compareImages(frames[0].image, frames[1].image);
  if (!metrics) return error(metrics.error());
  auto flip = computeFlip(frames[0].image, frames[1].image);  // the first pipeline is the reference
  if (!flip) return error(flip.error());
  const int64_t drawn[2] = {drawnPixels(frames[0].image), drawnPixels(frames[1].image)};
  const PairVerdict verdict = judgePair(cmd->scene, settings, names, frames, thresholdsGiven ? &t : nullptr);
  if (verdict.skinApplies && verdict.skin.empty()) return error(verdict.reason);  // a reference frame's error
  const DrawnCheck& shape = verdict.shape;
  const std::string skinning = skinningMethodNote(verdict, names[0], names[1]);
  const bool nothingDrawn = shape.kind == DrawnCheck::Kind::NothingDrawn;
  const bool failed = verdict.failed;
  const std::string& reason = verdict.reason;
  json judgedAgainst = json::object();
  if (verdict.byOwnMethod)
    for (const SkinnedFrameJudgement& j : verdict.skin) judgedAgainst[j.pipeline] = j.reference;
  else
    judgedAgainst[names[1]] = names[0];

  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return error(dir + ": cannot create folder: " + ec.message());
  namespace fs = std::filesystem;
  for (size_t i = 0; i < 2; ++i) {
    Status s = writeImage((fs::path(dir) / (names[i] + ".png")).string(), frames[i].image);
    if (!s) return error(s.error());
  }
  Status d = writeImage((fs::path(dir) / "diff.png").string(),
                        diffHeatmap(frames[0].image, frames[1].image));
  if (!d) return error(d.error());
  std::string legendWarning;
  Status legend = writeImage((fs::path(dir) / "diff_legend.png").string(), heatLegend(&legendWarning));
  if (!legend) return error(legend.error());
  if (!legendWarning.empty()) notes({"warning: " + legendWarning});
  if (Status f = writeImage((fs::path(dir) / "flip.png").string(), flipErrorImage(*flip)); !f) return error(f.error());

  nlohmann::json j = {
      {"scene", scene.source},
      {"pipelines", names},
      {"images", {names[0] + ".png", names[1] + ".png"}},
      {"diff", "diff.png"},
      {"diffLegend", heatLegendJson()},
      {"flipMap", "flip.png"},  // magma: black 0 .. light yellow 1
      {"settings", toJson(settings)},
      {"animation", settings.anim.anim < 0
                        ? nlohmann::json(nullptr)
                        : nlohmann::json{{"index", settings.anim.anim},
                                         {"name", scene.animations[size_t(settings.anim.anim)].name},
                                         {"duration", scene.animations[size_t(settings.anim.anim)].duration},
                                         {"time", settings.anim.time}}},
      {"loaderFallbacks", loaderFallbackJson(scene)},
      {"view", toJson(frames[0].view)},
      {"gl", toJson(frames[0].gl)},  // both images: one device (the equivalence figures)
      {"metrics", toJson(*metrics, *flip)},
      {"drawnPixels", {{names[0], drawn[0]}, {names[1], drawn[1]}, {"total", int64_t(metrics->width) * metrics->height}}},
      {"skinningMethods", {{names[0], report::skinBlendOf(names[0])}, {names[1], report::skinBlendOf(names[1])},
                           {"methodsDiffer", verdict.skinApplies},
                           {"differByDesign", verdict.skinApplies && shape.skinningMethodNote}}},
      {"skinJudgement", judgedJson(verdict)},
      {"drawnCheck", toJson(shape)},
      {"thresholds", {{"applied", thresholdsGiven},
                      {"units", "fail, hardfail: channel difference / 255 (0..1); failpercent: % of pixels"},
                      {"fail", t.fail},
                      {"failpercent", t.failPercent},
                      {"hardfail", std::isinf(t.hardFail) ? nlohmann::json(nullptr)
                                                          : nlohmann::json(t.hardFail)}}},
      {"verdict", {{"judged", (thresholdsGiven || shape.failed) && !nothingDrawn},
                   {"text", nothingDrawn ? "nothing drawn" : failed ? "fail" : !thresholdsGiven ? "no threshold given" : "pass"},
                   {"failed", failed || (thresholdsGiven && nothingDrawn)},
                   {"failPercent", verdict.failPercent},
                   {"judgedAgainst", judgedAgainst},  // pipeline: the image it was judged against
                   {"reason", nothingDrawn ? nlohmann::json("neither image drew any pixel")
                              : failed || thresholdsGiven ? nlohmann::json(reason) : nlohmann::json(nullptr)}}},
      {"stats", {toJson(frames[0].stats), toJson(frames[1].stats)}}};  // in --pipelines order
  std::string jsonPath = (fs::path(dir) / "metrics.json").string();
  if (Status w = writeTextFile(jsonPath, j.dump(2) + "\n"); !w) return error(w.error());
  // What was measured, one line each (not with --quiet), then the verdict line.
  std::vector<std::string> measured;
  char line[256];
  std::snprintf(line, sizeof line, "drawn pixels (not background): %s %lld, %s %lld of %lld", names[0].c_str(),
                (long long)drawn[0], names[1].c_str(), (long long)drawn[1], (long long)metrics->width * metrics->height);
  measured.push_back(line);
  for (const std::string& l : differenceLines(*metrics)) measured.push_back(l);
  std::snprintf(line, sizeof line, "%s (LDR-FLIP, 0..1, %.0f pixels per degree; map: flip.png)", flipText(*flip).c_str(),
                flip->pixelsPerDegree);
  measured.push_back(line);
  if (!skinning.empty()) measured.push_back("note: " + skinning);
  for (const SkinnedFrameJudgement& j : verdict.skin)
    for (const std::string& l : judgementLines(j)) measured.push_back(l);
  if (!quiet) {
    std::printf("%s: %s vs %s, %dx%d\n", scene.source.c_str(), names[0].c_str(), names[1].c_str(), metrics->width,
                metrics->height);
    for (const std::string& l : measured) std::printf("  %s\n", l.c_str());
  }
  for (const std::string& l : measured) junit.detail += (junit.detail.empty() ? "" : "\n") + l;
  // Two background-only frames agree trivially: nothing was compared.
  if (nothingDrawn && !thresholdsGiven) {  // nothing judged, but said
    notes({"warning: neither " + names[0] + " nor " + names[1] + " drew any pixel (both images are "
                             "background only): nothing was compared"});
  } else if (nothingDrawn) {
    std::printf("%s: %s vs %s -> NOT COMPARED\n", scene.source.c_str(), names[0].c_str(), names[1].c_str());
    return error("neither " + names[0] + " nor " + names[1] + " drew any pixel (both images are background only: the " +
                "scene is off screen, empty or scaled to zero at this pose); nothing was compared, so it cannot pass");
  }
  if (shape.failed && !quiet) std::printf("  drawn-pixel check: FAIL: %s\n", drawnFailure(verdict).c_str());
  std::string judgedBy;  // "motor against the motor-blend reference"
  for (const SkinnedFrameJudgement& j : verdict.skin)
    if (verdict.byOwnMethod)
      judgedBy += (judgedBy.empty() ? "" : ", ") + j.pipeline + " against " +
                  (j.reference == kMatrixReference ? j.reference : "the " + j.reference);
  std::string verdictText = " -> no threshold given, not judged (--fail/--failpercent/--hardfail judge; exit 0)";
  if (verdict.byOwnMethod && !thresholdsGiven && !failed)
    verdictText = " -> no threshold given (" + judgedBy + ": drawn pixels within 1 %; --fail/--failpercent/--hardfail "
                  "judge the pixels; exit 0)";
  if (failed)
    verdictText = " -> FAIL (" + reason + (verdict.skinApplies && !verdict.byOwnMethod && shape.skinningMethodNote
                                               ? "; the skinning methods differ by design, see the note" : "") + ")";
  else if (thresholdsGiven)
    verdictText = " -> PASS (" + (judgedBy.empty() ? std::string() : judgedBy + ": ") + "within the thresholds given)";
  std::printf("%s: %s vs %s%s\n", scene.source.c_str(), names[0].c_str(), names[1].c_str(), verdictText.c_str());
  junit.kind = failed ? JunitCase::Kind::Fail : nothingDrawn ? JunitCase::Kind::Skipped : JunitCase::Kind::Pass;
  junit.message = failed ? reason : nothingDrawn ? "neither image drew any pixel: nothing compared" : "";
  if (writeCase() != 0) return 2;
  return failed ? 1 : 0;
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
