#include "harness/claims/claims_uploads.h"

#include "harness/render/render_frame.h"
#include "pipelines/scene/loader.h"

namespace mb::claims {

using json = nlohmann::json;

Uploads::Uploads(const json& reportScenes, std::string reportSource)
    : fromReport_(true), scenes_(reportScenes.is_array() ? reportScenes : json::array()),
      reportSource_(std::move(reportSource)) {}

void Uploads::addReport(const json& reportScenes, const std::string& reportSource) {
  if (!reportScenes.is_array()) return;
  for (const json& s : reportScenes) scenes_.push_back(s);
  reportSource_ += " + " + reportSource;
}

std::string Uploads::source() const {
  return fromReport_ ? reportSource_ + " (the uploads its renders recorded: scenes[].pipelines[].stats)"
                     : std::string("renders here (32x32, the uploads do not depend on the size)");
}

std::vector<std::string> Uploads::reportSceneIds() const {
  std::vector<std::string> ids;
  for (const json& s : scenes_) ids.push_back(s.value("id", ""));
  return ids;
}

const json* Uploads::entry(const std::string& scene, const std::string& pipeline, std::string& why) const {
  for (const json& s : scenes_) {
    if (s.value("id", "") != scene) continue;
    const json ps = s.value("pipelines", json());
    if (!ps.is_object() || !ps.contains(pipeline)) {
      why = reportSource_ + ": scene " + scene + " has no pipeline " + pipeline;
      return nullptr;
    }
    return &s["pipelines"][pipeline];
  }
  why = reportSource_ + " has no scene " + scene;
  return nullptr;
}

json Uploads::memoryOf(const std::string& scene, const std::string& pipeline) const {
  std::string why;
  const json* e = fromReport_ ? entry(scene, pipeline, why) : nullptr;
  return e && (*e).value("memory", json()).is_object() ? (*e)["memory"] : json();
}

namespace {

// The upload counters the claims read, from toJson(PipelineStats) (render_frame.h); a counter
// the report did not record stays 0.
PipelineStats uploadsFromJson(const json& j) {
  PipelineStats s;
  auto u = [&](const char* key, uint64_t& v) { if (j.value(key, json()).is_number()) v = j[key].get<uint64_t>(); };
  auto d = [&](const char* key, double& v) { if (j.value(key, json()).is_number()) v = j[key].get<double>(); };
  u("vertexBytes", s.vertexBytes), u("vertices", s.vertices), u("instanceBytes", s.instanceBytes);
  u("instances", s.instances), u("drawnVertices", s.drawnVertices);
  u("normalMappedVertexBytes", s.normalMappedVertexBytes), u("normalMappedVertices", s.normalMappedVertices);
  d("floatsPerVertex", s.floatsPerVertex), d("floatsPerTransform", s.floatsPerTransform);
  d("floatsPerTransformWithScale", s.floatsPerTransformWithScale), d("floatsPerJoint", s.floatsPerJoint);
  return s;
}

}  // namespace

Result<PipelineStats> Uploads::of(const std::string& scene, const std::string& pipeline) const {
  using R = Result<PipelineStats>;
  if (fromReport_) {
    std::string why;
    const json* e = entry(scene, pipeline, why);
    if (!e) return R::fail(why);
    if ((*e).value("error", json()).is_string()) return R::fail(reportSource_ + ": " + scene + " [" + pipeline + "]: " + (*e)["error"].get<std::string>());
    if (!(*e).value("stats", json()).is_object()) return R::fail(reportSource_ + ": " + scene + " [" + pipeline + "] has no stats");
    return uploadsFromJson((*e)["stats"]);
  }
  auto s = loadScene(scene);
  if (!s) return R::fail(s.error());
  FrameSettings settings;
  settings.width = settings.height = 32;  // the uploads do not depend on the image size
  if (!s->animations.empty()) settings.anim.anim = 0;
  auto f = renderFrame(*s, pipeline, settings);
  if (!f) return R::fail(f.error());
  return f->stats;
}

}  // namespace mb::claims
