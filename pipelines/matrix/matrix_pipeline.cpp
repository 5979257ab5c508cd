// The matrix/TBN pipeline: the Khronos glTF-Sample-Viewer baseline the paper compares with
// (README.md: its CPU side, vertex shader and instanced nodes). Per draw it uploads u_ModelMatrix
// and u_NormalMatrix (2 x mat4 = 32 floats, skinned draws included, as the Sample Viewer does);
// per joint a joint matrix and a joint normal matrix. Vertex format per primitive as the Sample
// Viewer's (pipelines/gl/frame_vertices.h): a tangent only where the primitive has one
// (authored, or generated for a normal map); the MB_NO_TANGENT shader variant draws the others.
// Skinning: SkinSpace::Reference by default (the Sample Viewer's); WorldPalette on request
// (configure()). Morph targets: pipelines/README.md.
#include "pipelines/matrix/matrix_pipeline.h"

#include <glm/gtc/type_ptr.hpp>

#include "pipelines/gl/upload.h"
#include "pipelines/matrix/matrix_family.h"
#include "pipelines/matrix/matrix_pose.h"

namespace mb {
namespace {

class MatrixPipeline final : public gl::MatrixFamily<MatrixPipeline> {
public:
  std::string name() const override { return "matrix"; }
  void configure(const PipelineOptions& options) override {
    worldPalette_ = options.skinSpace == SkinSpace::WorldPalette;
  }
  SkinSpace skinSpace() const override {
    return worldPalette_ ? SkinSpace::WorldPalette : SkinSpace::Reference;
  }

private:
  friend class gl::MatrixFamily<MatrixPipeline>;
  static constexpr const char* kVertexShader = "matrix.vs";
  static constexpr const char* kPatchShader = "matrix_patch.vs";
  static constexpr size_t kBytesPerJoint = 2 * sizeof(glm::mat4);  // joint and joint normal matrix
  static inline const gl::InstanceLayout kInstanceLayout{4, 4, 4, 4, 4, 4, 4, 4};  // model, normal

  int frames() const { return 2; }
  gl::Defines defines(int kind, int noTangent) const {
    gl::Defines d;
    if (kind == gl::kSkinned) d.push_back({"SKINNED", ""});
    if (kind == gl::kSkinned && worldPalette_) d.push_back({"MB_WORLD_PALETTE", ""});
    if (kind == gl::kInstanced) d.push_back({"MB_INSTANCED", ""});
    if (noTangent) d.push_back({"MB_NO_TANGENT", ""});
    return d;
  }
  Status convert(const Scene& scene) {
    geometry_.upload(scene, gl::floatFrameFormat, stats_);  // variant 1: no tangent
    return {};
  }
  void preparePose(const Scene& scene) { prepareMatrixPose(scene, work_); }
  void pose(const AnimState& state, PhaseClock& clock) {
    matrix::poseScene(*scene_, state, worldPalette_, work_, pose_, clock);
  }

  const std::vector<matrix::SkinPalette>& palettes() const { return pose_.palettes; }
  uint64_t uploadPalette(size_t i) {
    const auto& m = pose_.palettes[i].matrices;
    palettes_.upload(i, m.empty() ? nullptr : glm::value_ptr(m[0]), m.size() * sizeof(glm::mat4),
                     stats_.skinBytesPerFrame);
    return m.size() / 2;
  }

  // Per instance: its model matrix and normal matrix (sign(det) in [3][3]).
  glm::mat4 instanceWorld(size_t node) const { return pose_.world[node]; }
  int writeInstance(const glm::mat4& model, std::vector<float>& out) const {
    const glm::mat4 normal = matrix::normalMatrix(model);
    out.insert(out.end(), glm::value_ptr(model), glm::value_ptr(model) + 16);
    out.insert(out.end(), glm::value_ptr(normal), glm::value_ptr(normal) + 16);
    return normal[3][3] < 0.0f ? 1 : 0;
  }

  // u_ModelMatrix and u_NormalMatrix on every draw, skinned ones included.
  bool drawUniforms(const gl::Program& program, const gl::Draw& m, gl::TransformCounters& c) const {
    const glm::mat4& model = pose_.world[size_t(m.d.node)];
    const glm::mat4& normal = pose_.normals[size_t(m.d.node)];
    gl::uniformMatrix4(program.uniform("u_ModelMatrix"), 1, glm::value_ptr(model), c.transformBytes);
    gl::uniformMatrix4(program.uniform("u_NormalMatrix"), 1, glm::value_ptr(normal), c.transformBytes);
    ++c.transforms;
    return normal[3][3] < 0.0f;  // sign(det(model)) as stored by normalMatrix()
  }

  bool worldPalette_ = false;
  MatrixPoseWork work_;  // per-frame buffers and the hierarchy order
  matrix::Pose pose_;
};

}  // namespace

std::unique_ptr<Pipeline> makeMatrixPipeline() { return std::make_unique<MatrixPipeline>(); }

}  // namespace mb
