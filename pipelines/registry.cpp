// Every pipeline's registry entry, one line per pipeline; each entry is declared in its folder.
#include "pipelines/registry.h"

#include <algorithm>
#include <sstream>

#include "pipelines/matrix/affine_pipeline.h"
#include "pipelines/curved/curved_pipeline.h"
#include "pipelines/hybrid/hybrid_pipeline.h"
#include "pipelines/matrix/matrix_pipeline.h"
#include "pipelines/motor/motor_pipeline.h"

namespace mb {
namespace {

std::vector<PipelineEntry>& entries() {
  static std::vector<PipelineEntry> list = {
      matrixEntry(),
      motorEntry(),
      affineEntry(),
      qtangentEntry(),
      motorQEntry(),
      hybridEntry(),
      matrixCEntry(),
      motorCEntry(),
      motorCFEntry(),
      curvedEntry(Space::Spherical, false),
      curvedEntry(Space::Spherical, true),
      curvedEntry(Space::Hyperbolic, false),
      curvedEntry(Space::Hyperbolic, true),
  };
  return list;
}

}  // namespace

const std::vector<PipelineEntry>& registeredPipelines() { return entries(); }

const PipelineEntry* findPipeline(const std::string& name) {
  for (const PipelineEntry& e : entries())
    if (e.name == name) return &e;
  return nullptr;
}

ScopedRegistration::ScopedRegistration(PipelineEntry entry) : name_(entry.name) {
  if (findPipeline(name_)) return;
  entries().push_back(std::move(entry));
  added_ = true;
}

ScopedRegistration::~ScopedRegistration() {
  if (added_) std::erase_if(entries(), [&](const PipelineEntry& e) { return e.name == name_; });
}

std::unique_ptr<Pipeline> createPipeline(const std::string& name) {
  const PipelineEntry* e = findPipeline(name);
  return e ? e->make() : nullptr;
}

SkinMethod skinMethodOf(const std::string& name) {
  const PipelineEntry* e = findPipeline(name);
  return e ? e->skin : SkinMethod::None;
}

std::vector<std::string> pipelineNames(Space space) {
  std::vector<std::string> names;
  for (const PipelineEntry& e : entries())
    if (e.space == space) names.push_back(e.name);
  return names;
}

std::vector<std::pair<std::string, std::string>> defines(const std::string& names) {
  std::vector<std::pair<std::string, std::string>> out;
  std::istringstream in(names);
  for (std::string word; in >> word;) {
    const size_t eq = word.find('=');
    out.push_back({word.substr(0, eq), eq == std::string::npos ? "" : word.substr(eq + 1)});
  }
  return out;
}

std::vector<ShaderVariant> programs(const std::string& stage, const std::string& clip,
                                    std::vector<ShaderVariant> rows) {
  for (ShaderVariant& v : rows) {
    if (v.stage.empty()) v.stage = stage;
    v.kernels.push_back(clip);
  }
  return rows;
}

std::vector<std::string> allPipelineNames() {
  std::vector<std::string> names;
  for (const PipelineEntry& e : entries()) names.push_back(e.name);
  return names;
}

}  // namespace mb
