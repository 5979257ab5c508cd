#include "harness/report/report_ops.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "harness/ops/ops_vertex.h"
#include "harness/ops/pipeline_ops.h"
#include "harness/process/progress.h"
#include "pipelines/pipeline.h"

namespace mb::report {
namespace {

using json = nlohmann::json;
const char* const kColumns[] = {"mul", "add", "div", "sqrt", "other"};

json ops5(const json& c) {
  json o;
  for (const char* k : kColumns) o[k] = c.is_object() ? c.value(k, 0.0) : 0.0;
  return o;
}

// The variant of `pipeline` labelled `label`, or nullptr.
const json* findVariant(const json& ops, const std::string& pipeline, const std::string& label) {
  if (!ops.contains("variants") || !ops["variants"].is_array()) return nullptr;
  for (const json& v : ops["variants"])
    if (v.value("pipeline", "") == pipeline && v.value("label", "") == label) return &v;
  return nullptr;
}

}  // namespace

json measureOpsPerVertex() {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  Clock::time_point shown = start;
  const opsv::VertexOps ops = opsv::measureVertexOps(opsv::SpirvDepth::Full, [&](size_t done, size_t total, const std::string& what) {
    const Clock::time_point now = Clock::now();
    if (done < total && now - shown < std::chrono::seconds(5)) return;  // a line every 5 s, and the last
    shown = now;
    const double elapsed = std::chrono::duration<double>(now - start).count();
    std::string line = "report: counting ops per vertex: " + std::to_string(done) + "/" + std::to_string(total) +
                       " kernels and shader variants (" + what + "), " + process::durationText(elapsed) + " elapsed";
    if (done < total) line += ", about " + process::durationText(elapsed / double(done) * double(total - done)) + " left";
    std::fprintf(stderr, "%s\n", line.c_str());
    std::fflush(stderr);
  });
  json full = opsv::toJson(ops);
  // A flat, stable view of the variants (ops_vertex's own JSON may grow other fields).
  json variants = json::array();
  for (const opsv::VariantRow& v : ops.variants) {
    json row = {{"pipeline", v.variant.pipeline}, {"label", v.variant.label},
                {"shader", v.variant.file}, {"kernels", v.variant.kernels},
                {"counted", {{"mul", v.counted.mul}, {"add", v.counted.add}, {"div", v.counted.div},
                             {"sqrt", v.counted.sqrt}, {"other", v.counted.other}}},
                {"spirv", nullptr}, {"difference", v.error.empty() ? v.why : v.error}};
    if (v.shader)
      row["spirv"] = {{"mul", v.shader->mul}, {"add", v.shader->add}, {"div", v.shader->div},
                      {"sqrt", v.shader->sqrt}, {"other", v.shader->other}, {"int", v.shader->intOps}};
    variants.push_back(row);
  }
  json kernels = json::array();
  for (const opsv::KernelRow& k : ops.kernels) {
    json row = {{"pipeline", k.kernel.pipeline}, {"kernel", k.kernel.kernel},
                {"function", k.kernel.function},
                {"counted", {{"mul", k.counted.mul}, {"add", k.counted.add}, {"div", k.counted.div},
                             {"sqrt", k.counted.sqrt}, {"other", k.counted.other},
                             {"other_calls", k.counted.otherCalls()}}},
                {"spirv", nullptr}, {"note", k.kernel.note}, {"difference", k.error.empty() ? k.why : k.error}};
    if (k.optimised)
      row["spirv"] = {{"mul", k.optimised->mul}, {"add", k.optimised->add}, {"div", k.optimised->div},
                      {"sqrt", k.optimised->sqrt}, {"other", k.optimised->other}};
    kernels.push_back(row);
  }
  return {{"kernels", kernels}, {"variants", variants}, {"toolsProblem", ops.toolsProblem},
          {"perPipeline", opsv::toJson(opsv::pipelineOps(ops))}, {"detail", full}};
}

json sceneOpsPerVertex(const json& ops, const json& mix, const json& pipelines) {
  if (!mix.is_object()) return nullptr;
  if (mix.value("curvedInstance", 0.0) > 0) {  // one variant draws every vertex of a curved scene
    json out = json::object();
    const std::string label = mix.value("curvedSpace", "") + " instance";
    for (const std::string& pipeline : allPipelineNames())
        if (const json* v = findVariant(ops, pipeline, label))
          out[pipeline] = {{"counted", v->at("counted").is_null() ? json() : ops5(v->at("counted"))},
                           {"spirv", v->at("spirv").is_null() ? json() : ops5(v->at("spirv"))}};
    return out;
  }
  const double skinned = mix.value("skinned", 0.0), rigidAll = mix.value("rigid", 0.0),
               scaled = mix.value("scaledFallback", 0.0), patch = mix.value("bezierPatch", 0.0),
               total = skinned + rigidAll + patch;
  if (total <= 0) return nullptr;
  json out = json::object();
  for (const std::string& pipeline : pipelineNames()) {  // those with shader variants
    const json* rigid = findVariant(ops, pipeline, "rigid");
    const json* skin = findVariant(ops, pipeline, "skinned");
    const json* fb = findVariant(ops, pipeline, "scaled fallback");
    const json* bezier = findVariant(ops, pipeline, "bezier patch");
    const json* linear = findVariant(ops, pipeline, "linear fallback");
    const json* skinLinear = findVariant(ops, pipeline, "skinned, linear fallback");
    if (!rigid || (skinned > 0 && !skin) || (patch > 0 && !bezier)) continue;
    // The exact fallback's vertices (the most in one frame drawn), within the scene's own counts.
    const json drawn = pipelines.is_object() && pipelines.contains(pipeline)
                           ? pipelines[pipeline].value("fallbacks", json::object()) : json::object();
    const double fbSkin = std::min(skinned, drawn.value("skinFallbackVertices", 0.0));
    const double fbRigid = std::min(rigidAll, std::max(0.0, drawn.value("fallbackVertices", 0.0) - fbSkin));
    json row;
    for (const char* way : {"counted", "spirv"}) {
      if ((*rigid)[way].is_null() || (skinned > 0 && (*skin)[way].is_null()) ||
          (patch > 0 && (*bezier)[way].is_null())) {
        row[way] = nullptr;
        continue;
      }
      auto usable = [&](const json* v) { return v && !(*v)[way].is_null(); };
      const double nLinear = usable(linear) ? fbRigid : 0.0, nSkinLinear = usable(skinLinear) ? fbSkin : 0.0;
      const double nFallback = usable(fb) ? std::min(scaled, rigidAll - nLinear) : 0.0;
      json mean;
      for (const char* c : kColumns) {
        auto cost = [&](const json* v) { return ops5((*v)[way])[c].get<double>(); };
        double sum = cost(rigid) * (rigidAll - nFallback - nLinear);
        if (nFallback > 0) sum += cost(fb) * nFallback;
        if (nLinear > 0) sum += cost(linear) * nLinear;
        if (skinned > 0) sum += cost(skin) * (skinned - nSkinLinear);
        if (nSkinLinear > 0) sum += cost(skinLinear) * nSkinLinear;
        if (patch > 0) sum += cost(bezier) * patch;
        mean[c] = sum / total;
      }
      row[way] = mean;
    }
    row["fallbackVertices"] = {{"rigid", fbRigid}, {"skinned", fbSkin}};
    out[pipeline] = row;
  }
  return out;
}

}  // namespace mb::report
