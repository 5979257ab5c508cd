// The matrix/TBN pipeline: the Khronos glTF-Sample-Viewer baseline the paper compares with.
// CPU: GLM matrices and quaternions for the hierarchy, animation and skin palettes.
// GPU: shaders/matrix.vs (+ SKINNED variant) and the shared shaders/forward.fs.
// Per draw it uploads u_ModelMatrix and u_NormalMatrix (2 x mat4 = 32 floats, skinned draws
// included, as the Sample Viewer does); per joint a joint matrix and a joint normal matrix.
// Vertex format per primitive as the Sample Viewer's (pipelines/gl/frame_vertices.h): a tangent only where
// the primitive has one (authored, or generated for a normal map); the MB_NO_TANGENT shader
// variant draws the others. Skinning: SkinSpace::Reference by default (the Sample Viewer's);
// WorldPalette on request (configure()). Instanced nodes (Node::instances): the same two
// matrices per instance, node world * instance composed per frame (MB_INSTANCED,
// pipelines/gl/instance_stream.h: 128 bytes per instance). Morph targets: the MB_MORPH variants
// (shaders/morph.glsl) for draws whose node has a non-zero weight, the glTF deltas as they are
// (pipelines/gl/morph_buffers.h), instanced draws too (every instance with its node's weights).
#include "pipelines/matrix/matrix_pipeline.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "pipelines/gl/frame_vertices.h"
#include "pipelines/gl/gpu_geometry.h"
#include "pipelines/gl/instance_stream.h"
#include "pipelines/gl/morph_buffers.h"
#include "pipelines/gl/patch_geometry.h"
#include "pipelines/gl/program.h"
#include "pipelines/gl/scene_textures.h"
#include "pipelines/gl/upload.h"
#include "pipelines/matrix/matrix_pose.h"
#include "pipelines/scene/transform.h"

namespace mb {
namespace {

class MatrixPipeline final : public Pipeline {
public:
  ~MatrixPipeline() override { release(); }
  std::string name() const override { return "matrix"; }
  void configure(const PipelineOptions& options) override {
    worldPalette_ = options.skinSpace == SkinSpace::WorldPalette;
  }
  SkinSpace skinSpace() const override {
    return worldPalette_ ? SkinSpace::WorldPalette : SkinSpace::Reference;
  }
  Status prepare(const Scene& scene) override;
  void update(const AnimState& state) override;
  void timeUpdatePhases(bool on) override { timePhases_ = on; }
  void render(const View& view) override;
  PipelineStats stats() const override { return stats_; }

private:
  void uploadPalettes();
  void streamInstances();
  void release();

  const Scene* scene_ = nullptr;
  std::unique_ptr<gl::Program> programs_[2][2];  // [skinned][no tangent]
  std::unique_ptr<gl::Program> morphing_[3][2];  // [skinned, 2: instanced][no tangent] with MB_MORPH
  gl::MorphBuffers morph_;
  std::unique_ptr<gl::Program> instanced_[2];    // MB_INSTANCED [no tangent]
  std::vector<std::vector<glm::mat4>> instanceMatrices_;  // per node: trsMatrix(instance)
  gl::InstanceStream instances_;
  bool worldPalette_ = false;
  std::unique_ptr<gl::Program> patch_;  // matrix_patch.vs, only for scenes with patches
  gl::PatchGeometry patches_;
  gl::SceneTextures textures_;
  gl::SceneGeometry geometry_;
  gl::PaletteBuffers palettes_;  // one per pose_.palettes entry (same order every update)
  std::vector<gl::DrawItem> draws_;
  MatrixPoseWork work_;  // per-frame buffers and the hierarchy order
  matrix::Pose pose_;
  bool timePhases_ = false;
  PipelineStats stats_;
};

Status MatrixPipeline::prepare(const Scene& scene) {
  release();
  if (Status curved = refuseCurvedScene(scene, name()); !curved) return curved;
  scene_ = &scene;
  stats_ = PipelineStats{};
  for (int skinned = 0; skinned < 2; ++skinned)
    for (int noTangent = 0; noTangent < 2; ++noTangent) {
      gl::Defines defines;
      if (skinned) defines.push_back({"SKINNED", ""});
      if (skinned && worldPalette_) defines.push_back({"MB_WORLD_PALETTE", ""});
      if (noTangent) defines.push_back({"MB_NO_TANGENT", ""});
      auto program = gl::Program::fromFiles("matrix.vs", "forward.fs", defines);
      if (!program) return Status::fail(program.error());
      programs_[skinned][noTangent] = program.take();
      if (skinned) programs_[skinned][noTangent]->bindStorageBlock("JointPalette", 0);
      if (!gl::maxMorphTargets(scene)) continue;
      for (const auto& d : gl::morphDefines(scene)) defines.push_back(d);
      auto morphing = gl::Program::fromFiles("matrix.vs", "forward.fs", defines);
      if (!morphing) return Status::fail(morphing.error());
      morphing_[skinned][noTangent] = morphing.take();
      if (skinned) morphing_[skinned][noTangent]->bindStorageBlock("JointPalette", 0);
      morphing_[skinned][noTangent]->bindStorageBlock("MorphDeltas", gl::kMorphBinding);
    }
  instanceMatrices_.assign(scene.nodes.size(), {});
  for (size_t n = 0; n < scene.nodes.size(); ++n)
    for (const TRS& t : scene.nodes[n].instances) instanceMatrices_[n].push_back(trsMatrix(t));
  for (int noTangent = 0; noTangent < 2 && gl::hasInstances(scene); ++noTangent) {
    gl::Defines defines{{"MB_INSTANCED", ""}};
    if (noTangent) defines.push_back({"MB_NO_TANGENT", ""});
    auto program = gl::Program::fromFiles("matrix.vs", "forward.fs", defines);
    if (!program) return Status::fail(program.error());
    instanced_[noTangent] = program.take();
    if (!gl::maxMorphTargets(scene)) continue;
    for (const auto& d : gl::morphDefines(scene)) defines.push_back(d);
    auto morphing = gl::Program::fromFiles("matrix.vs", "forward.fs", defines);
    if (!morphing) return Status::fail(morphing.error());
    morphing_[2][noTangent] = morphing.take();
    morphing_[2][noTangent]->bindStorageBlock("MorphDeltas", gl::kMorphBinding);
  }
  if (Status fits = gl::checkPaletteSize(scene, 2 * sizeof(glm::mat4)); !fits) return fits;
  if (Status tex = textures_.upload(scene, stats_.textureBytes); !tex) return tex;

  if (gl::hasPatches(scene)) {
    auto patch = gl::Program::fromFiles("matrix_patch.vs", "forward.fs");
    if (!patch) return Status::fail(patch.error());
    patch_ = patch.take();
    if (Status up = patches_.upload(scene, stats_); !up) return up;
  }
  auto t0 = gl::Clock::now();
  geometry_.upload(scene, gl::floatFrameFormat, stats_);  // variant 1: no tangent
  morph_.upload(scene, gl::packFrameDeltas, stats_);
  stats_.conversionMs = gl::msSince(t0);
  draws_ = gl::buildDrawList(scene);
  prepareMatrixPose(scene, work_);
  update(AnimState{});
  GLenum err = glGetError();
  if (err != GL_NO_ERROR) return Status::fail(scene.source + ": matrix prepare: " + gl::errorName(err));
  return {};
}

void MatrixPipeline::update(const AnimState& state) {
  if (!scene_) return;
  auto t0 = gl::Clock::now();
  PhaseClock clock(timePhases_ ? &stats_.updatePhases : nullptr);
  matrix::poseScene(*scene_, state, worldPalette_, work_, pose_, clock);
  morph_.update(*scene_, state);
  stats_.updateMs = gl::msSince(t0);
}

void MatrixPipeline::uploadPalettes() {
  stats_.skinBytesPerFrame = 0;
  uint64_t joints = 0;
  for (size_t i = 0; i < pose_.palettes.size(); ++i) {
    const auto& m = pose_.palettes[i].matrices;
    palettes_.upload(i, m.empty() ? nullptr : glm::value_ptr(m[0]), m.size() * sizeof(glm::mat4),
                     stats_.skinBytesPerFrame);
    joints += m.size() / 2;
  }
  stats_.floatsPerJoint = gl::floatsPer(stats_.skinBytesPerFrame, joints);
}

// Per instance: model = node world * instance, and its normal matrix (sign(det) in [3][3]);
// key 1: mirrored (the winding flips).
void MatrixPipeline::streamInstances() {
  instances_.begin(scene_->nodes.size());
  for (size_t n = 0; n < instanceMatrices_.size(); ++n) {
    const std::vector<glm::mat4>& local = instanceMatrices_[n];
    if (local.empty()) continue;
    instances_.addNode(int(n), local.size(), [&](size_t i, std::vector<float>& out) {
      const glm::mat4 model = pose_.world[n] * local[i];
      const glm::mat4 normal = matrix::normalMatrix(model);
      out.insert(out.end(), glm::value_ptr(model), glm::value_ptr(model) + 16);
      out.insert(out.end(), glm::value_ptr(normal), glm::value_ptr(normal) + 16);
      return normal[3][3] < 0.0f ? 1 : 0;
    });
  }
  instances_.upload(stats_);
}

void MatrixPipeline::render(const View& view) {
  if (!scene_) return;
  stats_.uniformBytesPerFrame = 0;
  stats_.draws = 0;
  stats_.morphDraws = 0;
  stats_.drawnVertices = 0;
  uploadPalettes();
  streamInstances();
  glm::mat4 viewMatrix = glm::inverse(glm::translate(glm::mat4(1.0f), view.eye) *
                                      glm::mat4_cast(view.orientation));
  glm::mat4 viewProjection = projectionMatrix(view) * viewMatrix;
  gl::beginDraws();
  // Per-frame uniforms go to a program when the frame first draws with it (unused variants
  // upload nothing, so uniformBytesPerFrame counts what a frame needs).
  // skinned -1: the Bezier patch program (matrix_patch.vs); 2: instanced (MB_INSTANCED).
  bool frameSet[4][2][2] = {};
  auto useProgram = [&](int skinned, int noTangent, bool morph = false) -> const gl::Program& {
    gl::Program& p = skinned < 0    ? *patch_
                     : morph        ? *morphing_[skinned][noTangent]
                     : skinned == 2 ? *instanced_[noTangent]
                                    : *programs_[skinned][noTangent];
    p.use();
    if (!frameSet[skinned + 1][noTangent][morph]) {
      frameSet[skinned + 1][noTangent][morph] = true;
      gl::uniformMatrix4(p.uniform("u_ViewProjectionMatrix"), 1, glm::value_ptr(viewProjection),
                         stats_.uniformBytesPerFrame);
      gl::setFrameUniforms(p, view, stats_.uniformBytesPerFrame);
    }
    return p;
  };
  uint64_t transformBytes = 0, transformDraws = 0;
  for (const gl::DrawItem& d : draws_) {
    const gl::GpuPrimitive& g = geometry_.at(d);
    const Primitive& prim = scene_->meshes[size_t(d.mesh)].primitives[size_t(d.primitive)];
    const bool patch = patches_.has(d);  // Bezier patches: drawn rigidly by their node (never skinned)
    if (!patch && !g.indexCount) continue;
    // A mesh shared by a skinned and an unskinned node is drawn rigidly on the latter.
    GLuint palette = 0;
    for (size_t i = 0; !patch && g.skinned && i < pose_.palettes.size(); ++i)
      if (pose_.palettes[i].node == d.node) palette = palettes_[i];
    const bool morph = !patch && morph_.active(d);
    const auto& groups = instances_.groups(d.node);  // instanceable nodes only: no patch, no skin
    if (!groups.empty()) {
      const gl::Program& program = useProgram(2, g.variant == 1 ? 1 : 0, morph);
      if (morph) morph_.bind(program, d, stats_.uniformBytesPerFrame), ++stats_.morphDraws;
      textures_.bindMaterial(program, prim.material, stats_.uniformBytesPerFrame);
      for (const gl::InstanceGroup& group : groups) {
        gl::setWinding(group.key == 1);
        stats_.drawnVertices += instances_.draw(g, group, {4, 4, 4, 4, 4, 4, 4, 4});
        ++stats_.draws;
      }
      continue;
    }
    const gl::Program& program =
        patch ? useProgram(-1, 0) : useProgram(palette ? 1 : 0, g.variant == 1 ? 1 : 0, morph);
    if (palette) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, palette);
    if (morph) {
      morph_.bind(program, d, stats_.uniformBytesPerFrame);
      ++stats_.morphDraws;
    }
    const glm::mat4& model = pose_.world[size_t(d.node)];
    const glm::mat4& normal = pose_.normals[size_t(d.node)];
    gl::uniformMatrix4(program.uniform("u_ModelMatrix"), 1, glm::value_ptr(model), transformBytes);
    gl::uniformMatrix4(program.uniform("u_NormalMatrix"), 1, glm::value_ptr(normal), transformBytes);
    ++transformDraws;
    textures_.bindMaterial(program, prim.material, stats_.uniformBytesPerFrame);
    gl::setWinding(normal[3][3] < 0.0f);  // sign(det(model)) as stored by normalMatrix()
    stats_.drawnVertices += patch ? patches_.draw(d) : g.draw();
    ++stats_.draws;
  }
  gl::endDraws();
  stats_.uniformBytesPerFrame += transformBytes;
  stats_.floatsPerTransform = gl::floatsPer(transformBytes, uint64_t(transformDraws));
  stats_.floatsPerTransformWithScale = stats_.floatsPerTransform;  // the scale is in the matrices
}

void MatrixPipeline::release() {
  geometry_.release();
  morph_.release();
  patches_.release();
  patch_.reset();
  palettes_.release();
  textures_.release();
  instances_.release();
  for (auto& p : instanced_) p.reset();
  for (auto& row : programs_)
    for (auto& p : row) p.reset();
  for (auto& row : morphing_)
    for (auto& p : row) p.reset();
  scene_ = nullptr;
}

}  // namespace

std::unique_ptr<Pipeline> makeMatrixPipeline() { return std::make_unique<MatrixPipeline>(); }

}  // namespace mb
