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
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

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
#include "harness/render/thresholds.h"
#include "harness/report/report_scene.h"
#include "harness/report/report_sources.h"

namespace mb {
namespace {

// True when the two pipelines blend joints by different methods (LBS vs motor blending).
bool methodsDiffer(const std::string& a, const std::string& b) {
  const std::string ma = report::skinBlendOf(a), mbl = report::skinBlendOf(b);
  return !ma.empty() && !mbl.empty() && ma != mbl;
}

// "matrix blends joints with linear blend skinning, motor blends joint motors": only where the
// drawn-pixel check lets the difference be the skinning method's (skinned primitives drawn, the
// drawn pixels within 1 %); where the check failed, the note says why it is not offered.
std::string skinningMethodNote(const DrawnCheck& check, bool skinnedDrawn, const std::string& a,
                               const std::string& b) {
  if (!skinnedDrawn || !methodsDiffer(a, b)) return "";
  const std::string which = "skinned scene: " + a + " blends joints by " + report::skinBlendOf(a) + ", " + b + " by " +
                            report::skinBlendOf(b);
  if (check.failed)
    return which + "; but a difference is taken for the methods' only while both images drew and their drawn "
                   "pixels agree within 1 %; here they do not, so it fails (look for a wrong pose, scale or a missing "
                   "mesh in the images)";
  if (!check.skinningMethodNote) return "";
  return which + "; the two methods pose a skinned mesh differently by design (LBS loses volume where joints turn far "
                 "apart), so differences there are the methods' expected difference, not an error (motorbench report "
                 "measures them apart: summary.skinningMethodImages)";
}

int runCompare(const std::vector<std::string>& argv) {
  auto fail = [](const std::string& message) { return commandError("compare", message); };
  Args args(argv, sceneCommandOptions({"pipelines", "fail", "failpercent", "hardfail"}));
  if (!args.error().empty()) return fail(args.error());
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
  }
  auto cmd = parseSceneCommand(args, "DIR");
  if (!cmd) return fail(cmd.error());
  const std::string& dir = cmd->output;
  const Scene& scene = cmd->scene;
  const FrameSettings& settings = cmd->settings;
  // Default: the paper's pair in the scene's space (matrix,motor; s3_matrix,s3_motor; h3_...),
  // the first two registered names (the registry lists the variants after them).
  std::vector<std::string> pair = pipelineNames(scene.curved.space);
  pair.resize(2);
  std::vector<std::string> names = args.has("pipelines") ? splitList(args.get("pipelines", "")) : pair;
  if (names.size() != 2) return fail("--pipelines needs exactly two names, e.g. matrix,motor");
  commandNotes("compare", cmd->notes);
  commandNotes("compare", loaderFallbackLines(scene));
  commandNotes("compare", unsupportedLines(scene));
  commandNotes("compare", describeFrame(scene, settings));

  std::vector<Frame> frames;
  for (const std::string& name : names) {
    auto frame = renderFrame(scene, name, settings);
    if (!frame) return fail(frame.error());
    commandNotes("compare", pipelineFallbackLines(name, frame->stats));
    frames.push_back(frame.take());
  }
  commandNotes("compare", {"drawn on " + describeGl(frames[0].gl) + " (both pipelines: one process, one device)"});
  auto metrics = compareImages(frames[0].image, frames[1].image);
  if (!metrics) return fail(metrics.error());
  auto flip = computeFlip(frames[0].image, frames[1].image);  // the first pipeline is the reference
  if (!flip) return fail(flip.error());
  Verdict verdict = judge(frames[0].image, frames[1].image, t);
  const int64_t drawn[2] = {drawnPixels(frames[0].image), drawnPixels(frames[1].image)};
  // Skinned primitives drawn: skinned vertices on nodes the scene reaches (the report's vertexMix).
  const bool skinnedDrawn = report::vertexMix(scene).value("skinned", 0L) > 0;
  const DrawnCheck shape =
      checkDrawn(names[0], drawn[0], names[1], drawn[1], skinnedDrawn, methodsDiffer(names[0], names[1]));
  const std::string skinning = skinningMethodNote(shape, skinnedDrawn, names[0], names[1]);
  const bool nothingDrawn = shape.kind == DrawnCheck::Kind::NothingDrawn;
  const bool failed = shape.failed || (thresholdsGiven && verdict.failed);
  std::string reason = shape.reason;  // the drawn-pixel check first, then the thresholds'
  if (thresholdsGiven && verdict.failed) reason += (reason.empty() ? "" : "; ") + verdict.reason;

  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return fail(dir + ": cannot create folder: " + ec.message());
  namespace fs = std::filesystem;
  for (size_t i = 0; i < 2; ++i) {
    Status s = writeImage((fs::path(dir) / (names[i] + ".png")).string(), frames[i].image);
    if (!s) return fail(s.error());
  }
  Status d = writeImage((fs::path(dir) / "diff.png").string(),
                        diffHeatmap(frames[0].image, frames[1].image));
  if (!d) return fail(d.error());
  std::string legendWarning;
  Status legend = writeImage((fs::path(dir) / "diff_legend.png").string(), heatLegend(&legendWarning));
  if (!legend) return fail(legend.error());
  if (!legendWarning.empty()) commandNotes("compare", {"warning: " + legendWarning});
  if (Status f = writeImage((fs::path(dir) / "flip.png").string(), flipErrorImage(*flip)); !f) return fail(f.error());

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
                           {"methodsDiffer", skinnedDrawn && methodsDiffer(names[0], names[1])},
                           {"differByDesign", shape.skinningMethodNote}}},
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
                   {"reason", nothingDrawn ? nlohmann::json("neither image drew any pixel")
                              : failed || thresholdsGiven ? nlohmann::json(reason) : nlohmann::json(nullptr)}}},
      {"stats", {toJson(frames[0].stats), toJson(frames[1].stats)}}};  // in --pipelines order
  std::string jsonPath = (fs::path(dir) / "metrics.json").string();
  if (Status w = writeTextFile(jsonPath, j.dump(2) + "\n"); !w) return fail(w.error());
  // What was measured, one line each, then the verdict line.
  std::printf("%s: %s vs %s, %dx%d\n", scene.source.c_str(), names[0].c_str(), names[1].c_str(), metrics->width,
              metrics->height);
  std::printf("  drawn pixels (not background): %s %lld, %s %lld of %lld\n", names[0].c_str(), (long long)drawn[0],
              names[1].c_str(), (long long)drawn[1], (long long)metrics->width * metrics->height);
  for (const std::string& line : differenceLines(*metrics)) std::printf("  %s\n", line.c_str());
  std::printf("  %s (LDR-FLIP, 0..1, %.0f pixels per degree; map: flip.png)\n", flipText(*flip).c_str(),
              flip->pixelsPerDegree);
  if (!skinning.empty()) std::printf("  note: %s\n", skinning.c_str());
  // Two background-only frames agree trivially: nothing was compared.
  if (nothingDrawn && !thresholdsGiven) {  // nothing judged, but said
    commandNotes("compare", {"warning: neither " + names[0] + " nor " + names[1] + " drew any pixel (both images are "
                             "background only): nothing was compared"});
  } else if (nothingDrawn) {
    std::printf("%s: %s vs %s -> NOT COMPARED\n", scene.source.c_str(), names[0].c_str(), names[1].c_str());
    return fail("neither " + names[0] + " nor " + names[1] + " drew any pixel (both images are background only: the " +
                "scene is off screen, empty or scaled to zero at this pose); nothing was compared, so it cannot pass");
  }
  if (shape.failed) std::printf("  drawn-pixel check: FAIL: %s\n", shape.reason.c_str());
  std::string verdictText = " -> no threshold given, not judged (--fail/--failpercent/--hardfail judge; exit 0)";
  if (failed)
    verdictText = " -> FAIL (" + reason + (shape.skinningMethodNote ? "; the skinning methods differ by design, see the note" : "") + ")";
  else if (thresholdsGiven)
    verdictText = " -> PASS (within the thresholds given)";
  std::printf("%s: %s vs %s%s\n", scene.source.c_str(), names[0].c_str(), names[1].c_str(), verdictText.c_str());
  return failed ? 1 : 0;
}

}  // namespace
}  // namespace mb

MB_COMMAND(compare, "compare",
           "SCENE [--pipelines matrix,motor] [--anim A] [--time T] [--anim2 B --time2 T2 --blend W] "
           "[--camera C] [--size WxH] [--instances N] [--fail F(0..1)] [--failpercent P(0..100)] [--hardfail H(0..1)] "
           "[--gpu auto|llvmpipe|N] -o DIR",
           "render a scene with two pipelines; write both images, diff.png, diff_legend.png, flip.png and "
           "metrics.json (PSNR, LDR-FLIP); exit 1 when a threshold given is exceeded (F, H: channel difference / 255) or one image "
           "is empty or the drawn pixels differ by more than 1 %",
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
               "  Exit 0 pass (or not judged), 1 a threshold exceeded, one image empty or drawn pixels more than 1 % apart\n"
               "  (with or without a threshold), 2 an error, or a threshold given and nothing drawn in either image.\n",
                "motorbench compare textured_box --failpercent 0.1 -o out/box", true);
