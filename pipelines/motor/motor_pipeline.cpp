// The PGA motor pipeline ("Look, Ma, No Matrices!", README.md): the CPU side in motor_rig.h,
// vertices and morph deltas in motor_geometry.h, shaders/motor.vs and the shared shaders/forward.fs.
//
// Per draw the vertex shader gets the world motor (8 floats, u_World) and the scale applied to
// positions before it: one float on the paper's path, a vec3 on the documented fallback
// (variant MB_SCALE_FALLBACK) for a non-uniformly scaled leaf (its scale applied to the
// vertices first, the frame corrected as a normal matrix would) and for mirrored nodes (a
// negative scale: a point reflection, front-face winding flipped). Per joint: 8 floats.
// PipelineStats::floatsPerTransform counts the motor uploads only; the scale is in
// uniformBytesPerFrame. Skinning: SkinSpace::WorldPalette by default (joint motors in world
// space, no node motor per vertex); Reference on request (configure()): the paper's form,
// joint motors relative to the mesh node and gp(u_World, blend) per vertex (MB_SKIN_REFERENCE).
// Instanced nodes, motor_c, motor_cf and morph targets: README.md. General nodes and skins whose
// palette is not one common positive scale: the exact fallback (linear_fallback.h, drawLinear).
#include "pipelines/motor/motor_pipeline.h"

#include "pipelines/gl/gltf_pipeline.h"
#include "pipelines/gl/upload.h"
#include "pipelines/motor/linear_fallback.h"
#include "pipelines/motor/motor_camera.h"
#include "pipelines/motor/motor_geometry.h"
#include "pipelines/motor/motor_rig.h"
#include "pipelines/scene/transform.h"

namespace mb {
namespace {

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

// The scale form of a draw's transform: the variant of its program (ProgramGrid).
enum ScaleForm { kUniform = 0, kPerAxis = 1, kLinear = 2 };  // MB_SCALE_FALLBACK, MB_LINEAR_FALLBACK

ScaleForm scaleForm(bool fallback) { return fallback ? kPerAxis : kUniform; }

// What every draw of one frame shares: the view, its camera motor and projection constants, the
// programs of its projection, and the transform uploads counted for PipelineStats.
struct MotorFrame : gl::TransformCounters {
  const View& view;
  Motor worldToView;
  MK::vec4 k;  // once per frame, not per vertex as the paper listing's project() does
  const gl::ProgramGrid& programs;
};

// A rigid or skinned draw's transform on the paper's path: the node's world motor (motor_c's
// rigid draws: the mesh's cube folded in) and the scale applied to the positions before it.
struct DrawTransform {
  motor::ScaledMotor world;
  DrawScale scale;
  bool dequantise = false;  // motor_c's skinned or morphing draws: u_Dequant per vertex instead
  bool transform = false;   // uploads u_World
};

class MotorPipeline final : public gl::GltfPipeline {
public:
  explicit MotorPipeline(const MotorVariant& variant) : variant_(variant) {}
  ~MotorPipeline() override { release(); }
  std::string name() const override { return variant_.name; }
  void configure(const PipelineOptions& options) override {
    referenceSkin_ = options.skinSpace == SkinSpace::Reference;
    morphMethod_ = options.morph;
  }
  SkinSpace skinSpace() const override {
    return referenceSkin_ ? SkinSpace::Reference : SkinSpace::WorldPalette;
  }

  Status prepare(const Scene& scene) override {
    release();
    if (Status begun = beginPrepare(scene, 8 * sizeof(float)); !begun) return begun;
    if (Status linked = linkPrograms(false); !linked) return linked;
    if (hasOrthographicCamera(scene))
      if (Status linked = linkPrograms(true); !linked) return linked;

    // Load-time conversion: transforms and inverse binds to motors, frames to rotors.
    auto t0 = gl::Clock::now();
    rig_ = motor::buildRig(scene);
    instanceMotors_.assign(scene.nodes.size(), {});
    // An instance is a leaf: its residual is exact. A general node streams none: drawNode() draws
    // each of its instances exactly.
    for (size_t n = 0; n < scene.nodes.size(); ++n)
      for (const TRS& t : scene.nodes[n].instances)
        if (!rig_.general[n]) instanceMotors_[n].push_back(motor::fromTRS(t, true));
    geometry_.upload(scene, variant_, morphMethod_, stats_);
    stats_.conversionMs = gl::msSince(t0);
    return endPrepare(scene);
  }

  void update(const AnimState& state) override {
    if (!scene_) return;
    auto t0 = gl::Clock::now();
    motor::RigCounts counts = rig_.bindCounts;
    PhaseClock clock(timePhases_ ? &stats_.updatePhases : nullptr);
    motor::poseScene(*scene_, rig_, state, referenceSkin_, pose_, &counts, clock);
    geometry_.morph.update(*scene_, state);
    stats_.updateMs = gl::msSince(t0);
    stats_.nonUniformScaleNodes = counts.nonUniformScaleNodes;
    stats_.negativeScaleNodes = counts.negativeScaleNodes;
    stats_.shearMatrixNodes = counts.shearMatrixNodes;
  }

  void render(const View& view) override {
    if (!scene_) return;
    beginFrame(pose_.palettes.size(), [this](size_t i) { return uploadPalette(i); });
    // Per instance: node world composed with the instance (composeInto), then its motor and the
    // scale a draw would get; key bit 0: scale fallback (vec3 scale), bit 1: mirrored winding.
    stats_.scaleFallbackInstances = 0;
    motor::ScaledMotor composed;
    streamInstances(instanceMotors_, [this](size_t n) -> const motor::ScaledMotor& { return pose_.world[n]; },
                    [&](const motor::ScaledMotor& world, const motor::ScaledMotor& local, std::vector<float>& out) {
                      motor::composeInto(world, local, composed);
                      const DrawScale scale = drawScale(composed.scale, composed.residual);
                      out.insert(out.end(), &composed.motor[0][0], &composed.motor[0][0] + 8);
                      out.insert(out.end(), &scale.value[0], &scale.value[0] + (scale.fallback ? 3 : 1));
                      stats_.scaleFallbackInstances += scale.fallback;
                      return (scale.fallback ? 1 : 0) | (scale.mirrored ? 2 : 0);
                    });
    const Motor worldToView = motor::worldToViewMotor(view);
    const MK::vec4 k = motor::projectionConstants(view);
    // An orthographic View draws with the MB_ORTHOGRAPHIC programs (a hand-made View on a scene
    // without an orthographic camera builds them here; prepare() did for the others).
    if (view.orthographic && !orthographic_.at[gl::kRigid][kUniform][0] && !linkPrograms(true)) return;
    MotorFrame frame{{}, view, worldToView, k, view.orthographic ? orthographic_ : programs_};
    drawList(*this, frame, geometry_.vertices, geometry_.morph, pose_.palettes);
  }

private:
  friend class gl::GltfPipeline;  // drawList() calls drawInstanceGroups() and drawNode()

  uint64_t uploadPalette(size_t i) {
    std::vector<float>& m = pose_.palettes[i].motors;
    // motor_cf: every joint motor in the first one's hemisphere (negation changes no pose), so
    // vertices led by different joints blend to world rotors of one sign.
    for (size_t j = 8; variant_.fragmentRotor && j + 8 <= m.size(); j += 8)
      if (m[0] * m[j] + m[1] * m[j + 1] + m[2] * m[j + 2] + m[3] * m[j + 3] < 0.0f)
        for (size_t k = j; k < j + 8; ++k) m[k] = -m[k];
    palettes_.upload(i, m.data(), m.size() * sizeof(float), stats_.skinBytesPerFrame);
    if (pose_.palettes[i].fallback) {
      const std::vector<float>& l = pose_.palettes[i].linear;
      linearBuffers_.upload(i, l.data(), l.size() * sizeof(float), stats_.skinBytesPerFrame);
    }
    return scene_->skins[size_t(pose_.palettes[i].skin)].joints.size();
  }

  // `p` made current for `m`, the frame's camera, projection and view uniforms set (see use()).
  const gl::Program& useProgram(const MotorFrame& f, const gl::Draw& m, gl::CachedProgram& p) {
    return use(p, m, geometry_.morph, [&](const gl::Program& program) {
      gl::uniform4fv(program.uniform("u_Camera"), 2, &f.worldToView[0][0], stats_.uniformBytesPerFrame);
      gl::uniform4f(program.uniform("u_ProjectionK"), &f.k[0], stats_.uniformBytesPerFrame);
      gl::setFrameUniforms(program, f.view, stats_.uniformBytesPerFrame);
    });
  }

  // One instanced draw per group (key bit 0: vec3 scale, bit 1: mirrored winding).
  void drawInstanceGroups(MotorFrame& f, const gl::Draw& m, const std::vector<gl::InstanceGroup>& groups) {
    for (const gl::InstanceGroup& group : groups) {
      const bool fallback = group.key & 1;
      const gl::Program& program = useProgram(f, m, f.programs.of(m, gl::kInstanced, scaleForm(fallback)));
      if (variant_.compact) setDequant(program, geometry_.cubes, m.d);
      bindMaterial(program, m.prim);
      drawGroup(m.g, group, {4, 4, fallback ? 3 : 1}, group.key & 2);
    }
  }

  // A draw by its node's transform or its skin's palette: the instances of a general node one
  // exact draw each (node world x instance, linear_fallback.h); on the exact fallback when the node
  // is general or the palette is not one common positive scale, else the paper's path.
  void drawNode(MotorFrame& f, const gl::Draw& m) {
    const std::vector<TRS>& instances = scene_->nodes[size_t(m.d.node)].instances;
    if (!m.patch && rig_.general[size_t(m.d.node)] && !instances.empty()) {
      for (const TRS& instance : instances) {
        const glm::mat4 world = pose_.exact.world[size_t(m.d.node)] * trsMatrix(instance);
        drawLinear(f, m, nullptr, &world);
      }
      return;
    }
    const motor::JointPalette* palette = m.palette < 0 ? nullptr : &pose_.palettes[size_t(m.palette)];
    const gl::DrawKind kind = palette ? gl::kSkinned : gl::kRigid;
    if (palette ? palette->fallback : (!m.patch && rig_.general[size_t(m.d.node)]))
      return drawLinear(f, m, palette);
    const DrawTransform t = drawTransform(m, palette);
    const gl::Program& program = useProgram(f, m, m.patch ? *f.programs.patch[t.scale.fallback]
                                                          : f.programs.of(m, kind, scaleForm(t.scale.fallback)));
    // A draw with a transform counts its scale with it, the others in the per-frame bytes.
    setDrawUniforms(f, m, t, program, t.scale.fallback, t.transform ? f.scaleBytes : stats_.uniformBytesPerFrame);
    if (t.transform) ++f.transforms;
    gl::setWinding(t.scale.mirrored);
    drawByRotorHemisphere(f, m, t, kind);
  }

  DrawTransform drawTransform(const gl::Draw& m, const motor::JointPalette* palette) const {
    DrawTransform t;
    const motor::ScaledMotor& node = pose_.world[size_t(m.d.node)];
    t.world = node;
    t.scale = palette ? drawScale(palette->scale, glm::vec3(1.0f)) : drawScale(node.scale, node.residual);
    t.dequantise = variant_.compact && (palette || m.morph);
    if (variant_.compact && !m.patch && !t.dequantise) {
      const compact::PositionCube& cube = geometry_.cubes[size_t(m.d.mesh)][size_t(m.d.primitive)];
      motor::composeInto({node.motor, 1.0f, glm::vec3(1.0f)}, motor::fromTRS(TRS{t.scale.value * cube.center}, true),
                         t.world);
      t.scale = drawScale(node.scale * cube.extent, node.residual);
    }
    // glTF: a skinned mesh ignores its node's transform, so with a world-space palette only
    // rigid draws upload one; the reference form composes it per vertex.
    t.transform = !palette || referenceSkin_;
    return t;
  }

  // The draw's uniforms and material (u_Scale a vec3 when perAxis, its bytes counted in `scaleBytes`).
  void setDrawUniforms(MotorFrame& f, const gl::Draw& m, const DrawTransform& t, const gl::Program& p,
                       bool perAxis, uint64_t& scaleBytes) {
    if (t.dequantise) setDequant(p, geometry_.cubes, m.d);
    if (t.transform) gl::uniform4fv(p.uniform("u_World"), 2, &t.world.motor[0][0], f.transformBytes);
    if (perAxis)
      gl::uniform3f(p.uniform("u_Scale"), &t.scale.value[0], scaleBytes);
    else
      gl::uniform1f(p.uniform("u_Scale"), t.scale.value.x, scaleBytes);
    bindMaterial(p, m.prim);
  }

  // motor_cf: triangles whose corner rotors cannot share a hemisphere (rotor_signs.h) are drawn
  // after the others by the per-vertex extraction of its scale-fallback program (motor_c's way).
  // Every other draw is one counted draw.
  void drawByRotorHemisphere(MotorFrame& f, const gl::Draw& m, const DrawTransform& t, gl::DrawKind kind) {
    const size_t interpolable = variant_.fragmentRotor && !m.patch && !t.scale.fallback
                                    ? geometry_.interpolable[size_t(m.d.mesh)][size_t(m.d.primitive)]
                                    : size_t(m.g.indexCount);
    if (interpolable >= size_t(m.g.indexCount)) return drawCounted(m);
    stats_.drawnVertices += m.g.drawRange(0, GLsizei(interpolable));
    // t.scale is uniform here: u_Scale (x, x, x).
    setDrawUniforms(f, m, t, useProgram(f, m, f.programs.of(m, kind, kPerAxis)), true, stats_.uniformBytesPerFrame);
    m.g.drawRange(GLsizei(interpolable), m.g.indexCount - GLsizei(interpolable));
    stats_.draws += 2;
  }

  // The defines of a program (linkGrid adds the MB_MORPH ones): morph method (b), MB_MORPH_ROTOR,
  // for the float and int16 rotors when the morph method is Rotor (the compact rotors morph by
  // method (a) always); orthographic: every program with MB_ORTHOGRAPHIC.
  gl::Defines defines(int kind, int form, bool morphing, bool orthographic) const {
    gl::Defines d;
    if (morphing && morphMethod_ == MorphMethod::Rotor && !variant_.compact) d.push_back({"MB_MORPH_ROTOR", ""});
    if (kind == gl::kSkinned) d.push_back({"MB_SKINNED", ""});
    if (kind == gl::kSkinned && referenceSkin_ && form != kLinear) d.push_back({"MB_SKIN_REFERENCE", ""});
    if (kind == gl::kInstanced) d.push_back({"MB_INSTANCED", ""});
    if (form == kPerAxis) d.push_back({"MB_SCALE_FALLBACK", ""});
    if (form == kLinear) d.push_back({"MB_LINEAR_FALLBACK", ""});
    if (variant_.compact) d.push_back({"MB_COMPACT", ""});
    if (variant_.fragmentRotor) d.push_back({"MB_SIGNED_ROTOR", ""});
    if (variant_.fragmentRotor && form == kUniform) d.push_back({"MB_FRAGMENT_ROTOR", ""});
    if (orthographic) d.push_back({"MB_ORTHOGRAPHIC", ""});
    return d;
  }

  // The programs of one projection (orthographic: the MB_ORTHOGRAPHIC ones), kept when all link: every
  // draw kind and scale form (instanced: no linear form), patch programs for scenes with Bezier patches.
  Status linkPrograms(bool orthographic) {
    gl::ProgramGrid grid;
    Status linked = linkGrid(grid, "motor.vs", [](int kind) { return kind == gl::kInstanced ? 2 : 3; },
                             [&](int kind, int form, bool morph) { return defines(kind, form, morph, orthographic); });
    for (int fallback = 0; linked && fallback < 2 && gl::hasPatches(*scene_); ++fallback) {
      gl::Defines d;
      if (fallback) d.push_back({"MB_SCALE_FALLBACK", ""});
      if (orthographic) d.push_back({"MB_ORTHOGRAPHIC", ""});
      grid.patch[fallback] = link(linked, "motor_patch.vs", d);
    }
    if (linked) (orthographic ? orthographic_ : programs_) = grid;
    return linked;
  }

  // One draw on the exact fallback: a rigid draw of a general node with its exact world's polar
  // factors, or a skinned draw with its palette's motors and linear parts (world space).
  void drawLinear(MotorFrame& f, const gl::Draw& m, const motor::JointPalette* palette,
                  const glm::mat4* world = nullptr) {
    const gl::DrawItem& d = m.d;
    const gl::Program& program = useProgram(f, m, f.programs.of(m, palette ? gl::kSkinned : gl::kRigid, kLinear));
    bool mirrored = false;
    if (palette) {  // (drawList() bound its motors)
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, linearBuffers_[size_t(m.palette)]);
      // Winding as the matrix pipeline's skinned draw: the sign of the mesh node's world.
      const motor::ScaledMotor& node = pose_.world[size_t(d.node)];
      mirrored = rig_.exact ? glm::determinant(glm::mat3(pose_.exact.world[size_t(d.node)])) < 0.0f
                            : drawScale(node.scale, node.residual).mirrored;
      ++stats_.skinFallbackDraws;
      stats_.skinFallbackJoints += int(palette->motors.size() / 8);
    } else {
      const motor::LinearTransform t = motor::linearFromAffine(world ? *world : pose_.exact.world[size_t(d.node)]);
      gl::uniform4fv(program.uniform("u_World"), 2, &t.motor[0][0], f.transformBytes);
      // The motor is the transform (floatsPerTransform); the linear parts count as its scale.
      gl::uniformMatrix3(program.uniform("u_Linear"), 1, &t.linear[0][0], f.scaleBytes);
      gl::uniformMatrix3(program.uniform("u_LinearNormal"), 1, &t.normalLinear[0][0], f.scaleBytes);
      mirrored = glm::determinant(t.linear) < 0.0f;
      ++stats_.linearFallbackDraws;
      ++f.transforms;
    }
    if (variant_.compact) setDequant(program, geometry_.cubes, d);
    bindMaterial(program, m.prim);
    gl::setWinding(mirrored);
    const uint64_t drawn = m.g.draw();
    stats_.drawnVertices += drawn;
    stats_.fallbackVertices += drawn;
    if (palette) stats_.skinFallbackVertices += drawn;
    ++stats_.draws;
  }

  void release() {
    geometry_.release();
    linearBuffers_.release();
    orthographic_ = {};
    releaseShared();
  }

  MotorVariant variant_;
  gl::ProgramGrid orthographic_;  // programs_ with MB_ORTHOGRAPHIC, for an orthographic View
  MorphMethod morphMethod_ = MorphMethod::PipelineDefault;
  gl::PaletteBuffers linearBuffers_;             // per palette: the fallback's 24 floats per joint
  std::vector<std::vector<motor::ScaledMotor>> instanceMotors_;  // per node: fromTRS(instance)
  bool referenceSkin_ = false;
  motor::MotorGeometry geometry_;                 // vertices, morph deltas, motor_c's cubes
  motor::Rig rig_;
  motor::PoseWork pose_;  // per-frame buffers; world and palettes of the last update()
};

}  // namespace

std::unique_ptr<Pipeline> makeMotorPipeline(const MotorVariant& variant) {
  return std::make_unique<MotorPipeline>(variant);
}

}  // namespace mb
