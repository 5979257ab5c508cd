// The matrix family's pipelines (matrix, affine, qtangent, matrix_c, and hybrid in
// pipelines/hybrid): one prepare, update and render over the shared draw path, the pipeline
// (`Self`, CRTP so that no virtual call is made per draw or per instance) supplying what is its
// own:
//   kVertexShader, kPatchShader, kJointBlock, kBytesPerJoint, kInstanceLayout, frames(),
//   defines(kind, frame)                                   its programs
//   convert(scene) (timed as conversionMs), preparePose(scene)   its vertices and pose set-up
//   pose(state, clock), posed(clock)                       its CPU update
//   palettes(), uploadPalette(i) -> joints                 its joint palettes
//   instanceWorld(node), writeInstance(model, out) -> key  its per-instance data
//   instancedUniforms(program, d), drawUniforms(program, d, palette, patch, morph, counters)
//                                                          its per-draw uniforms (-> mirrored)
// Every draw's program is picked from the table by draw kind (rigid, skinned, instanced), frame
// variant (GpuPrimitive::variant 1: MB_NO_TANGENT) and whether the draw morphs (MB_MORPH).
#pragma once
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "pipelines/gl/frame_vertices.h"
#include "pipelines/gl/gltf_pipeline.h"
#include "pipelines/gl/upload.h"
#include "pipelines/scene/transform.h"

namespace mb::gl {

// How a draw reaches world space; the rows of a pipeline's program table.
enum DrawKind { kRigid = 0, kSkinned = 1, kInstanced = 2, kDrawKinds = 3 };
using ProgramTable = CachedProgram* [kDrawKinds][2];  // [kind][frame variant]

// What every draw of one frame shares: the view, its view-projection matrix and the transform
// uploads counted for PipelineStats.
struct MatrixFrame : TransformCounters {
  const View& view;
  glm::mat4 viewProjection;
};

template <class Self>
class MatrixFamily : public GltfPipeline {
public:
  Status prepare(const Scene& scene) override {
    release();
    if (Status begun = beginPrepare(scene, Self::kBytesPerJoint); !begun) return begun;
    Status linked = linkTable(scene);
    if (linked && hasPatches(scene)) patch_ = link(linked, Self::kPatchShader, {});
    if (!linked) return linked;
    instanceMatrices_.assign(scene.nodes.size(), {});
    for (size_t n = 0; n < scene.nodes.size(); ++n)
      for (const TRS& t : scene.nodes[n].instances) instanceMatrices_[n].push_back(trsMatrix(t));
    auto t0 = Clock::now();
    if (Status converted = self().convert(scene); !converted) return converted;
    morph_.upload(scene, packFrameDeltas, stats_);
    stats_.conversionMs = msSince(t0);
    self().preparePose(scene);
    return endPrepare(scene);
  }

  void update(const AnimState& state) override {
    if (!scene_) return;
    auto t0 = Clock::now();
    PhaseClock clock(timePhases_ ? &stats_.updatePhases : nullptr);
    self().pose(state, clock);
    morph_.update(*scene_, state);
    self().posed(clock);
    stats_.updateMs = msSince(t0);
  }

  void render(const View& view) override {
    if (!scene_) return;
    beginFrame(self().palettes().size(), [this](size_t i) { return self().uploadPalette(i); });
    streamInstances();
    const glm::mat4 viewMatrix =
        glm::inverse(glm::translate(glm::mat4(1.0f), view.eye) * glm::mat4_cast(view.orientation));
    MatrixFrame frame{{}, view, projectionMatrix(view) * viewMatrix};
    drawList(*this, frame, geometry_, morph_, self().palettes());
  }

protected:
  ~MatrixFamily() override { release(); }
  // The defaults of the optional hooks.
  void preparePose(const Scene&) {}
  void posed(PhaseClock&) {}
  void instancedUniforms(const Program&, const DrawItem&) {}

  SceneGeometry geometry_;
  MorphBuffers morph_;

private:
  friend class GltfPipeline;  // drawList() calls the draw hooks below
  Self& self() { return static_cast<Self&>(*this); }

  // An instanced node: its program, uniforms, morph deltas and material once, then one instanced
  // draw per group (key 1: mirrored).
  void drawInstanceGroups(const MatrixFrame& f, const Draw& m, const std::vector<InstanceGroup>& groups) {
    const Program& program = useProgram(f, tableProgram(m, kInstanced));
    self().instancedUniforms(program, m.d);
    if (m.morph) morph_.bind(program, m.d, stats_.uniformBytesPerFrame), ++stats_.morphDraws;
    bindMaterial(program, m.prim);
    for (const InstanceGroup& group : groups) drawGroup(m.g, group, Self::kInstanceLayout, group.key == 1);
  }

  // A draw by its node's transform or its skin's palette, or a Bezier patch (kPatchShader).
  void drawNode(MatrixFrame& f, const Draw& m) {
    const GLuint palette = m.palette < 0 ? 0 : palettes_[size_t(m.palette)];
    const Program& program = useProgram(f, m.patch ? patch_ : tableProgram(m, palette ? kSkinned : kRigid));
    if (m.morph) morph_.bind(program, m.d, stats_.uniformBytesPerFrame), ++stats_.morphDraws;
    const bool mirrored = self().drawUniforms(program, m.d, palette, m.patch, m.morph, f);
    bindMaterial(program, m.prim);
    setWinding(mirrored);
    drawCounted(m);
  }

  // The program of `kind` for the draw's frame variant, from morphing_ when the draw morphs.
  CachedProgram* tableProgram(const Draw& m, DrawKind kind) const {
    return (m.morph ? morphing_ : programs_)[kind][m.g.variant == 1 ? 1 : 0];
  }

  // `p` made current, the frame's view-projection and view uniforms set (see use()).
  const Program& useProgram(const MatrixFrame& f, CachedProgram* p) {
    return use(*p, [&](const Program& program) {
      uniformMatrix4(program.uniform("u_ViewProjectionMatrix"), 1, glm::value_ptr(f.viewProjection),
                     stats_.uniformBytesPerFrame);
      setFrameUniforms(program, f.view, stats_.uniformBytesPerFrame);
    });
  }

  // Links kVertexShader for each draw kind (instanced only for scenes with instances) and each of
  // its frames() frame variants (0, 1: MB_NO_TANGENT where the pipeline has it) with
  // defines(kind, frame), into programs_; for scenes with morph targets the same with the morph
  // defines into morphing_. Skinned programs read kJointBlock at binding 0.
  Status linkTable(const Scene& scene) {
    Status linked;
    for (int kind = 0; kind < (hasInstances(scene) ? 3 : 2); ++kind)
      for (int frame = 0; frame < self().frames(); ++frame) {
        Defines defines = self().defines(kind, frame);
        std::vector<StorageBlock> blocks;
        if (kind == kSkinned) blocks.push_back({Self::kJointBlock, 0});
        if (!(programs_[kind][frame] = link(linked, Self::kVertexShader, defines, blocks))) return linked;
        if (!maxMorphTargets(scene)) continue;
        for (const auto& d : morphDefines(scene)) defines.push_back(d);
        blocks.push_back({"MorphDeltas", kMorphBinding});
        if (!(morphing_[kind][frame] = link(linked, Self::kVertexShader, defines, blocks))) return linked;
      }
    return linked;
  }

  // Per instance: model = node world * instance, written by the pipeline, which returns its
  // key (1: mirrored, the winding flips).
  void streamInstances() {
    instances_.begin(scene_->nodes.size());
    for (size_t n = 0; n < instanceMatrices_.size(); ++n) {
      const std::vector<glm::mat4>& local = instanceMatrices_[n];
      if (local.empty()) continue;
      const glm::mat4 world = self().instanceWorld(n);
      instances_.addNode(int(n), local.size(), [&](size_t i, std::vector<float>& out) {
        return self().writeInstance(world * local[i], out);
      });
    }
    instances_.upload(stats_);
  }

  void release() {
    geometry_.release();
    morph_.release();
    for (auto* table : {&programs_, &morphing_})
      for (auto& row : *table)
        for (auto& p : row) p = nullptr;
    patch_ = nullptr;
    releaseShared();
  }

  ProgramTable programs_ = {};  // [rigid, skinned, instanced][frame variant]
  ProgramTable morphing_ = {};  // the same with MB_MORPH, for scenes with morph targets
  CachedProgram* patch_ = nullptr;  // kPatchShader, for scenes with Bezier patches
  std::vector<std::vector<glm::mat4>> instanceMatrices_;  // per node: trsMatrix(instance)
};

}  // namespace mb::gl
