// motorbench compare SCENE [--pipelines A,B] [frame options] [--fail F --failpercent P
//   --hardfail H] -o DIR: renders both, writes DIR/A.png, DIR/B.png, DIR/diff.png and
// DIR/diff_legend.png and DIR/metrics.json, prints one summary line; exit 1 when the idiff
// thresholds are exceeded. Units: --fail and --hardfail are channel differences as a fraction
// of full scale (0..1; 1/255 = one byte step), --failpercent a percentage of pixels (0..100).
// Only the thresholds given judge: --hardfail alone fails only on the largest difference.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "harness/cli/command.h"
#include "harness/options/args.h"
#include "harness/render/counter_glossary.h"
#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"

namespace mb {
namespace {

std::string summaryLine(const std::string& scene, const std::string& a, const std::string& b,
                        const ImageMetrics& m, const Verdict* v) {
  char psnr[32];
  if (m.rmse == 0.0) std::snprintf(psnr, sizeof psnr, "inf");
  else std::snprintf(psnr, sizeof psnr, "%.2f", m.psnr);
  char line[512];
  std::snprintf(line, sizeof line,
                "%s: %s vs %s %dx%d: PSNR %s dB, RMSE %.6f, max %.0f/255 at (%d,%d), "
                ">1/255 %.3f%%, >2/255 %.3f%%, >4/255 %.3f%%",
                scene.c_str(), a.c_str(), b.c_str(), m.width, m.height, psnr, m.rmse,
                std::round(m.maxError * 255.0), m.maxX, m.maxY, 100 * m.fractionOver1,
                100 * m.fractionOver2, 100 * m.fractionOver4);
  std::string s = line;
  if (!v) s += " -> no threshold given, not judged (--fail/--failpercent/--hardfail judge; exit 0)";
  else s += v->failed ? " -> FAIL (" + v->reason + ")" : " -> PASS (within the thresholds given)";
  return s;
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
  }
  const bool thresholdsGiven = args.has("fail") || args.has("failpercent") || args.has("hardfail");
  Thresholds t;
  t.fail = args.real("fail", t.fail, 0.0, 1.0, "a channel difference as a fraction of full scale (1/255 = one byte step)");
  // --hardfail alone judges the largest difference only; --failpercent alone counts any change.
  t.failPercent = args.real("failpercent", args.has("fail") || !args.has("hardfail") ? 0.0 : 100.0, 0.0, 100.0,
                            "a percentage of pixels");
  t.hardFail = args.real("hardfail", t.hardFail, 0.0, 1.0, "a channel difference as a fraction of full scale");
  {
    namespace fs = std::filesystem;
    const std::string dir = args.get("o", args.get("output", ""));
    std::error_code ec;
    if (!dir.empty() && fs::exists(dir, ec) && !fs::is_directory(dir, ec))
      return fail("-o " + dir + ": is a file; compare writes a folder (images, diff, metrics.json)");
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
  commandNotes("compare", describeFrame(scene, settings));

  std::vector<Frame> frames;
  for (const std::string& name : names) {
    auto frame = renderFrame(scene, name, settings);
    if (!frame) return fail(frame.error());
    frames.push_back(frame.take());
  }
  auto metrics = compareImages(frames[0].image, frames[1].image);
  if (!metrics) return fail(metrics.error());
  Verdict verdict = judge(frames[0].image, frames[1].image, t);

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
  Status legend = writeImage((fs::path(dir) / "diff_legend.png").string(), heatLegend());
  if (!legend) return fail(legend.error());

  nlohmann::json j = {
      {"scene", scene.source},
      {"pipelines", names},
      {"images", {names[0] + ".png", names[1] + ".png"}},
      {"diff", "diff.png"},
      {"diffLegend", heatLegendJson()},
      {"settings", toJson(settings)},
      {"animation", settings.anim.anim < 0
                        ? nlohmann::json(nullptr)
                        : nlohmann::json{{"index", settings.anim.anim},
                                         {"name", scene.animations[size_t(settings.anim.anim)].name},
                                         {"duration", scene.animations[size_t(settings.anim.anim)].duration},
                                         {"time", settings.anim.time}}},
      {"loaderFallbacks", loaderFallbackJson(scene)},
      {"view", toJson(frames[0].view)},
      {"gl", {{"renderer", frames[0].glRenderer}, {"version", frames[0].glVersion},
              {"backend", frames[0].glBackend}}},
      {"metrics", toJson(*metrics)},
      {"thresholds", {{"applied", thresholdsGiven},
                      {"units", "fail, hardfail: channel difference / 255 (0..1); failpercent: % of pixels"},
                      {"fail", t.fail},
                      {"failpercent", t.failPercent},
                      {"hardfail", std::isinf(t.hardFail) ? nlohmann::json(nullptr)
                                                          : nlohmann::json(t.hardFail)}}},
      {"verdict", {{"judged", thresholdsGiven},
                   {"text", !thresholdsGiven ? "no threshold given" : verdict.failed ? "fail" : "pass"},
                   {"failed", thresholdsGiven && verdict.failed},
                   {"failPercent", verdict.failPercent},
                   {"reason", thresholdsGiven ? nlohmann::json(verdict.reason) : nlohmann::json(nullptr)}}},
      {"stats", {toJson(frames[0].stats), toJson(frames[1].stats)}}};  // in --pipelines order
  std::string jsonPath = (fs::path(dir) / "metrics.json").string();
  std::ofstream out(jsonPath);
  out << j.dump(2) << "\n";
  if (!out.good()) return fail(jsonPath + ": write failed");
  std::printf("%s\n", summaryLine(scene.source, names[0], names[1], *metrics,
                                  thresholdsGiven ? &verdict : nullptr).c_str());
  return thresholdsGiven && verdict.failed ? 1 : 0;
}

}  // namespace
}  // namespace mb

MB_COMMAND(compare, "compare",
           "SCENE [--pipelines matrix,motor] [--anim A] [--time T] [--anim2 B --time2 T2 --blend W] "
           "[--camera C] [--size WxH] [--instances N] [--fail F(0..1)] [--failpercent P(0..100)] [--hardfail H(0..1)] -o DIR",
           "render a scene with two pipelines; write both images, diff.png, diff_legend.png and "
           "metrics.json; exit 1 when a threshold given is exceeded (F, H: channel difference / 255)",
           mb::runCompare);
