// The matrix/TBN pipeline: the Khronos glTF-Sample-Viewer baseline the paper compares with.
// CPU: GLM matrices and quaternions for the hierarchy, animation and skin palettes.
// GPU: shaders/matrix.vs (+ SKINNED variant) and the shared shaders/forward.fs.
#include "pipelines/matrix/matrix_pipeline.h"

#include <chrono>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "pipelines/gl/program.h"
#include "pipelines/gl/scene_textures.h"
#include "pipelines/gl/upload.h"
#include "pipelines/matrix/matrix_pose.h"
#include "pipelines/matrix/matrix_vertices.h"

namespace mb {
namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

struct GpuPrimitive {
  GLuint vao = 0, vertices = 0, indices = 0;
  GLsizei indexCount = 0;
  bool skinned = false;
  gl::ExtraStreams extra;
};

class MatrixPipeline final : public Pipeline {
public:
  ~MatrixPipeline() override { release(); }
  std::string name() const override { return "matrix"; }
  Status prepare(const Scene& scene) override;
  void update(const AnimState& state) override;
  void render(const View& view) override;
  PipelineStats stats() const override { return stats_; }

private:
  GpuPrimitive upload(const Primitive& p, bool skinned);
  void uploadPalettes();
  void release();

  const Scene* scene_ = nullptr;
  std::unique_ptr<gl::Program> rigid_, skinned_;
  gl::SceneTextures textures_;
  std::vector<std::vector<GpuPrimitive>> meshes_;  // [mesh][primitive]
  std::vector<gl::DrawItem> draws_;
  matrix::Pose pose_;
  std::vector<GLuint> paletteBuffers_;  // per pose_.palettes entry (same order every update)
  PipelineStats stats_;
};

GpuPrimitive MatrixPipeline::upload(const Primitive& p, bool skinned) {
  GpuPrimitive g;
  glGenVertexArrays(1, &g.vao);
  glBindVertexArray(g.vao);
  g.vertices = gl::createBuffer(GL_ARRAY_BUFFER, matrix::interleaveVertices(p), stats_.vertexBytes);
  const GLsizei stride = matrix::kFloatsPerVertex * sizeof(float);
  const GLint sizes[4] = {3, 3, 4, 2};  // position, normal, tangent, uv0
  size_t offset = 0;
  for (GLuint loc = 0; loc < 4; ++loc) {
    glEnableVertexAttribArray(loc);
    glVertexAttribPointer(loc, sizes[loc], GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(offset * sizeof(float)));
    offset += size_t(sizes[loc]);
  }
  g.extra.upload(p, stats_.extraVertexBytes, stats_.skinVertexBytes);
  g.skinned = skinned && g.extra.joints != 0;
  g.indices = gl::createBuffer(GL_ELEMENT_ARRAY_BUFFER, p.indices, stats_.indexBytes);
  g.indexCount = GLsizei(p.indices.size());
  glBindVertexArray(0);
  stats_.vertices += p.positions.size();
  return g;
}

Status MatrixPipeline::prepare(const Scene& scene) {
  release();
  scene_ = &scene;
  stats_ = PipelineStats{};
  auto rigid = gl::Program::fromFiles("matrix.vs", "forward.fs");
  if (!rigid) return Status::fail(rigid.error());
  auto skinned = gl::Program::fromFiles("matrix.vs", "forward.fs", {{"SKINNED", ""}});
  if (!skinned) return Status::fail(skinned.error());
  rigid_ = rigid.take();
  skinned_ = skinned.take();
  skinned_->bindStorageBlock("JointPalette", 0);

  GLint maxBlock = 0;
  glGetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  for (const Skin& s : scene.skins)
    if (s.joints.size() * 2 * sizeof(glm::mat4) > size_t(maxBlock))
      return Status::fail(scene.source + ": skin '" + s.name + "' has " +
                          std::to_string(s.joints.size()) + " joints; the joint palette exceeds "
                          "GL_MAX_SHADER_STORAGE_BLOCK_SIZE (" + std::to_string(maxBlock) + ")");

  Status tex = textures_.upload(scene, stats_.textureBytes);
  if (!tex) return tex;
  auto t0 = Clock::now();
  // Which meshes are drawn skinned: any node instancing them with a skin.
  std::vector<bool> skinnedMesh(scene.meshes.size(), false);
  for (const Node& n : scene.nodes)
    if (n.mesh >= 0 && size_t(n.mesh) < scene.meshes.size() && n.skin >= 0)
      skinnedMesh[size_t(n.mesh)] = true;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    meshes_.emplace_back();
    for (const Primitive& p : scene.meshes[m].primitives)
      meshes_.back().push_back(upload(p, skinnedMesh[m]));
  }
  stats_.conversionMs = msSince(t0);
  draws_ = gl::buildDrawList(scene);
  if (stats_.vertices)
    stats_.floatsPerVertex = double(stats_.vertexBytes) / sizeof(float) / double(stats_.vertices);
  update(AnimState{});
  GLenum err = glGetError();
  if (err != GL_NO_ERROR) return Status::fail(scene.source + ": matrix prepare: " + gl::errorName(err));
  return {};
}

void MatrixPipeline::update(const AnimState& state) {
  if (!scene_) return;
  auto t0 = Clock::now();
  pose_ = matrix::poseScene(*scene_, state);
  stats_.updateMs = msSince(t0);
}

void MatrixPipeline::uploadPalettes() {
  stats_.skinBytesPerFrame = 0;
  uint64_t joints = 0;
  while (paletteBuffers_.size() < pose_.palettes.size()) {
    GLuint b = 0;
    glGenBuffers(1, &b);
    paletteBuffers_.push_back(b);
  }
  for (size_t i = 0; i < pose_.palettes.size(); ++i) {
    const auto& m = pose_.palettes[i].matrices;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, paletteBuffers_[i]);
    gl::bufferData(GL_SHADER_STORAGE_BUFFER, m.size() * sizeof(glm::mat4),
                   m.empty() ? nullptr : glm::value_ptr(m[0]), GL_STREAM_DRAW,
                   stats_.skinBytesPerFrame);
    joints += m.size() / 2;
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  stats_.floatsPerJoint = joints ? double(stats_.skinBytesPerFrame) / sizeof(float) / double(joints) : 0.0;
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
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  uint64_t transformBytes = 0;
  for (gl::Program* p : {rigid_.get(), skinned_.get()}) {
    p->use();
    gl::uniformMatrix4(p->uniform("u_ViewProjectionMatrix"), 1, glm::value_ptr(viewProjection),
                       stats_.uniformBytesPerFrame);
    gl::setFrameUniforms(*p, view, stats_.uniformBytesPerFrame);
  }
  for (const gl::DrawItem& d : draws_) {
    const GpuPrimitive& g = meshes_[size_t(d.mesh)][size_t(d.primitive)];
    const Primitive& prim = scene_->meshes[size_t(d.mesh)].primitives[size_t(d.primitive)];
    if (!g.indexCount) continue;
    // A mesh shared by a skinned and an unskinned node is drawn rigidly on the latter.
    GLuint palette = 0;
    for (size_t i = 0; g.skinned && i < pose_.palettes.size(); ++i)
      if (pose_.palettes[i].node == d.node) palette = paletteBuffers_[i];
    const gl::Program& program = palette ? *skinned_ : *rigid_;
    program.use();
    if (palette) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, palette);
    const glm::mat4& model = pose_.world[size_t(d.node)];
    glm::mat4 normal = matrix::normalMatrix(model);
    gl::uniformMatrix4(program.uniform("u_ModelMatrix"), 1, glm::value_ptr(model), transformBytes);
    gl::uniformMatrix4(program.uniform("u_NormalMatrix"), 1, glm::value_ptr(normal), transformBytes);
    textures_.bindMaterial(program, prim.material, stats_.uniformBytesPerFrame);
    gl::setWinding(normal[3][3] < 0.0f);
    glBindVertexArray(g.vao);
    g.extra.setDefaults();
    glDrawElements(GL_TRIANGLES, g.indexCount, GL_UNSIGNED_INT, nullptr);
    ++stats_.draws;
  }
  glBindVertexArray(0);
  gl::setWinding(false);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  stats_.uniformBytesPerFrame += transformBytes;
  stats_.floatsPerTransform =
      stats_.draws ? double(transformBytes) / sizeof(float) / stats_.draws : 0.0;
}

void MatrixPipeline::release() {
  for (auto& mesh : meshes_)
    for (GpuPrimitive& g : mesh) {
      g.extra.release();
      glDeleteBuffers(1, &g.vertices);
      glDeleteBuffers(1, &g.indices);
      glDeleteVertexArrays(1, &g.vao);
    }
  meshes_.clear();
  if (!paletteBuffers_.empty())
    glDeleteBuffers(GLsizei(paletteBuffers_.size()), paletteBuffers_.data());
  paletteBuffers_.clear();
  textures_.release();
  rigid_.reset();
  skinned_.reset();
  scene_ = nullptr;
}

}  // namespace

std::unique_ptr<Pipeline> makeMatrixPipeline() { return std::make_unique<MatrixPipeline>(); }

}  // namespace mb
