// motorbench compare SCENE [--pipelines A,B] [frame options] [--fail F --failpercent P
//   --hardfail H] -o DIR: renders both, writes DIR/A.png, DIR/B.png, DIR/diff.png and
// DIR/metrics.json, prints one summary line; exit 1 when the idiff thresholds are exceeded.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "harness/options/args.h"
#include "harness/cli/command.h"
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
  if (v) s += v->failed ? " -> FAIL (" + v->reason + ")" : " -> PASS";
  return s;
}

int runCompare(const std::vector<std::string>& argv) {
  auto fail = [](const std::string& message) { return commandError("compare", message); };
  Args args(argv);
  auto cmd = parseSceneCommand(args, {"pipelines", "fail", "failpercent", "hardfail"}, "DIR");
  if (!cmd) return fail(cmd.error());
  const std::string& dir = cmd->output;
  const Scene& scene = cmd->scene;
  const FrameSettings& settings = cmd->settings;
  // Default: the pair of the scene's space (matrix,motor; s3_matrix,s3_motor; h3_...).
  const std::vector<std::string> pair = pipelineNames(scene.curved.space);
  std::vector<std::string> names = args.has("pipelines") ? splitList(args.get("pipelines", "")) : pair;
  if (names.size() != 2) return fail("--pipelines needs exactly two names, e.g. matrix,motor");
  bool thresholdsGiven = args.has("fail") || args.has("failpercent") || args.has("hardfail");
  Thresholds t;
  for (auto [key, value] : {std::pair{"fail", &t.fail}, {"failpercent", &t.failPercent},
                            {"hardfail", &t.hardFail}}) {
    auto v = numberOption(args, key, *value);
    if (!v) return fail(v.error());
    *value = *v;
  }

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

  nlohmann::json j = {
      {"scene", scene.source},
      {"pipelines", names},
      {"images", {names[0] + ".png", names[1] + ".png"}},
      {"diff", "diff.png"},
      {"settings", toJson(settings)},
      {"view", toJson(frames[0].view)},
      {"gl", {{"renderer", frames[0].glRenderer}, {"version", frames[0].glVersion},
              {"backend", frames[0].glBackend}}},
      {"metrics", toJson(*metrics)},
      {"thresholds", {{"applied", thresholdsGiven}, {"fail", t.fail},
                      {"failpercent", t.failPercent},
                      {"hardfail", std::isinf(t.hardFail) ? nlohmann::json(nullptr)
                                                          : nlohmann::json(t.hardFail)}}},
      {"verdict", {{"failed", thresholdsGiven && verdict.failed},
                   {"failPercent", verdict.failPercent}, {"reason", verdict.reason}}},
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
           "SCENE [--pipelines matrix,motor] [--anim A --time T ...] [--size WxH] "
           "[--fail F --failpercent P --hardfail H] -o DIR",
           "render a scene with two pipelines; write both images, diff.png and metrics.json",
           mb::runCompare);
