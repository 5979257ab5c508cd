// The matrix/TBN pipeline: the Khronos glTF-Sample-Viewer baseline the paper compares with.
// CPU: GLM matrices and quaternions for the hierarchy, animation and skin palettes.
// GPU: shaders/matrix.vs (+ SKINNED variant) and the shared shaders/forward.fs.
// Per draw it uploads u_ModelMatrix and u_NormalMatrix (2 x mat4 = 32 floats, skinned draws
// included, as the Sample Viewer does); per joint a joint matrix and a joint normal matrix.
#include "pipelines/matrix/matrix_pipeline.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "pipelines/gl/gpu_geometry.h"
#include "pipelines/gl/patch_geometry.h"
#include "pipelines/gl/program.h"
#include "pipelines/gl/scene_textures.h"
#include "pipelines/gl/upload.h"
#include "pipelines/matrix/matrix_pose.h"
#include "pipelines/matrix/matrix_vertices.h"

namespace mb {
namespace {

class MatrixPipeline final : public Pipeline {
public:
  ~MatrixPipeline() override { release(); }
  std::string name() const override { return "matrix"; }
  Status prepare(const Scene& scene) override;
  void update(const AnimState& state) override;
  void render(const View& view) override;
  PipelineStats stats() const override { return stats_; }

private:
  void uploadPalettes();
  void release();

  const Scene* scene_ = nullptr;
  std::unique_ptr<gl::Program> rigid_, skinned_;
  std::unique_ptr<gl::Program> patch_;  // matrix_patch.vs, only for scenes with patches
  gl::PatchGeometry patches_;
  gl::SceneTextures textures_;
  gl::SceneGeometry geometry_;
  gl::PaletteBuffers palettes_;  // one per pose_.palettes entry (same order every update)
  std::vector<gl::DrawItem> draws_;
  matrix::Pose pose_;
  PipelineStats stats_;
};

Status MatrixPipeline::prepare(const Scene& scene) {
  release();
  if (Status curved = refuseCurvedScene(scene, name()); !curved) return curved;
  scene_ = &scene;
  stats_ = PipelineStats{};
  auto rigid = gl::Program::fromFiles("matrix.vs", "forward.fs");
  if (!rigid) return Status::fail(rigid.error());
  auto skinned = gl::Program::fromFiles("matrix.vs", "forward.fs", {{"SKINNED", ""}});
  if (!skinned) return Status::fail(skinned.error());
  rigid_ = rigid.take();
  skinned_ = skinned.take();
  skinned_->bindStorageBlock("JointPalette", 0);
  if (Status fits = gl::checkPaletteSize(scene, 2 * sizeof(glm::mat4)); !fits) return fits;
  if (Status tex = textures_.upload(scene, stats_.textureBytes); !tex) return tex;

  if (gl::hasPatches(scene)) {
    auto patch = gl::Program::fromFiles("matrix_patch.vs", "forward.fs");
    if (!patch) return Status::fail(patch.error());
    patch_ = patch.take();
    if (Status up = patches_.upload(scene, stats_); !up) return up;
  }
  auto t0 = gl::Clock::now();
  geometry_.upload(scene, matrix::interleaveVertices, {3, 3, 4, 2}, stats_);  // pos, n, t, uv
  stats_.conversionMs = gl::msSince(t0);
  draws_ = gl::buildDrawList(scene);
  update(AnimState{});
  GLenum err = glGetError();
  if (err != GL_NO_ERROR) return Status::fail(scene.source + ": matrix prepare: " + gl::errorName(err));
  return {};
}

void MatrixPipeline::update(const AnimState& state) {
  if (!scene_) return;
  auto t0 = gl::Clock::now();
  pose_ = matrix::poseScene(*scene_, state);
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

void MatrixPipeline::render(const View& view) {
  if (!scene_) return;
  stats_.uniformBytesPerFrame = 0;
  stats_.draws = 0;
  uploadPalettes();
  glm::mat4 viewMatrix = glm::inverse(glm::translate(glm::mat4(1.0f), view.eye) *
                                      glm::mat4_cast(view.orientation));
  glm::mat4 viewProjection =
      glm::perspective(view.yfov, view.aspect, view.znear, view.zfar) * viewMatrix;
  gl::beginDraws();
  for (gl::Program* p : {rigid_.get(), skinned_.get(), patch_.get()}) {
    if (!p) continue;
    p->use();
    gl::uniformMatrix4(p->uniform("u_ViewProjectionMatrix"), 1, glm::value_ptr(viewProjection),
                       stats_.uniformBytesPerFrame);
    gl::setFrameUniforms(*p, view, stats_.uniformBytesPerFrame);
  }
  uint64_t transformBytes = 0;
  for (const gl::DrawItem& d : draws_) {
    const gl::GpuPrimitive& g = geometry_.at(d);
    const Primitive& prim = scene_->meshes[size_t(d.mesh)].primitives[size_t(d.primitive)];
    if (patches_.has(d)) {  // Bezier patches: drawn rigidly by their node (never skinned)
      patch_->use();
      const glm::mat4& model = pose_.world[size_t(d.node)];
      glm::mat4 normal = matrix::normalMatrix(model);
      gl::uniformMatrix4(patch_->uniform("u_ModelMatrix"), 1, glm::value_ptr(model), transformBytes);
      gl::uniformMatrix4(patch_->uniform("u_NormalMatrix"), 1, glm::value_ptr(normal), transformBytes);
      textures_.bindMaterial(*patch_, prim.material, stats_.uniformBytesPerFrame);
      gl::setWinding(normal[3][3] < 0.0f);
      patches_.draw(d);
      ++stats_.draws;
      continue;
    }
    if (!g.indexCount) continue;
    // A mesh shared by a skinned and an unskinned node is drawn rigidly on the latter.
    GLuint palette = 0;
    for (size_t i = 0; g.skinned && i < pose_.palettes.size(); ++i)
      if (pose_.palettes[i].node == d.node) palette = palettes_[i];
    const gl::Program& program = palette ? *skinned_ : *rigid_;
    program.use();
    if (palette) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, palette);
    const glm::mat4& model = pose_.world[size_t(d.node)];
    glm::mat4 normal = matrix::normalMatrix(model);
    gl::uniformMatrix4(program.uniform("u_ModelMatrix"), 1, glm::value_ptr(model), transformBytes);
    gl::uniformMatrix4(program.uniform("u_NormalMatrix"), 1, glm::value_ptr(normal), transformBytes);
    textures_.bindMaterial(program, prim.material, stats_.uniformBytesPerFrame);
    gl::setWinding(normal[3][3] < 0.0f);  // sign(det(model)) as stored by normalMatrix()
    g.draw();
    ++stats_.draws;
  }
  gl::endDraws();
  stats_.uniformBytesPerFrame += transformBytes;
  stats_.floatsPerTransform = gl::floatsPer(transformBytes, uint64_t(stats_.draws));
}

void MatrixPipeline::release() {
  geometry_.release();
  patches_.release();
  patch_.reset();
  palettes_.release();
  textures_.release();
  rigid_.reset();
  skinned_.reset();
  scene_ = nullptr;
}

}  // namespace

std::unique_ptr<Pipeline> makeMatrixPipeline() { return std::make_unique<MatrixPipeline>(); }

}  // namespace mb
