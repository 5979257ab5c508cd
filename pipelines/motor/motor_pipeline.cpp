// The PGA motor pipeline ("Look, Ma, No Matrices!"). CPU: motors + one signed uniform scale
// per node, composed with the geometric product (motor_rig.h); animation blended as motors.
// GPU: shaders/motor.vs (9-float vertices: position, tangent rotor, uv), the shared
// shaders/forward.fs.
//
// Per draw the vertex shader gets the world motor (8 floats, u_World) and the scale applied to
// positions before it: one float on the paper's path, a vec3 on the documented fallback
// (variant MB_SCALE_FALLBACK) for a non-uniformly scaled leaf (its scale applied to the
// vertices first, the frame corrected as a normal matrix would) and for mirrored nodes (a
// negative scale: a point reflection, front-face winding flipped). Per joint: 8 floats.
// PipelineStats::floatsPerTransform counts the motor uploads only; the scale is in
// uniformBytesPerFrame.
#include "pipelines/motor/motor_pipeline.h"

#include <chrono>

#include "pipelines/gl/program.h"
#include "pipelines/gl/scene_textures.h"
#include "pipelines/gl/upload.h"
#include "pipelines/motor/motor_camera.h"
#include "pipelines/motor/motor_rig.h"
#include "pipelines/motor/motor_vertices.h"

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

// Program variants: [skinned][scale fallback].
struct Programs {
  std::unique_ptr<gl::Program> p[2][2];
};

// The scale a draw applies to its positions, and whether the paper's path can take it.
struct DrawScale {
  glm::vec3 value{1.0f};
  bool fallback = false;  // non-uniform or negative: motorScaledVertex
  bool mirrored = false;  // odd number of negative factors: winding flips
};

DrawScale drawScale(float uniform, const glm::vec3& residual) {
  DrawScale s;
  s.value = uniform * residual;
  s.fallback = residual != glm::vec3(1.0f) || !(uniform > 0.0f);
  s.mirrored = s.value.x * s.value.y * s.value.z < 0.0f;
  return s;
}

class MotorPipeline final : public Pipeline {
public:
  ~MotorPipeline() override { release(); }
  std::string name() const override { return "motor"; }
  Status prepare(const Scene& scene) override;
  void update(const AnimState& state) override;
  void render(const View& view) override;
  PipelineStats stats() const override { return stats_; }

private:
  GpuPrimitive upload(const Primitive& p, bool skinned);
  void uploadPalettes();
  void release();

  const Scene* scene_ = nullptr;
  Programs programs_;
  gl::SceneTextures textures_;
  std::vector<std::vector<GpuPrimitive>> meshes_;  // [mesh][primitive]
  std::vector<gl::DrawItem> draws_;
  motor::Rig rig_;
  std::vector<motor::ScaledMotor> world_;          // per node, last update()
  std::vector<motor::JointPalette> palettes_;
  std::vector<GLuint> paletteBuffers_;             // per palettes_ entry
  PipelineStats stats_;
};

GpuPrimitive MotorPipeline::upload(const Primitive& p, bool skinned) {
  GpuPrimitive g;
  glGenVertexArrays(1, &g.vao);
  glBindVertexArray(g.vao);
  motor::VertexStream stream = motor::interleaveVertices(p);
  stats_.zeroScalarFrames += stream.zeroScalarFrames;
  g.vertices = gl::createBuffer(GL_ARRAY_BUFFER, stream.data, stats_.vertexBytes);
  const GLsizei stride = motor::kFloatsPerVertex * sizeof(float);
  const GLint sizes[3] = {3, 4, 2};  // position, tangent rotor, uv0 (locations 0, 1, 2)
  size_t offset = 0;
  for (GLuint loc = 0; loc < 3; ++loc) {
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

Status MotorPipeline::prepare(const Scene& scene) {
  release();
  scene_ = &scene;
  stats_ = PipelineStats{};
  for (int skinned = 0; skinned < 2; ++skinned)
    for (int fallback = 0; fallback < 2; ++fallback) {
      gl::Defines defines;
      if (skinned) defines.push_back({"MB_SKINNED", ""});
      if (fallback) defines.push_back({"MB_SCALE_FALLBACK", ""});
      auto program = gl::Program::fromFiles("motor.vs", "forward.fs", defines);
      if (!program) return Status::fail(program.error());
      programs_.p[skinned][fallback] = program.take();
      if (skinned) programs_.p[skinned][fallback]->bindStorageBlock("MotorJoints", 0);
    }
  GLint maxBlock = 0;
  glGetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  for (const Skin& s : scene.skins)
    if (s.joints.size() * 8 * sizeof(float) > size_t(maxBlock))
      return Status::fail(scene.source + ": skin '" + s.name + "' has " +
                          std::to_string(s.joints.size()) + " joints; the joint palette exceeds "
                          "GL_MAX_SHADER_STORAGE_BLOCK_SIZE (" + std::to_string(maxBlock) + ")");

  Status tex = textures_.upload(scene, stats_.textureBytes);
  if (!tex) return tex;
  // Load-time conversion: transforms and inverse binds to motors, frames to rotors.
  auto t0 = Clock::now();
  rig_ = motor::buildRig(scene);
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
  if (err != GL_NO_ERROR) return Status::fail(scene.source + ": motor prepare: " + gl::errorName(err));
  return {};
}

void MotorPipeline::update(const AnimState& state) {
  if (!scene_) return;
  auto t0 = Clock::now();
  motor::RigCounts counts = rig_.bindCounts;
  world_ = motor::worldPose(*scene_, motor::localForState(*scene_, rig_, state, &counts));
  palettes_ = motor::jointPalettes(*scene_, rig_, world_);
  stats_.updateMs = msSince(t0);
  for (const motor::JointPalette& p : palettes_) counts.nonUniformSkins += !p.uniform;
  stats_.nonUniformScaleNodes = counts.nonUniformScaleNodes;
  stats_.negativeScaleNodes = counts.negativeScaleNodes;
  stats_.shearMatrixNodes = counts.shearMatrixNodes;
}

void MotorPipeline::uploadPalettes() {
  stats_.skinBytesPerFrame = 0;
  uint64_t joints = 0;
  while (paletteBuffers_.size() < palettes_.size()) {
    GLuint b = 0;
    glGenBuffers(1, &b);
    paletteBuffers_.push_back(b);
  }
  for (size_t i = 0; i < palettes_.size(); ++i) {
    const std::vector<float>& m = palettes_[i].motors;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, paletteBuffers_[i]);
    gl::bufferData(GL_SHADER_STORAGE_BUFFER, m.size() * sizeof(float),
                   m.empty() ? nullptr : m.data(), GL_STREAM_DRAW, stats_.skinBytesPerFrame);
    joints += scene_->skins[size_t(palettes_[i].skin)].joints.size();
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  stats_.floatsPerJoint = joints ? double(stats_.skinBytesPerFrame) / sizeof(float) / double(joints) : 0.0;
}

void MotorPipeline::render(const View& view) {
  if (!scene_) return;
  stats_.uniformBytesPerFrame = 0;
  stats_.draws = 0;
  uploadPalettes();
  const motor::CameraMotor camera = motor::cameraFromView(view);
  const float projection[4] = {camera.znear, camera.zfar, camera.yfov, camera.aspect};
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  for (auto& row : programs_.p)
    for (auto& p : row) {
      p->use();
      gl::uniform4fv(p->uniform("u_Camera"), 2, &camera.worldToView[0][0], stats_.uniformBytesPerFrame);
      gl::uniform4f(p->uniform("u_Projection"), projection, stats_.uniformBytesPerFrame);
      gl::setFrameUniforms(*p, view, stats_.uniformBytesPerFrame);
    }
  uint64_t transformBytes = 0;
  int transforms = 0;
  for (const gl::DrawItem& d : draws_) {
    const GpuPrimitive& g = meshes_[size_t(d.mesh)][size_t(d.primitive)];
    const Primitive& prim = scene_->meshes[size_t(d.mesh)].primitives[size_t(d.primitive)];
    if (!g.indexCount) continue;
    // A mesh shared by a skinned and an unskinned node is drawn rigidly on the latter.
    const motor::JointPalette* palette = nullptr;
    GLuint paletteBuffer = 0;
    for (size_t i = 0; g.skinned && i < palettes_.size(); ++i)
      if (palettes_[i].node == d.node) palette = &palettes_[i], paletteBuffer = paletteBuffers_[i];
    const motor::ScaledMotor& world = world_[size_t(d.node)];
    const DrawScale scale = palette ? drawScale(palette->scale, glm::vec3(1.0f))
                                    : drawScale(world.scale, world.residual);
    const gl::Program& program = *programs_.p[palette ? 1 : 0][scale.fallback ? 1 : 0];
    program.use();
    if (palette) {
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, paletteBuffer);
    } else {
      // glTF: a skinned mesh ignores its node's transform, so only rigid draws upload one.
      gl::uniform4fv(program.uniform("u_World"), 2, &world.motor[0][0], transformBytes);
      ++transforms;
    }
    if (scale.fallback)
      gl::uniform3f(program.uniform("u_Scale"), &scale.value[0], stats_.uniformBytesPerFrame);
    else
      gl::uniform1f(program.uniform("u_Scale"), scale.value.x, stats_.uniformBytesPerFrame);
    textures_.bindMaterial(program, prim.material, stats_.uniformBytesPerFrame);
    gl::setWinding(scale.mirrored);
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
  stats_.floatsPerTransform = transforms ? double(transformBytes) / sizeof(float) / transforms : 0.0;
}

void MotorPipeline::release() {
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
  for (auto& row : programs_.p)
    for (auto& p : row) p.reset();
  scene_ = nullptr;
}

}  // namespace

std::unique_ptr<Pipeline> makeMotorPipeline() { return std::make_unique<MotorPipeline>(); }

}  // namespace mb
