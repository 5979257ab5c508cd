// Golden images for `motorbench check`: which frames are kept (the plan), the manifest
// golden.json that records how each one was made, and the threshold rule.
//
// Threshold rule (why two levels): llvmpipe is bit-exact run to run, so on the renderer that
// made a golden the check can be tight ("exact": a pixel may move by at most one 8-bit step).
// Another Mesa/LLVM version or GPU rounds shading differently and may sample texture LODs a
// little differently, so when the running GL_RENDERER or GL_VERSION differs from the one
// recorded for the image the check uses the scene's "portable" thresholds and says so with a
// warning. Every threshold is per scene and lives in golden.json; `--update` keeps them.
#pragma once
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "pipelines/scene/scene.h"

namespace mb::check {

constexpr int kWidth = 160, kHeight = 120;  // small: the committed PNGs stay well under 2 MB
constexpr const char* kManifest = "golden.json";

// One animation state kept as a golden: "rest" (rest pose; skinned meshes in bind pose) or
// "<animation>-t<time>".
struct Pose {
  std::string name;
  AnimState anim;
};

// The plan: rest pose, plus each animation (the first kMaxAnimations) at 35 % and 70 % of its
// duration, times rounded to milliseconds so the manifest holds them exactly (a pose whose name
// repeats, as both of an animation without duration, is kept once). Every animation,
// because built-in scenes add one per case they exist to show (e.g. the tube's candy wrapper).
// A user's file (check FILE|DIR) keeps its first animation only: one file, rest and two poses.
constexpr int kMaxAnimations = 4;
constexpr int kMaxFileAnimations = 1;
constexpr double kPoseFractions[2] = {0.35, 0.7};
std::vector<Pose> posesFor(const Scene& scene, int maxAnimations = kMaxAnimations);

// The scene name of a user's file in golden.json and in its image names: its path relative to
// the folder argument (a file argument: its name) with every character but [A-Za-z0-9_-] as '_'
// ("props/Fox.glb" -> "props_Fox_glb").
std::string fileSceneName(const std::string& relativePath);

// "<scene>.<pose>.<pipeline>.png"
std::string fileName(const std::string& scene, const std::string& pose, const std::string& pipeline);

// idiff semantics: a pixel warns/fails when some channel differs by more than warn/fail; the
// image when more than warnPercent/failPercent % of pixels do, or (fail only) any channel
// differs by more than hardFail.
struct Level {
  double warn = 1e-6, warnPercent = 0;
  Thresholds fail;
};
struct SceneThresholds {
  Level exact, portable;
};
SceneThresholds defaultThresholds(const std::string& scene);

struct Entry {
  std::string file, scene, pipeline, pose;
  FrameSettings settings;
  std::string glRenderer, glVersion, glBackend;
  nlohmann::json view;  // where the camera was (informational)
};

// What the goldens of a user's file were made from (content_hash.h): a file whose hash differs
// now is named as changed, not judged against them.
struct Source {
  std::string path;                    // relative to the folder argument, as the user sees it
  std::string sha256;                  // contentHash() when the goldens were recorded
  std::vector<std::string> resources;  // the external uris in the hash
};

struct Manifest {
  std::map<std::string, SceneThresholds> thresholds;  // by scene
  std::map<std::string, Source> sources;              // by scene; files only (built-ins have none)
  std::vector<Entry> entries;
  const Entry* find(const std::string& file) const;
};

// Errors name the file and the reason (missing, bad JSON, missing field).
Result<Manifest> readManifest(const std::string& path);
Status writeManifest(const std::string& path, const Manifest& manifest);

// True when (renderer, version) are the ones recorded for `entry`: the rule picks "exact".
bool rendererMatches(const Entry& entry, const std::string& renderer, const std::string& version);

}  // namespace mb::check
