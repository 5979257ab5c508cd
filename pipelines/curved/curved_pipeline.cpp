#include "pipelines/curved/curved_pipeline.h"

#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include "pipelines/curved/curved_motor.h"
#include "pipelines/gl/gpu_geometry.h"
#include "pipelines/gl/program.h"
#include "pipelines/gl/upload.h"
#include "pipelines/scene/curved_space.h"

namespace mb {
namespace {

// The space's perspective (column-major; README.md). S3: clip = (f x / aspect, f y, -0.01 w, -z),
// near atan(0.01), far pi - atan(0.01). H3: Klein's (x, y, z) / w, near tanh(0.01), far 1.
glm::mat4 projection(int kappa, float yfov, float aspect) {
  const float f = 1.0f / std::tan(0.5f * yfov);
  glm::mat4 p(0.0f);
  p[0][0] = f / aspect;
  p[1][1] = f;
  p[2][3] = -1.0f;
  if (kappa > 0) {
    p[3][2] = -0.01f;
  } else {
    const float n = std::tanh(0.01f), fa = 1.0f;
    p[2][2] = (fa + n) / (n - fa);
    p[3][2] = 2.0f * fa * n / (n - fa);
  }
  return p;
}

class CurvedPipeline final : public Pipeline {
public:
  CurvedPipeline(Space space, bool motor) : space_(space), kappa_(kappaOf(space)), motor_(motor) {}
  ~CurvedPipeline() override { release(); }
  std::string name() const override { return curvedEntry(space_, motor_).name; }
  Status prepare(const Scene& scene) override;
  void update(const AnimState& state) override;
  void render(const View& view) override;
  PipelineStats stats() const override { return stats_; }

private:
  void release();

  Space space_;
  int kappa_;
  bool motor_;
  const Scene* scene_ = nullptr;
  std::unique_ptr<gl::Program> program_;
  GLuint vao_ = 0, vertexBuffer_ = 0, instanceBuffer_ = 0;
  // Posed by update(): the camera and the lights in view space, each side by its own math.
  glm::mat4 view_{1.0f};
  std::array<float, 8> viewMotor_{};
  std::array<glm::vec4, 3> lights_{};
  PipelineStats stats_;
};

Status CurvedPipeline::prepare(const Scene& scene) {
  release();
  stats_ = PipelineStats{};
  const CurvedScene& c = scene.curved;
  if (c.space != space_)
    return Status::fail(scene.source + ": pipeline " + name() + " draws " + spaceName(space_) +
                        " scenes (s3_tiling / h3_tiling), this one is " +
                        (c.space == Space::Euclidean ? std::string("a Euclidean glTF scene")
                                                     : std::string(spaceName(c.space))));
  if (c.positions.empty() || c.positions.size() != c.normals.size() || c.instances.empty() ||
      c.lights.size() != 3)
    return Status::fail(scene.source + ": curved scene without triangles, instances or 3 lights");
  const ShaderVariant variant = curvedEntry(space_, motor_).variants[0];  // the program it declares
  auto program = gl::Program::fromFiles(variant.stage, variant.fragment, variant.defines);
  if (!program) return Status::fail(program.error());
  program_ = program.take();

  // Per vertex: position and normal, 8 floats, the same on both sides.
  std::vector<float> vertices;
  for (size_t v = 0; v < c.positions.size(); ++v)
    for (const glm::vec4& x : {c.positions[v], c.normals[v]}) vertices.insert(vertices.end(), {x.x, x.y, x.z, x.w});
  // Per instance: the matrix as is, or the motor converted from it (timed: conversion).
  auto t0 = gl::Clock::now();
  std::vector<float> instances;
  instances.reserve(c.instances.size() * (motor_ ? 8 : 16));
  for (const glm::dmat4& m : c.instances) {
    if (!motor_) {
      instances.insert(instances.end(), glm::value_ptr(m), glm::value_ptr(m) + 16);  // double -> float
      continue;
    }
    auto mo = curved::motorOfMatrix(kappa_, m);
    if (!mo) return Status::fail(scene.source + ": instance " + std::to_string(&m - c.instances.data()) + ": " + mo.error());
    for (double x : curved::shaderMotor(kappa_, *mo)) instances.push_back(float(x));
  }
  stats_.conversionMs = motor_ ? gl::msSince(t0) : 0.0;

  glGenVertexArrays(1, &vao_);
  glBindVertexArray(vao_);
  vertexBuffer_ = gl::createBuffer(GL_ARRAY_BUFFER, vertices, stats_.vertexBytes);
  gl::pointAttributes({{0}, {1}});  // vec4s: position, normal
  // Instances are the curved scenes' transforms; their uploads are the floats per transform.
  instanceBuffer_ = gl::createBuffer(GL_ARRAY_BUFFER, instances, stats_.extraVertexBytes);
  std::vector<gl::PackedAttribute> columns{{2}, {3}, {4}, {5}};  // vec4s: the matrix's, the motor's 2
  columns.resize(motor_ ? 2 : 4);
  gl::pointAttributes(columns, true);
  glBindVertexArray(0);
  stats_.vertices = c.positions.size();
  stats_.floatsPerVertex = gl::floatsPer(stats_.vertexBytes, stats_.vertices);
  stats_.floatsPerTransform = gl::floatsPer(stats_.extraVertexBytes, c.instances.size());
  scene_ = &scene;
  update(AnimState{});
  GLenum err = glGetError();
  if (err != GL_NO_ERROR) return Status::fail(scene.source + ": " + name() + " prepare: " + gl::errorName(err));
  return {};
}

void CurvedPipeline::update(const AnimState& state) {
  if (!scene_) return;
  auto t0 = gl::Clock::now();
  const CurvedScene& c = scene_->curved;
  const double t = state.anim >= 0 ? double(state.time) : 0.0;
  if (motor_) {
    const curved::Motor8 v = curved::viewMotor(c, t);
    const curved::Motor8 up = curved::shaderMotor(kappa_, v);
    for (int k = 0; k < 8; ++k) viewMotor_[size_t(k)] = float(up[size_t(k)]);
    for (int l = 0; l < 3; ++l) lights_[size_t(l)] = glm::vec4(curved::sandwich(kappa_, v, glm::dvec4(c.lights[size_t(l)])));
  } else {
    glm::dmat4 v(1.0);  // (E1 ... En)^-1 = En^-1 ... E1^-1
    for (const CurvedMove& mv : c.camera)
      v = elementaryMatrix(kappa_, mv.i, mv.j, -(mv.angle0 + mv.rate * t)) * v;
    view_ = glm::mat4(v);
    for (int l = 0; l < 3; ++l) lights_[size_t(l)] = glm::vec4(v * glm::dvec4(c.lights[size_t(l)]));
  }
  stats_.updateMs = gl::msSince(t0);
}

void CurvedPipeline::render(const View& view) {
  if (!scene_) return;
  stats_.uniformBytesPerFrame = 0;
  const glm::mat4 proj = projection(kappa_, scene_->curved.yfov, view.aspect);
  gl::beginDraws();
  glDisable(GL_CULL_FACE);
  program_->use();
  uint64_t& u = stats_.uniformBytesPerFrame;
  gl::uniformMatrix4(program_->uniform("u_Projection"), 1, glm::value_ptr(proj), u);
  if (motor_)
    gl::uniform4fv(program_->uniform("u_Camera"), 2, viewMotor_.data(), u);
  else
    gl::uniformMatrix4(program_->uniform("u_View"), 1, glm::value_ptr(view_), u);
  gl::uniform4fv(program_->uniform("u_Lights"), 3, glm::value_ptr(lights_[0]), u);
  gl::uniform1f(program_->uniform("u_LightStrength"), scene_->curved.lightStrength, u);
  glBindVertexArray(vao_);
  glDrawArraysInstanced(GL_TRIANGLES, 0, GLsizei(stats_.vertices), GLsizei(scene_->curved.instances.size()));
  stats_.draws = 1;
  gl::endDraws();
}

void CurvedPipeline::release() {
  if (vertexBuffer_) glDeleteBuffers(1, &vertexBuffer_);
  if (instanceBuffer_) glDeleteBuffers(1, &instanceBuffer_);
  if (vao_) glDeleteVertexArrays(1, &vao_);
  vertexBuffer_ = instanceBuffer_ = vao_ = 0;
  program_.reset();
  scene_ = nullptr;
}

template <Space S, bool Motor>
std::unique_ptr<Pipeline> makeCurved() {
  return std::make_unique<CurvedPipeline>(S, Motor);
}

}  // namespace

// One program each: the instance vertex of its space (MB_KAPPA = the curvature) and curved.fs.
PipelineEntry curvedEntry(Space space, bool motor) {
  static const std::string kMain = "main() adds the projection u_Projection * position (mat4 * vec4: 16 mul, 12 add), "
                                   "the same on both sides of a space";
  const bool s3 = space == Space::Spherical;
  const auto make = motor ? (s3 ? makeCurved<Space::Spherical, true> : makeCurved<Space::Hyperbolic, true>)
                          : (s3 ? makeCurved<Space::Spherical, false> : makeCurved<Space::Hyperbolic, false>);
  return {.name = std::string(s3 ? "s3_" : "h3_") + (motor ? "motor" : "matrix"), .make = make, .space = space,
          .skin = SkinMethod::None, .family = motor ? PipelineFamily::Motor : PipelineFamily::Matrix,
          .variants = {{.stage = motor ? "curved_motor.vs" : "curved_matrix.vs", .defines = {{"MB_KAPPA", s3 ? "1" : "-1"}},
                        .draws = s3 ? "S3 instance" : "H3 instance",
                        .kernels = {motor ? "curvedMotorVertex" : "curvedMatrixVertex"}, .note = kMain,
                        .fragment = "curved.fs"}}};
}

}  // namespace mb
