// The affine pipelines' GL side. Per draw: u_ModelMatrix (mat4x3, 12 floats) and
// u_NormalMatrix (mat3, 9 floats) for rigid draws (PipelineStats::floatsPerTransform = 21),
// u_Mirror (sign(det), in uniformBytesPerFrame) for every draw; skinned draws read the joint
// palette (12 floats per joint, stored as rows) and upload no transform, as glTF ignores a
// skinned node's own transform. The projection matrix is built once per frame. Bezier patch
// primitives are drawn rigidly by their node with affine_patch.vs (the same per-draw uniforms).
// Instanced nodes (Node::instances): the same model, normal matrix and mirror per instance,
// node world * instance composed per frame (MB_INSTANCED, pipelines/gl/instance_stream.h:
// 22 floats, 88 bytes per instance). matrix_c (FrameFormat::Compact, issue 29): rigid draws
// get the mesh's quantisation cube folded into u_ModelMatrix (model * translate * scale);
// skinned and instanced draws get it as u_Dequant (a vec4 per draw, in uniformBytesPerFrame).
// Morph targets (issue 37): a draw (instanced too) whose node has a non-zero weight uses the
// MB_MORPH variant of its program, the glTF deltas as matrix does (morph_buffers.h); qtangent,
// hybrid and matrix_c decode their frame and add the deltas to it (affine.vs), and matrix_c's
// morphing rigid draws dequantise per vertex instead of folding the cube into the model.
#include "pipelines/affine/affine_pipeline.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "pipelines/affine/compact_vertices.h"
#include "pipelines/affine/qtangent_vertices.h"
#include "pipelines/compact/compact_encoding.h"
#include "pipelines/gl/frame_vertices.h"
#include "pipelines/gl/gpu_geometry.h"
#include "pipelines/gl/instance_stream.h"
#include "pipelines/gl/morph_buffers.h"
#include "pipelines/gl/patch_geometry.h"
#include "pipelines/gl/program.h"
#include "pipelines/gl/scene_textures.h"
#include "pipelines/gl/upload.h"
#include "pipelines/scene/transform.h"

namespace mb::affine {
namespace {

class MatrixPoser final : public Poser {
public:
  Status prepare(const Scene& scene) override {
    prepareMatrixPose(scene, work_);
    return {};
  }
  void pose(const Scene& scene, const AnimState& state, Pose& out, PipelineStats&, PhaseClock& clock) override {
    poseScene(scene, state, work_, out, clock);
  }

private:
  MatrixPoseWork work_;
};

// A palette as the shader's row_major mat4x3 array reads it: per joint its three rows.
void appendRows(std::vector<float>& out, const glm::mat4x3& m) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) out.push_back(m[c][r]);
}

class AffinePipeline final : public Pipeline {
public:
  AffinePipeline(std::string name, FrameFormat format, std::unique_ptr<Poser> poser)
      : name_(std::move(name)), format_(format), poser_(std::move(poser)) {}
  ~AffinePipeline() override { release(); }
  std::string name() const override { return name_; }
  Status prepare(const Scene& scene) override;
  void update(const AnimState& state) override;
  void timeUpdatePhases(bool on) override { timePhases_ = on; }
  void render(const View& view) override;
  PipelineStats stats() const override { return stats_; }

private:
  void uploadPalettes();
  void streamInstances();
  void setDequant(const gl::Program& program, const gl::DrawItem& d);
  void release();

  std::string name_;
  FrameFormat format_;
  std::unique_ptr<Poser> poser_;
  const Scene* scene_ = nullptr;
  // [rigid, skinned, instanced (MB_INSTANCED)][no tangent] (qtangent: [.][0] only); the
  // instanced row only for scenes with instances.
  std::unique_ptr<gl::Program> programs_[3][2];
  std::unique_ptr<gl::Program> morphing_[3][2];  // programs_ with MB_MORPH, scenes with targets
  gl::MorphBuffers morph_;
  std::vector<std::vector<glm::mat4>> instanceMatrices_;  // per node: trsMatrix(instance)
  gl::InstanceStream instances_;
  std::unique_ptr<gl::Program> patch_;  // affine_patch.vs, only for scenes with patches
  gl::PatchGeometry patches_;
  gl::SceneTextures textures_;
  gl::SceneGeometry geometry_;
  std::vector<std::vector<compact::PositionCube>> cubes_;  // matrix_c: per mesh, per primitive
  gl::PaletteBuffers palettes_;  // one per pose_.palettes entry
  std::vector<gl::DrawItem> draws_;
  Pose pose_;
  bool timePhases_ = false;
  PipelineStats stats_;
};

Status AffinePipeline::prepare(const Scene& scene) {
  release();
  scene_ = &scene;
  stats_ = PipelineStats{};
  const bool qtangent = format_ == FrameFormat::QTangent, compact = format_ == FrameFormat::Compact;
  for (int kind = 0; kind < (gl::hasInstances(scene) ? 3 : 2); ++kind)
    for (int noTangent = 0; noTangent < (qtangent || compact ? 1 : 2); ++noTangent) {
      gl::Defines defines;
      if (qtangent) defines.push_back({"MB_QTANGENT", ""});
      if (compact) defines.push_back({"MB_COMPACT", ""});
      if (kind == 1) defines.push_back({"MB_SKINNED", ""});
      if (kind == 2) defines.push_back({"MB_INSTANCED", ""});
      if (noTangent) defines.push_back({"MB_NO_TANGENT", ""});
      auto program = gl::Program::fromFiles("affine.vs", "forward.fs", defines);
      if (!program) return Status::fail(program.error());
      programs_[kind][noTangent] = program.take();
      if (kind == 1) programs_[kind][noTangent]->bindStorageBlock("AffineJoints", 0);
      if (!gl::maxMorphTargets(scene)) continue;
      for (const auto& d : gl::morphDefines(scene)) defines.push_back(d);
      auto morphing = gl::Program::fromFiles("affine.vs", "forward.fs", defines);
      if (!morphing) return Status::fail(morphing.error());
      morphing_[kind][noTangent] = morphing.take();
      if (kind == 1) morphing_[kind][noTangent]->bindStorageBlock("AffineJoints", 0);
      morphing_[kind][noTangent]->bindStorageBlock("MorphDeltas", gl::kMorphBinding);
    }
  instanceMatrices_.assign(scene.nodes.size(), {});
  for (size_t n = 0; n < scene.nodes.size(); ++n)
    for (const TRS& t : scene.nodes[n].instances) instanceMatrices_[n].push_back(trsMatrix(t));
  if (Status fits = gl::checkPaletteSize(scene, 12 * sizeof(float)); !fits) return fits;
  if (Status tex = textures_.upload(scene, stats_.textureBytes); !tex) return tex;
  if (gl::hasPatches(scene)) {
    auto patch = gl::Program::fromFiles("affine_patch.vs", "forward.fs");
    if (!patch) return Status::fail(patch.error());
    patch_ = patch.take();
    if (Status up = patches_.upload(scene, stats_); !up) return up;
  }

  auto t0 = gl::Clock::now();
  if (Status posed = poser_->prepare(scene); !posed) return posed;
  if (format_ == FrameFormat::QTangent) {
    auto interleave = [this](const Primitive& p) {
      PackedStream s = interleaveQTangent(p);
      stats_.biasedFrames += s.biasedFrames;
      return std::move(s.bytes);
    };
    geometry_.uploadPacked(scene, interleave, qtangentAttributes(), stats_);
  } else if (compact) {
    cubes_ = compact::primitiveCubes(scene);
    geometry_.uploadPacked(scene, interleaveCompact, compact::attributes(), stats_);
  } else {
    geometry_.upload(scene, gl::floatFrameFormat, stats_);  // as matrix: tangent only where needed
  }
  if (gl::maxMorphTargets(scene)) morph_.upload(scene, gl::packFrameDeltas, stats_);
  stats_.conversionMs = gl::msSince(t0);
  draws_ = gl::buildDrawList(scene);
  update(AnimState{});
  GLenum err = glGetError();
  if (err != GL_NO_ERROR)
    return Status::fail(scene.source + ": " + name_ + " prepare: " + gl::errorName(err));
  return {};
}

void AffinePipeline::update(const AnimState& state) {
  if (!scene_) return;
  auto t0 = gl::Clock::now();
  PhaseClock clock(timePhases_ ? &stats_.updatePhases : nullptr);
  poser_->pose(*scene_, state, pose_, stats_, clock);
  drawnNormalMatrices(*scene_, pose_);
  morph_.update(*scene_, state);
  clock.lap(&UpdatePhases::hierarchyMs);
  stats_.updateMs = gl::msSince(t0);
}

void AffinePipeline::uploadPalettes() {
  stats_.skinBytesPerFrame = 0;
  uint64_t joints = 0;
  std::vector<float> rows;
  for (size_t i = 0; i < pose_.palettes.size(); ++i) {
    rows.clear();
    for (const glm::mat4x3& m : pose_.palettes[i].joints) appendRows(rows, m);
    palettes_.upload(i, rows.data(), rows.size() * sizeof(float), stats_.skinBytesPerFrame);
    joints += pose_.palettes[i].joints.size();
  }
  stats_.floatsPerJoint = gl::floatsPer(stats_.skinBytesPerFrame, joints);
}

// Per instance: model = node world * instance (mat4x3), its normal matrix and mirror; key 1:
// mirrored (the winding flips).
void AffinePipeline::streamInstances() {
  instances_.begin(scene_->nodes.size());
  for (size_t n = 0; n < instanceMatrices_.size(); ++n) {
    const std::vector<glm::mat4>& local = instanceMatrices_[n];
    if (local.empty()) continue;
    const glm::mat4 world(pose_.world[n]);
    instances_.addNode(int(n), local.size(), [&](size_t i, std::vector<float>& out) {
      const glm::mat4x3 model(world * local[i]);
      const glm::mat3 normal = normalMatrix(model);
      const float sign = mirror(model);
      out.insert(out.end(), glm::value_ptr(model), glm::value_ptr(model) + 12);
      out.insert(out.end(), glm::value_ptr(normal), glm::value_ptr(normal) + 9);
      out.push_back(sign);
      return sign < 0.0f ? 1 : 0;
    });
  }
  instances_.upload(stats_);
}

void AffinePipeline::render(const View& view) {
  if (!scene_) return;
  stats_.uniformBytesPerFrame = 0;
  stats_.draws = 0;
  stats_.morphDraws = 0;
  stats_.drawnVertices = 0;
  uploadPalettes();
  streamInstances();
  const glm::mat4 viewMatrix = glm::inverse(glm::translate(glm::mat4(1.0f), view.eye) *
                                            glm::mat4_cast(view.orientation));
  const glm::mat4 viewProjection = projectionMatrix(view) * viewMatrix;
  gl::beginDraws();
  // Per-frame uniforms go to a program when the frame first draws with it (as matrix and
  // motor do: a program the frame does not use uploads nothing).
  // kind -1: the Bezier patch program; 0 rigid, 1 skinned, 2 instanced.
  bool frameSet[4][2][2] = {};
  auto useProgram = [&](int kind, int noTangent, bool morph = false) -> const gl::Program& {
    gl::Program& p = kind < 0 ? *patch_ : morph ? *morphing_[kind][noTangent] : *programs_[kind][noTangent];
    p.use();
    if (!frameSet[kind + 1][noTangent][morph]) {
      frameSet[kind + 1][noTangent][morph] = true;
      gl::uniformMatrix4(p.uniform("u_ViewProjectionMatrix"), 1, glm::value_ptr(viewProjection),
                         stats_.uniformBytesPerFrame);
      gl::setFrameUniforms(p, view, stats_.uniformBytesPerFrame);
    }
    return p;
  };
  uint64_t transformBytes = 0, transforms = 0;
  uint64_t mirrorBytes = 0;  // u_Mirror of the per-draw transforms: their per-draw float, as the motor's u_Scale
  for (const gl::DrawItem& d : draws_) {
    const gl::GpuPrimitive& g = geometry_.at(d);
    const Primitive& prim = scene_->meshes[size_t(d.mesh)].primitives[size_t(d.primitive)];
    const bool patch = patches_.has(d);  // drawn rigidly by its node (never skinned)
    if (!patch && !g.indexCount) continue;
    // A mesh shared by a skinned and an unskinned node is drawn rigidly on the latter.
    GLuint palette = 0;
    for (size_t i = 0; !patch && g.skinned && i < pose_.palettes.size(); ++i)
      if (pose_.palettes[i].node == d.node) palette = palettes_[i];
    const int noTangent = g.variant == 1 ? 1 : 0;
    const bool morph = !patch && morphing_[0][0] && morph_.active(d);
    const auto& groups = instances_.groups(d.node);  // instanceable nodes only: no patch, no skin
    if (!groups.empty()) {
      const gl::Program& program = useProgram(2, noTangent, morph);
      if (format_ == FrameFormat::Compact) setDequant(program, d);
      if (morph) morph_.bind(program, d, stats_.uniformBytesPerFrame), ++stats_.morphDraws;
      textures_.bindMaterial(program, prim.material, stats_.uniformBytesPerFrame);
      for (const gl::InstanceGroup& group : groups) {
        gl::setWinding(group.key == 1);
        stats_.drawnVertices += instances_.draw(g, group, {3, 3, 3, 3, 3, 3, 3, 1});
        ++stats_.draws;
      }
      continue;
    }
    const gl::Program& program = patch ? useProgram(-1, 0) : useProgram(palette ? 1 : 0, noTangent, morph);
    if (morph) {
      morph_.bind(program, d, stats_.uniformBytesPerFrame);
      ++stats_.morphDraws;
    }
    glm::mat4x3 model = pose_.world[size_t(d.node)];
    const float sign = pose_.mirrors[size_t(d.node)];
    if (format_ == FrameFormat::Compact && !patch && !palette && !morph) {  // the mesh's cube folded in
      const compact::PositionCube& cube = cubes_[size_t(d.mesh)][size_t(d.primitive)];
      model = model * glm::scale(glm::translate(glm::mat4(1.0f), cube.center), glm::vec3(cube.extent));
    }
    if (format_ == FrameFormat::Compact && (palette || morph)) setDequant(program, d);
    if (palette) {
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, palette);
    } else {
      const glm::mat3& normal = pose_.normals[size_t(d.node)];
      gl::uniformMatrix4x3(program.uniform("u_ModelMatrix"), 1, glm::value_ptr(model), transformBytes);
      gl::uniformMatrix3(program.uniform("u_NormalMatrix"), 1, glm::value_ptr(normal), transformBytes);
      ++transforms;
    }
    gl::uniform1f(program.uniform("u_Mirror"), sign, palette ? stats_.uniformBytesPerFrame : mirrorBytes);
    textures_.bindMaterial(program, prim.material, stats_.uniformBytesPerFrame);
    gl::setWinding(sign < 0.0f);
    stats_.drawnVertices += patch ? patches_.draw(d) : g.draw();
    ++stats_.draws;
  }
  gl::endDraws();
  stats_.uniformBytesPerFrame += transformBytes + mirrorBytes;
  stats_.floatsPerTransform = gl::floatsPer(transformBytes, transforms);
  // Beside the motor's 8 + u_Scale (issue 35 item 7): mat4x3 + mat3 + the mirror float.
  stats_.floatsPerTransformWithScale = gl::floatsPer(transformBytes + mirrorBytes, transforms);
}

// matrix_c's draws that cannot fold the mesh's cube (skinned, instanced) dequantise per vertex.
void AffinePipeline::setDequant(const gl::Program& program, const gl::DrawItem& d) {
  const glm::vec4 q = cubes_[size_t(d.mesh)][size_t(d.primitive)].dequant();
  gl::uniform4f(program.uniform("u_Dequant"), &q[0], stats_.uniformBytesPerFrame);
}

void AffinePipeline::release() {
  geometry_.release();
  morph_.release();
  for (auto& row : morphing_)
    for (auto& p : row) p.reset();
  patches_.release();
  patch_.reset();
  palettes_.release();
  textures_.release();
  instances_.release();
  for (auto& row : programs_)
    for (auto& p : row) p.reset();
  scene_ = nullptr;
}

}  // namespace

std::unique_ptr<Poser> makeMatrixPoser() { return std::make_unique<MatrixPoser>(); }

std::unique_ptr<Pipeline> makePipeline(const std::string& name, FrameFormat format,
                                       std::unique_ptr<Poser> poser) {
  return std::make_unique<AffinePipeline>(name, format, std::move(poser));
}

}  // namespace mb::affine

namespace mb {
std::unique_ptr<Pipeline> makeAffinePipeline() {
  return affine::makePipeline("affine", affine::FrameFormat::Float, affine::makeMatrixPoser());
}
std::unique_ptr<Pipeline> makeQtangentPipeline() {
  return affine::makePipeline("qtangent", affine::FrameFormat::QTangent, affine::makeMatrixPoser());
}
std::unique_ptr<Pipeline> makeMatrixCPipeline() {
  return affine::makePipeline("matrix_c", affine::FrameFormat::Compact, affine::makeMatrixPoser());
}
}  // namespace mb
