#include "pipelines/gl/gltf_pipeline.h"

namespace mb::gl {

Status GltfPipeline::beginPrepare(const Scene& scene, size_t bytesPerJoint) {
  if (Status curved = refuseCurvedScene(scene, name()); !curved) return curved;
  scene_ = &scene;
  stats_ = PipelineStats{};
  if (Status fits = checkPaletteSize(scene, bytesPerJoint); !fits) return fits;
  if (Status tex = textures_.upload(scene, stats_.textureBytes); !tex) return tex;
  return patches_.upload(scene, stats_);  // nothing for a scene without patches
}

Status GltfPipeline::endPrepare(const Scene& scene) {
  draws_ = buildDrawList(scene);
  update(AnimState{});
  GLenum err = glGetError();
  if (err != GL_NO_ERROR) return Status::fail(scene.source + ": " + name() + " prepare: " + errorName(err));
  return {};
}

CachedProgram* GltfPipeline::link(Status& status, const std::string& vs, const Defines& defines) {
  std::string key = vs;
  for (const auto& [name, value] : defines) key += '\n' + name + '=' + value;
  if (auto found = cache_.find(key); found != cache_.end()) return found->second.get();
  auto program = Program::fromFiles(vs, "forward.fs", defines);
  if (!program) {
    status = Status::fail(program.error());
    return nullptr;
  }
  // Stored only once linked: a key that failed is linked (and fails) again when asked for.
  return (cache_[key] = std::make_unique<CachedProgram>(CachedProgram{program.take()})).get();
}

Status GltfPipeline::linkGrid(ProgramGrid& grid, const std::string& vs, const std::function<int(int)>& variants,
                              const std::function<Defines(int, int, bool)>& defines) {
  Status linked;
  const int kinds = hasInstances(*scene_) ? kDrawKinds : kInstanced, morphs = maxMorphTargets(*scene_) ? 2 : 1;
  for (int kind = 0; kind < kinds; ++kind)
    for (int variant = 0; variant < variants(kind); ++variant)
      for (int morphing = 0; morphing < morphs; ++morphing) {
        Defines d = defines(kind, variant, morphing);
        if (morphing)
          for (auto& m : morphDefines(*scene_)) d.push_back(m);
        if (!(grid.at[kind][variant][morphing] = link(linked, vs, d))) return linked;
      }
  return linked;
}

void GltfPipeline::releaseShared() {
  patches_.release();
  palettes_.release();
  textures_.release();
  instances_.release();
  cache_.clear();
  programs_ = {};
  draws_.clear();
  scene_ = nullptr;
}

}  // namespace mb::gl
