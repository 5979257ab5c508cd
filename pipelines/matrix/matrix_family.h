// The matrix family's pipelines (matrix, affine, qtangent, matrix_c, and hybrid in
// pipelines/hybrid): one prepare, update and render over the shared draw path, the pipeline
// (`Self`, CRTP so that no virtual call is made per draw or per instance) supplying what is its
// own:
//   kVertexShader, kPatchShader, kBytesPerJoint, kInstanceLayout, frames(),
//   defines(kind, frame)                                   its programs
//   convert(scene) (timed as conversionMs), preparePose(scene)   its vertices and pose set-up
//   pose(state, clock), posed(clock)                       its CPU update
//   palettes(), uploadPalette(i) -> joints                 its joint palettes
//   instanceWorld(node), writeInstance(model, out) -> key  its per-instance data
//   instancedUniforms(program, d), drawUniforms(program, draw, counters)
//                                                          its per-draw uniforms (-> mirrored)
// Every draw's program is picked from the grid by draw kind (rigid, skinned, instanced), frame
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
    Status linked = linkGrid(programs_, Self::kVertexShader, [this](int) { return self().frames(); },
                             [this](int kind, int frame, bool) { return self().defines(kind, frame); });
    if (linked && hasPatches(scene)) programs_.patch[0] = link(linked, Self::kPatchShader, {});
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
    // Per instance: model = node world * instance, written by the pipeline, which returns its
    // key (1: mirrored, the winding flips).
    streamInstances(instanceMatrices_, [this](size_t n) { return self().instanceWorld(n); },
                    [this](const glm::mat4& world, const glm::mat4& local, std::vector<float>& out) {
                      return self().writeInstance(world * local, out);
                    });
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
    const Program& program = useProgram(f, m, programs_.of(m, kInstanced, m.g.variant));
    self().instancedUniforms(program, m.d);
    bindMaterial(program, m.prim);
    for (const InstanceGroup& group : groups) drawGroup(m.g, group, Self::kInstanceLayout, group.key == 1);
  }

  // A draw by its node's transform or its skin's palette, or a Bezier patch (kPatchShader).
  void drawNode(MatrixFrame& f, const Draw& m) {
    CachedProgram& p = m.patch ? *programs_.patch[0] : programs_.of(m, m.palette < 0 ? kRigid : kSkinned, m.g.variant);
    const Program& program = useProgram(f, m, p);
    const bool mirrored = self().drawUniforms(program, m, f);
    bindMaterial(program, m.prim);
    setWinding(mirrored);
    drawCounted(m);
  }

  // `p` made current for `m`, the frame's view-projection and view uniforms set (see use()).
  const Program& useProgram(const MatrixFrame& f, const Draw& m, CachedProgram& p) {
    return use(p, m, morph_, [&](const Program& program) {
      uniformMatrix4(program.uniform("u_ViewProjectionMatrix"), 1, glm::value_ptr(f.viewProjection),
                     stats_.uniformBytesPerFrame);
      setFrameUniforms(program, f.view, stats_.uniformBytesPerFrame);
    });
  }

  void release() {
    geometry_.release();
    morph_.release();
    releaseShared();
  }

  std::vector<std::vector<glm::mat4>> instanceMatrices_;  // per node: trsMatrix(instance)
};

}  // namespace mb::gl
