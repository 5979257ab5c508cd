#include "harness/check/golden.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <utility>

#include "harness/render/thresholds.h"

namespace mb::check {
namespace {

using nlohmann::json;

// File names must survive any shell and file system: keep [A-Za-z0-9_-], map the rest to '_'.
std::string safe(const std::string& s) {
  std::string out;
  for (char c : s) {
    bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
              c == '_' || c == '-';
    out += ok ? c : '_';
  }
  return out.empty() ? "_" : out;
}

json numberOrNull(double v) { return std::isinf(v) ? json(nullptr) : json(v); }

json toJson(const Level& l) {
  return {{"warn", l.warn}, {"warnpercent", l.warnPercent}, {"fail", l.fail.fail},
          {"failpercent", l.fail.failPercent}, {"hardfail", numberOrNull(l.fail.hardFail)}};
}

// One level of a scene's thresholds; a channel difference of 1 or more (byte steps written as a
// fraction: it would pass any image) is an error naming `where` (harness/render/thresholds.h).
Level levelFrom(const json& j, const std::string& where) {
  Level l;
  l.warn = j.at("warn").get<double>();
  l.warnPercent = j.at("warnpercent").get<double>();
  l.fail.fail = j.at("fail").get<double>();
  l.fail.failPercent = j.at("failpercent").get<double>();
  const json& h = j.at("hardfail");
  l.fail.hardFail = h.is_null() ? std::numeric_limits<double>::infinity() : h.get<double>();
  for (const auto& [key, value] : {std::pair{"fail", l.fail.fail}, std::pair{"warn", l.warn}, std::pair{"hardfail", l.fail.hardFail}})
    if (!std::isinf(value))
      if (std::string e = channelDifferenceError("thresholds " + where + " " + key, value); !e.empty())
        throw std::invalid_argument(e);
  return l;
}

FrameSettings settingsFrom(const json& j) {
  FrameSettings s;
  s.anim.anim = j.at("anim").get<int>();
  s.anim.time = j.at("time").get<float>();
  s.anim.anim2 = j.at("anim2").get<int>();
  s.anim.time2 = j.at("time2").get<float>();
  s.anim.blend = j.at("blend").get<float>();
  s.camera = j.at("camera").get<int>();
  s.width = j.at("width").get<int>();
  s.height = j.at("height").get<int>();
  return s;
}

}  // namespace

std::vector<Pose> posesFor(const Scene& scene, int maxAnimations) {
  std::vector<Pose> poses = {{"rest", AnimState{}}};
  for (int a = 0; a < int(scene.animations.size()) && a < maxAnimations; ++a) {
    const Animation& anim = scene.animations[size_t(a)];
    for (double fraction : kPoseFractions) {
      float t = float(std::round(fraction * anim.duration * 1000.0) / 1000.0);
      char name[64];
      std::snprintf(name, sizeof name, "-t%.3f", double(t));
      AnimState state;
      state.anim = a;
      state.time = state.time2 = t;
      const std::string pose = safe(anim.name.empty() ? "anim" + std::to_string(a) : anim.name) + name;
      // An animation without duration (or one too short for milliseconds) poses once.
      if (std::none_of(poses.begin(), poses.end(), [&](const Pose& p) { return p.name == pose; }))
        poses.push_back({pose, state});
    }
  }
  return poses;
}

std::string fileSceneName(const std::string& relativePath) { return safe(relativePath); }

std::string fileName(const std::string& scene, const std::string& pose, const std::string& pipeline) {
  return safe(scene) + "." + pose + "." + safe(pipeline) + ".png";
}

SceneThresholds defaultThresholds(const std::string& scene) {
  SceneThresholds t;
  // Exact: one 8-bit step (1/255 = 0.0039) passes, anything more on any pixel fails; every
  // change at all is a warning.
  t.exact.fail.fail = 0.004;
  t.exact.fail.failPercent = 0.0;
  // Portable: shading may drift by a few steps over a small share of the image (rounding,
  // texture LOD); a real regression moves whole surfaces. The crowd has the most silhouette
  // and small-feature pixels, so it gets more room. No hard limit: a silhouette pixel that
  // another rasterizer covers differently may change completely.
  t.portable.fail.fail = 0.02;
  t.portable.fail.failPercent = scene == "crowd" ? 2.0 : 1.0;
  return t;
}

const Entry* Manifest::find(const std::string& file) const {
  for (const Entry& e : entries)
    if (e.file == file) return &e;
  return nullptr;
}

Result<Manifest> readManifest(const std::string& path) {
  std::ifstream in(path);
  if (!in) return Result<Manifest>::fail(path + ": cannot open (missing golden manifest; "
                                         "`motorbench check --update` creates it)");
  try {
    json j = json::parse(in);
    Manifest m;
    for (const auto& [scene, t] : j.at("thresholds").items())
      m.thresholds[scene] = {levelFrom(t.at("exact"), scene + " exact"), levelFrom(t.at("portable"), scene + " portable")};
    const json sources = j.value("sources", json::object());  // kept alive for the loop
    for (const auto& [scene, source] : sources.items())
      m.sources[scene] = {source.at("path").get<std::string>(), source.at("sha256").get<std::string>(),
                          source.value("resources", std::vector<std::string>{})};
    for (const json& e : j.at("images")) {
      Entry entry;
      entry.file = e.at("file").get<std::string>();
      entry.scene = e.at("scene").get<std::string>();
      entry.pipeline = e.at("pipeline").get<std::string>();
      entry.pose = e.at("pose").get<std::string>();
      entry.settings = settingsFrom(e.at("settings"));
      entry.glRenderer = e.at("gl").at("renderer").get<std::string>();
      entry.glVersion = e.at("gl").at("version").get<std::string>();
      entry.glBackend = e.at("gl").value("backend", "");
      entry.view = e.value("view", json::object());
      m.entries.push_back(std::move(entry));
    }
    return m;
  } catch (const std::exception& e) {
    return Result<Manifest>::fail(path + ": " + e.what());
  }
}

Status writeManifest(const std::string& path, const Manifest& m) {
  json j;
  j["format"] = 1;
  j["rule"] =
      "Per image: when GL_RENDERER and GL_VERSION equal the ones recorded for it, the scene's "
      "'exact' thresholds apply; otherwise its 'portable' thresholds apply and check warns. "
      "Thresholds use idiff semantics on channel values in [0,1]: a pixel fails when a channel "
      "differs by more than 'fail'; the image fails when more than 'failpercent' % of pixels "
      "fail or any difference exceeds 'hardfail' (null = none); 'warn'/'warnpercent' likewise "
      "only warn.";
  j["camera"] = "automatic framing (pipelines/scene/camera_rule.h) unless settings.camera >= 0";
  j["thresholds"] = json::object();
  for (const auto& [scene, t] : m.thresholds)
    j["thresholds"][scene] = {{"exact", toJson(t.exact)}, {"portable", toJson(t.portable)}};
  // Only golden folders of users' files have sources: the built-ins' golden.json stays as it was.
  if (!m.sources.empty()) {
    j["sourcesRule"] = "sha256: SHA-256 of the file's bytes, then for each external resource it names (buffers[] "
                       "and images[] uris, not data: URIs, in that order) a newline, the uri, a newline, its byte "
                       "count, a newline and its bytes ('missing' for one that cannot be read); a file without any is `sha256sum FILE`. A file "
                       "whose hash differs is reported as changed, not judged; `check --update` records it again.";
    for (const auto& [scene, s] : m.sources)
      j["sources"][scene] = {{"path", s.path}, {"sha256", s.sha256}, {"resources", s.resources}};
  }
  j["images"] = json::array();
  for (const Entry& e : m.entries)
    j["images"].push_back({{"file", e.file}, {"scene", e.scene}, {"pipeline", e.pipeline},
                           {"pose", e.pose}, {"settings", mb::toJson(e.settings)},
                           {"gl", {{"renderer", e.glRenderer}, {"version", e.glVersion},
                                   {"backend", e.glBackend}}},
                           {"view", e.view}});
  std::ofstream out(path);
  out << j.dump(2) << "\n";
  if (!out.good()) return Status::fail(path + ": write failed");
  return {};
}

bool rendererMatches(const Entry& e, const std::string& renderer, const std::string& version) {
  return e.glRenderer == renderer && e.glVersion == version;
}

}  // namespace mb::check
