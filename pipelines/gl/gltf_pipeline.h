// The draw path every glTF pipeline shares (matrix, affine, motor and their variants): the
// guards of prepare() (the curved-space refusal, the palette limit, the GL error check), the
// programs (linked once per define set, as the Khronos Sample Viewer's shader cache keys them),
// textures, Bezier patches, the draw list and the frame's loop over it, the per-frame stat
// resets, the joint palette and instance buffers, material binding, winding and the draw counts,
// and release(). A pipeline derives from it and supplies what is its own: its vertex layout and
// encoding, its vertex shader and defines, its draws' programs and uniforms and its CPU update.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/gl/gpu_geometry.h"
#include "pipelines/gl/instance_stream.h"
#include "pipelines/gl/morph_buffers.h"
#include "pipelines/gl/patch_geometry.h"
#include "pipelines/gl/program.h"
#include "pipelines/gl/scene_textures.h"
#include "pipelines/gl/upload.h"
#include "pipelines/pipeline.h"

namespace mb::gl {

// A linked program and the frame that last set its per-frame uniforms.
struct CachedProgram {
  std::unique_ptr<Program> program;
  uint64_t frame = 0;
};

// What the per-draw uniforms of a frame added up to: the transforms, the bytes of their
// uniforms and of what a transform adds beside them (affine's mirror float, motor's scale).
struct TransformCounters {
  uint64_t transformBytes = 0, scaleBytes = 0, transforms = 0;
};

// One item of the draw list as a frame draws it.
struct Draw {
  const DrawItem& d;
  const GpuPrimitive& g;
  const Primitive& prim;
  bool patch = false;  // Bezier patches: drawn rigidly by their node (never skinned)
  bool morph = false;  // its morph deltas bound (counted per draw call)
  int palette = -1;    // its node's joint palette (its buffer bound at binding 0), -1: none
};

// How a draw reaches world space: the first index of a ProgramGrid.
enum DrawKind { kRigid = 0, kSkinned = 1, kInstanced = 2, kDrawKinds = 3 };

// A pipeline's programs (owned by the program cache), only those a scene can use linked: its
// vertex shader's by draw kind, by what the pipeline varies beside it (matrix family: the frame
// variant; motor: the scale form) and by whether the draw morphs; its patch shader's.
struct ProgramGrid {
  CachedProgram* at[kDrawKinds][3][2] = {};  // [kind][variant][MB_MORPH]
  CachedProgram* patch[2] = {};              // motor: [per-axis scale]
  CachedProgram& of(const Draw& m, DrawKind kind, int variant) const { return *at[kind][variant][m.morph ? 1 : 0]; }
};

class GltfPipeline : public Pipeline {
public:
  void timeUpdatePhases(bool on) override { timePhases_ = on; }
  PipelineStats stats() const override { return stats_; }

protected:
  // prepare()'s shared start (after the pipeline's release()): a curved-space scene refused, the
  // stats reset, the palette checked against the storage block limit at `bytesPerJoint`, the
  // textures and Bezier patches uploaded.
  Status beginPrepare(const Scene& scene, size_t bytesPerJoint);
  // prepare()'s shared end: the draw list, the rest pose (update(AnimState{})) and the GL
  // error check naming the scene and the pipeline.
  Status endPrepare(const Scene& scene);
  // The program of `vs` (with forward.fs) and a define set, linked the first time that key is
  // asked for (its storage blocks name their binding points: layout(binding = N)); nullptr with
  // `status` set on failure.
  CachedProgram* link(Status& status, const std::string& vs, const Defines& defines);
  // Links `vs` into `grid`: each draw kind (instanced only for a scene with instances), each of
  // its variants(kind) variants, morphing (for a scene with morph targets: morphDefines added)
  // or not, with defines(kind, variant, morphing).
  Status linkGrid(ProgramGrid& grid, const std::string& vs, const std::function<int(int)>& variants,
                  const std::function<Defines(int, int, bool)>& defines);
  // Makes `p` current for draw `m`; the first time in a frame, setFrame(program) uploads its
  // per-frame uniforms (a program the frame does not use uploads nothing, so
  // uniformBytesPerFrame counts what a frame needs). A morphing draw's deltas are bound
  // (counted per draw call).
  template <class SetFrame>
  const Program& use(CachedProgram& p, const Draw& m, const MorphBuffers& morph, SetFrame&& setFrame) {
    p.program->use();
    if (p.frame != frame_) {
      p.frame = frame_;
      setFrame(*p.program);
    }
    if (m.morph) {
      morph.bind(*p.program, m.d, stats_.uniformBytesPerFrame);
      ++stats_.morphDraws;
    }
    return *p.program;
  }
  // render()'s shared start: the per-frame counters reset, a new frame for the programs'
  // per-frame uniforms, the joint palettes uploaded (upload(i) uploads palette i of `palettes`,
  // adding its bytes to skinBytesPerFrame, and returns its joints).
  template <class Upload>
  void beginFrame(size_t palettes, Upload upload) {
    stats_.uniformBytesPerFrame = 0;
    stats_.draws = 0;
    stats_.morphDraws = 0;
    stats_.drawnVertices = 0;
    stats_.linearFallbackDraws = stats_.skinFallbackDraws = stats_.skinFallbackJoints = 0;
    stats_.fallbackVertices = stats_.skinFallbackVertices = 0;
    ++frame_;
    stats_.skinBytesPerFrame = 0;
    uint64_t joints = 0;
    for (size_t i = 0; i < palettes; ++i) joints += upload(i);
    stats_.floatsPerJoint = floatsPer(stats_.skinBytesPerFrame, joints);
  }
  // The frame's instances streamed: node n's when local[n] (its instances' transforms, converted
  // by prepare()) has any, instance i written by write(world, local[n][i], out), which returns its
  // key, with world = worldOf(n) read once per node.
  template <class Local, class WorldOf, class Write>
  void streamInstances(const std::vector<std::vector<Local>>& local, WorldOf worldOf, Write write) {
    instances_.begin(scene_->nodes.size());
    for (size_t n = 0; n < local.size(); ++n) {
      if (local[n].empty()) continue;
      const auto& world = worldOf(n);
      instances_.addNode(int(n), local[n].size(),
                         [&](size_t i, std::vector<float>& out) { return write(world, local[n][i], out); });
    }
    instances_.upload(stats_);
  }
  // The frame's draw list, each item with something to draw handed to `self` (no virtual call
  // per draw): self.drawInstanceGroups(frame, draw, groups) for an instanced node,
  // self.drawNode(frame, draw) for the others. `frame`, the pipeline's per-frame context, counts
  // the transforms. Draw::palette: the palette in `palettes` of the item's node (a mesh shared by
  // a skinned and an unskinned node is drawn rigidly on the latter; patches are never skinned),
  // its buffer bound at storage binding 0, where every skinned program reads its joints.
  template <class Self, class Frame, class Palette>
  void drawList(Self& self, Frame& frame, const SceneGeometry& geometry, const MorphBuffers& morph,
                const std::vector<Palette>& palettes) {
    beginDraws();
    for (const DrawItem& d : draws_) {
      const GpuPrimitive& g = geometry.at(d);
      const bool patch = patches_.has(d);
      if (!patch && !g.indexCount) continue;
      int palette = -1;
      for (size_t i = 0; !patch && g.skinned && i < palettes.size(); ++i)
        if (palettes[i].node == d.node) palette = int(i);
      if (palette >= 0) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, palettes_[size_t(palette)]);
      const Primitive& prim = scene_->meshes[size_t(d.mesh)].primitives[size_t(d.primitive)];
      const Draw draw{d, g, prim, patch, !patch && morph.active(d), palette};
      const auto& groups = instances_.groups(d.node);  // instanceable nodes only: no patch, no skin
      if (groups.empty())
        self.drawNode(frame, draw);
      else
        self.drawInstanceGroups(frame, draw, groups);
    }
    endDraws();
    const TransformCounters& c = frame;
    stats_.uniformBytesPerFrame += c.transformBytes + c.scaleBytes;
    stats_.floatsPerTransform = floatsPer(c.transformBytes, c.transforms);
    stats_.floatsPerTransformWithScale = floatsPer(c.transformBytes + c.scaleBytes, c.transforms);
  }
  void bindMaterial(const Program& program, const Primitive& prim) {
    textures_.bindMaterial(program, prim.material, stats_.uniformBytesPerFrame);
  }
  // One draw of `m` (its patch or its triangles), counted.
  void drawCounted(const Draw& m) {
    stats_.drawnVertices += m.patch ? patches_.draw(m.d) : m.g.draw();
    ++stats_.draws;
  }
  // One instanced draw of `group` (the winding flipped when `mirrored`), counted.
  void drawGroup(const GpuPrimitive& g, const InstanceGroup& group, const InstanceLayout& layout, bool mirrored) {
    setWinding(mirrored);
    stats_.drawnVertices += instances_.draw(g, group, layout);
    ++stats_.draws;
  }
  // The 16-byte vertex (matrix_c, motor_c): u_Dequant, the cube of `d`'s primitive, for draws
  // that cannot fold it into their transform and dequantise per vertex (`cubes`: per mesh, per
  // primitive, compact::primitiveCubes).
  template <class Cubes>
  void setDequant(const Program& program, const Cubes& cubes, const DrawItem& d) {
    const glm::vec4 q = cubes[size_t(d.mesh)][size_t(d.primitive)].dequant();
    uniform4f(program.uniform("u_Dequant"), &q[0], stats_.uniformBytesPerFrame);
  }
  // The shared GL objects released (a pipeline's release() calls it after its own).
  void releaseShared();

  const Scene* scene_ = nullptr;
  PipelineStats stats_;
  bool timePhases_ = false;
  std::map<std::string, std::unique_ptr<CachedProgram>> cache_;  // by vertex shader and define set
  ProgramGrid programs_;
  PatchGeometry patches_;
  SceneTextures textures_;
  PaletteBuffers palettes_;  // one per palette of the pose (same order every update)
  InstanceStream instances_;
  std::vector<DrawItem> draws_;

private:
  uint64_t frame_ = 0;
};

}  // namespace mb::gl
