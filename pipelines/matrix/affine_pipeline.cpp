// The affine pipelines' GL side. Per draw: u_ModelMatrix (mat4x3, 12 floats) and u_NormalMatrix
// (mat3, 9 floats) for rigid draws (PipelineStats::floatsPerTransform = 21), u_Mirror
// (sign(det), in uniformBytesPerFrame) for every draw; skinned draws read the joint palette (12
// floats per joint, stored as rows) and upload no transform, as glTF ignores a skinned node's
// own transform. Bezier patch primitives are drawn rigidly by their node with affine_patch.vs
// (the same per-draw uniforms). Instanced nodes and matrix_c's quantisation cube: README.md;
// morph targets: pipelines/README.md.
#include "pipelines/matrix/affine_pipeline.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "pipelines/matrix/matrix_c_vertices.h"
#include "pipelines/matrix/qtangent_vertices.h"
#include "pipelines/compact/compact_encoding.h"
#include "pipelines/gl/upload.h"
#include "pipelines/matrix/matrix_family.h"

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

class AffinePipeline final : public gl::MatrixFamily<AffinePipeline> {
public:
  AffinePipeline(std::string name, FrameFormat format, std::unique_ptr<Poser> poser)
      : name_(std::move(name)), format_(format), poser_(std::move(poser)) {}
  std::string name() const override { return name_; }

private:
  friend class gl::MatrixFamily<AffinePipeline>;
  static constexpr const char* kVertexShader = "affine.vs";
  static constexpr const char* kPatchShader = "affine_patch.vs";
  static constexpr size_t kBytesPerJoint = 12 * sizeof(float);  // mat4x3
  static inline const gl::InstanceLayout kInstanceLayout{3, 3, 3, 3, 3, 3, 3, 1};  // model, normal, mirror

  // Float frames: tangent or not; qtangent and matrix_c: one frame variant.
  int frames() const { return format_ == FrameFormat::Float ? 2 : 1; }
  gl::Defines defines(int kind, int noTangent) const {
    gl::Defines d;
    if (format_ == FrameFormat::QTangent) d.push_back({"MB_QTANGENT", ""});
    if (format_ == FrameFormat::Compact) d.push_back({"MB_COMPACT", ""});
    if (kind == gl::kSkinned) d.push_back({"MB_SKINNED", ""});
    if (kind == gl::kInstanced) d.push_back({"MB_INSTANCED", ""});
    if (noTangent) d.push_back({"MB_NO_TANGENT", ""});
    return d;
  }
  Status convert(const Scene& scene);
  void pose(const AnimState& state, PhaseClock& clock) {
    poser_->pose(*scene_, state, pose_, stats_, clock);
    drawnNormalMatrices(*scene_, pose_);
  }
  void posed(PhaseClock& clock) { clock.lap(&UpdatePhases::hierarchyMs); }

  const std::vector<Palette>& palettes() const { return pose_.palettes; }
  uint64_t uploadPalette(size_t i) {
    rows_.clear();
    for (const glm::mat4x3& m : pose_.palettes[i].joints) appendRows(rows_, m);
    palettes_.upload(i, rows_.data(), rows_.size() * sizeof(float), stats_.skinBytesPerFrame);
    return pose_.palettes[i].joints.size();
  }

  // Per instance: its model (mat4x3), normal matrix and mirror.
  glm::mat4 instanceWorld(size_t node) const { return glm::mat4(pose_.world[node]); }
  int writeInstance(const glm::mat4& world, std::vector<float>& out) const {
    const glm::mat4x3 model(world);
    const glm::mat3 normal = normalMatrix(model);
    const float sign = mirror(model);
    out.insert(out.end(), glm::value_ptr(model), glm::value_ptr(model) + 12);
    out.insert(out.end(), glm::value_ptr(normal), glm::value_ptr(normal) + 9);
    out.push_back(sign);
    return sign < 0.0f ? 1 : 0;
  }

  void instancedUniforms(const gl::Program& program, const gl::DrawItem& d) {
    if (format_ == FrameFormat::Compact) setDequant(program, cubes_, d);
  }

  // Rigid draws: u_ModelMatrix and u_NormalMatrix (matrix_c: the mesh's cube folded into the
  // model unless the draw morphs); skinned draws: the palette (drawList() bound it). u_Mirror on
  // every draw, counted with the transform (its per-draw float, as the motor's u_Scale) on rigid ones.
  bool drawUniforms(const gl::Program& program, const gl::Draw& m, gl::TransformCounters& c) {
    const gl::DrawItem& d = m.d;
    const bool compact = format_ == FrameFormat::Compact, skinned = m.palette >= 0;
    glm::mat4x3 model = pose_.world[size_t(d.node)];
    const float sign = pose_.mirrors[size_t(d.node)];
    if (compact && !m.patch && !skinned && !m.morph) {
      const compact::PositionCube& cube = cubes_[size_t(d.mesh)][size_t(d.primitive)];
      model = model * glm::scale(glm::translate(glm::mat4(1.0f), cube.center), glm::vec3(cube.extent));
    }
    if (compact && (skinned || m.morph)) setDequant(program, cubes_, d);
    if (!skinned) {
      const glm::mat3& normal = pose_.normals[size_t(d.node)];
      gl::uniformMatrix4x3(program.uniform("u_ModelMatrix"), 1, glm::value_ptr(model), c.transformBytes);
      gl::uniformMatrix3(program.uniform("u_NormalMatrix"), 1, glm::value_ptr(normal), c.transformBytes);
      ++c.transforms;
    }
    gl::uniform1f(program.uniform("u_Mirror"), sign, skinned ? stats_.uniformBytesPerFrame : c.scaleBytes);
    return sign < 0.0f;
  }

  std::string name_;
  FrameFormat format_;
  std::unique_ptr<Poser> poser_;
  std::vector<std::vector<compact::PositionCube>> cubes_;  // matrix_c: per mesh, per primitive
  Pose pose_;
  std::vector<float> rows_;  // a palette's rows, reused
};

Status AffinePipeline::convert(const Scene& scene) {
  if (Status posed = poser_->prepare(scene); !posed) return posed;
  if (format_ == FrameFormat::QTangent) {
    geometry_.uploadPacked(scene, interleaveQTangent, gl::snormFrameAttributes(), stats_);
  } else if (format_ == FrameFormat::Compact) {
    cubes_ = compact::primitiveCubes(scene);
    geometry_.uploadPacked(scene, interleaveCompact, compact::attributes(), stats_);
  } else {
    geometry_.upload(scene, gl::floatFrameFormat, stats_);  // as matrix: tangent only where needed
  }
  return {};
}

}  // namespace

std::unique_ptr<Pipeline> makePipeline(const std::string& name, FrameFormat format,
                                       std::unique_ptr<Poser> poser) {
  return std::make_unique<AffinePipeline>(name, format, poser ? std::move(poser) : std::make_unique<MatrixPoser>());
}

}  // namespace mb::affine
