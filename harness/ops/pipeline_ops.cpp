#include "harness/ops/pipeline_ops.h"

#include <algorithm>
#include <cstdio>

#include "harness/ops/ops_text.h"
#include "pipelines/pipeline.h"

namespace mb::opsv {
namespace {

const VariantRow* variantOf(const VertexOps& ops, const std::string& pipeline, const std::string& label) {
  for (const VariantRow& v : ops.variants)
    if (v.variant.pipeline == pipeline && v.variant.label == label) return &v;
  return nullptr;
}

// A curved pipeline draws one variant: its instance vertex.
const VariantRow* rigidVariantOf(const VertexOps& ops, const std::string& pipeline) {
  if (const VariantRow* v = variantOf(ops, pipeline, "rigid")) return v;
  for (const VariantRow& v : ops.variants)
    if (v.variant.pipeline == pipeline && v.variant.label.find(" instance") != std::string::npos) return &v;
  return nullptr;
}

// The variant's first kernel (its transform) or the whole variant.
OpsFigure figureOf(const VertexOps& ops, const VariantRow* v, bool transformOnly) {
  OpsFigure f;
  if (!v || !v->kernelsResolved || v->variant.kernels.empty()) return f;
  f.present = true;
  if (!transformOnly) {
    f.counted = v->counted, f.spirv = v->probes;
    return f;
  }
  if (const KernelRow* k = findKernel(ops.kernels, v->variant.pipeline, v->variant.kernels.front()))
    f.counted = k->counted, f.spirv = k->optimised;
  return f;
}

std::string cell(const OpsFigure& f, bool spirvSide) {
  if (!f.present) return "-";
  if (!spirvSide) return std::to_string(total(f.counted));
  return f.spirv ? std::to_string(total(*f.spirv)) : "-";
}

}  // namespace

uint64_t total(const OpCounts& c) { return c.mul + c.add + c.div + c.sqrt + c.other; }
uint64_t total(const spirv::Counts& c) { return c.mul + c.add + c.div + c.sqrt + c.other; }

std::vector<PipelineOps> pipelineOps(const VertexOps& ops) {
  std::vector<PipelineOps> rows;
  const std::vector<std::string> euclidean = pipelineNames(Space::Euclidean);
  for (const std::string& p : allPipelineNames()) {
    PipelineOps row{p, {}, {}, {}, {}, ""};
    const VariantRow* rigid = rigidVariantOf(ops, p);
    row.rigid = figureOf(ops, rigid, true);
    row.toClip = figureOf(ops, rigid, false);
    row.skinned = figureOf(ops, variantOf(ops, p, "skinned"), true);
    row.patch = figureOf(ops, variantOf(ops, p, "bezier patch"), false);
    const bool skins = std::find(euclidean.begin(), euclidean.end(), p) != euclidean.end();
    std::string missing;
    auto need = [&](const OpsFigure& f, const char* what) {
      if (!f.present || total(f.counted) == 0) missing += (missing.empty() ? "" : ", ") + std::string(what);
    };
    need(row.rigid, "rigid");
    need(row.toClip, "to clip");
    if (skins) need(row.skinned, "skinned");
    if (!missing.empty())
      row.problem = "no counted ops (" + missing + "): its registry entry declares no such variant, or "
                    "its kernels are not counted";
    rows.push_back(row);
  }
  return rows;
}

std::string readmeOpsCell(const PipelineOps& row) {
  auto three = [&](bool spirvSide) {
    return cell(row.rigid, spirvSide) + " / " + cell(row.skinned, spirvSide) + " / " + cell(row.toClip, spirvSide);
  };
  return three(false) + " (" + three(true) + ")";
}

std::string formatPipelineOps(const std::vector<PipelineOps>& rows) {
  std::string out =
      "Ops per vertex per pipeline (counted mul/add/div/sqrt/other; total; SPIR-V total of the kernels' probes):\n"
      "  rigid = object to world with frame, skinned = the same with 4 joints, to clip = rigid + world to clip\n\n";
  char buf[512];
  std::snprintf(buf, sizeof buf, "%-10s %-22s %-22s %-22s %-22s\n", "pipeline", "rigid", "skinned", "to clip",
                "bezier patch");
  out += buf;
  auto fig = [](const OpsFigure& f) {
    if (!f.present) return std::string("-");
    return text(f.counted) + " =" + std::to_string(total(f.counted)) + " (" +
           (f.spirv ? std::to_string(total(*f.spirv)) : "-") + ")";
  };
  for (const PipelineOps& r : rows) {
    std::snprintf(buf, sizeof buf, "%-10s %-22s %-22s %-22s %-22s %s\n", r.pipeline.c_str(), fig(r.rigid).c_str(),
                  fig(r.skinned).c_str(), fig(r.toClip).c_str(), fig(r.patch).c_str(), r.problem.c_str());
    out += buf;
  }
  return out;
}

nlohmann::json toJson(const std::vector<PipelineOps>& rows) {
  auto fig = [](const OpsFigure& f) -> nlohmann::json {
    if (!f.present) return nullptr;
    nlohmann::json j = {{"counted", {{"mul", f.counted.mul}, {"add", f.counted.add}, {"div", f.counted.div},
                                     {"sqrt", f.counted.sqrt}, {"other", f.counted.other},
                                     {"total", total(f.counted)}}},
                        {"spirv", nullptr}};
    if (f.spirv)
      j["spirv"] = {{"mul", f.spirv->mul}, {"add", f.spirv->add}, {"div", f.spirv->div}, {"sqrt", f.spirv->sqrt},
                    {"other", f.spirv->other}, {"total", total(*f.spirv)}};
    return j;
  };
  nlohmann::json out = nlohmann::json::array();
  for (const PipelineOps& r : rows)
    out.push_back({{"pipeline", r.pipeline}, {"rigid", fig(r.rigid)}, {"skinned", fig(r.skinned)},
                   {"toClip", fig(r.toClip)}, {"patch", fig(r.patch)}, {"readmeCell", readmeOpsCell(r)},
                   {"problem", r.problem}});
  return out;
}

}  // namespace mb::opsv
