// The paper's statistics over glTF files: "less than 0.5 % of the almost 400 random glTF files
// tested had any animation on the scale", and non-uniform scale found only on leaf nodes.
// Measured here on the built-in scenes plus a corpus folder, with the sample size stated:
// a sample of N files cannot show a fraction below 1/N.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "harness/claims/claims_sources.h"
#include "harness/report/report_inputs.h"
#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"

namespace mb::claims {
namespace {

namespace fs = std::filesystem;

// The .gltf/.glb files below `dir` (none when it is not a folder), as report finds them.
std::vector<std::string> corpusFiles(const std::string& dir) {
  std::vector<std::string> out;
  std::error_code ec;
  if (dir.empty() || !fs::is_directory(dir, ec)) return out;
  for (const report::Input& in : report::expandInputs({dir})) out.push_back(in.spec);
  return out;
}

// A scale channel that changes the scale: some key differs from the first (a channel of
// constant keys, as some exporters write for every node, animates nothing).
bool scaleChanges(const Scene& s) {
  for (const Animation& a : s.animations)
    for (const Channel& c : a.channels) {
      if (c.path != AnimPath::Scale || c.values.size() < 6) continue;
      const size_t stride = c.interpolation == Interpolation::CubicSpline ? 9 : 3;
      const size_t first = c.interpolation == Interpolation::CubicSpline ? 3 : 0;
      for (size_t k = first + stride; k + 2 < c.values.size(); k += stride)
        for (size_t i = 0; i < 3; ++i)
          if (std::fabs(c.values[k + i] - c.values[first + i]) > 1e-6f) return true;
    }
  return false;
}

std::string pct(int n, int of) {
  char b[64];
  std::snprintf(b, sizeof b, "%d of %d files (%.1f %%)", n, of, of ? 100.0 * n / of : 0.0);
  return b;
}

}  // namespace

std::vector<Claim> corpusClaims(const std::string& corpusDir) {
  std::vector<std::string> files = builtinSceneNames();
  const std::vector<std::string> corpus = corpusFiles(corpusDir);
  files.insert(files.end(), corpus.begin(), corpus.end());
  std::vector<FileStats> stats;
  std::vector<std::string> animatedNames, changingNames, failed;
  int changing = 0;
  for (const std::string& f : files) {
    auto scene = loadScene(f);
    if (!scene) {
      failed.push_back(f + ": " + scene.error());
      continue;
    }
    stats.push_back(computeFileStats(*scene));
    const std::string name = fs::path(f).filename().string();
    if (stats.back().scale.animatedScale) animatedNames.push_back(name);
    if (scaleChanges(*scene)) ++changing, changingNames.push_back(name);
  }
  const nlohmann::json agg = aggregateJson(stats);
  const int n = agg["loaded"], animated = agg["filesWithAnimatedScale"];
  const int nonUniform = agg["filesWithNonUniformScale"], leaves = agg["filesWithNonUniformOnlyOnLeaves"];
  const std::string sample = std::to_string(builtinSceneNames().size()) + " built-in scenes (generated to exercise "
                             "skinning, hierarchy and scale, so not a random sample) + " +
                             std::to_string(corpus.size()) + " files of " +
                             (corpus.empty() ? std::string("no corpus (") + (corpusDir.empty() ? "none given" : corpusDir + " not found") + ")"
                                             : corpusDir) +
                             (failed.empty() ? "" : "; " + std::to_string(failed.size()) + " failed to load");
  auto join = [](const std::vector<std::string>& v) {
    std::string s;
    for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
    return s.empty() ? std::string("none") : s;
  };
  Claim a{"animated_scale_corpus", "Scene statistics", "less than 0.5 % of ~400 glTF files animate scale"};
  a.paper = "< 0.5 % of ~400 files";
  a.paperValue = {{"fraction", 0.005}, {"files", 400}};
  a.measured = pct(animated, n) + " have a scale channel (" + join(animatedNames) + "); " + pct(changing, n) +
               " have one whose keys change the scale (" + join(changingNames) + ")";
  a.measuredValue = {{"files", n}, {"withScaleChannel", animated}, {"withChangingScale", changing},
                     {"fraction", n ? double(animated) / n : 0.0}};
  a.method = "motorbench inspect's scale analysis (a scale channel in any animation) over " + sample +
             "; additionally, channels whose keys all equal the first are not counted as changing";
  a.verdict = Verdict::NotMeasurable;
  char smallest[64];
  std::snprintf(smallest, sizeof smallest, "%.1f %%", n ? 100.0 / n : 100.0);
  a.verdictText = "not measurable here: a sample of " + std::to_string(n) + " files cannot resolve 0.5 % (its "
                  "smallest non-zero fraction is " + smallest + "), and the built-in scenes animate scale on purpose";
  Claim l{"nonuniform_scale_leaves", "Scene statistics", "non-uniform scale is found only on leaf nodes"};
  l.paper = "all files with non-uniform scale: only on leaves";
  l.paperValue = {{"fractionOnlyOnLeaves", 1.0}};
  l.measured = std::to_string(leaves) + " of " + std::to_string(nonUniform) + " files with non-uniform scale have it only on leaves";
  l.measuredValue = {{"filesWithNonUniformScale", nonUniform}, {"onlyOnLeaves", leaves}, {"files", n}};
  l.method = "motorbench inspect's scale analysis (rest pose and every scale key) over " + sample;
  if (nonUniform == 0) {
    l.verdict = Verdict::NotMeasurable;
    l.verdictText = "not measurable here: no file of the sample has non-uniform scale";
  } else {
    l.verdict = leaves == nonUniform ? Verdict::Reproduced : Verdict::Differs;
    l.verdictText = leaves == nonUniform ? "reproduced (on a sample of " + std::to_string(n) + " files)"
                                         : "differs: " + std::to_string(nonUniform - leaves) + " of " +
                                               std::to_string(nonUniform) + " files have non-uniform scale on inner nodes";
  }
  return {a, l};
}

}  // namespace mb::claims
