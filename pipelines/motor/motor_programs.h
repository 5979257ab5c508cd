// The motor.vs / motor_patch.vs program variants a scene needs, built once by the motor
// pipelines' prepare() (motor_pipeline.cpp says what each variant draws). One table indexed by
// how the draw reaches world space (rigid, skinned, instanced), the scale form its transform
// takes (the paper's uniform scale, the per-axis scale fallback, the exact linear fallback) and
// whether it morphs (MB_MORPH, issue 37); programs a scene cannot use are not built. A second
// table with MB_ORTHOGRAPHIC draws orthographic Views (motor_pipeline.cpp builds it when needed).
#pragma once
#include <memory>

#include "pipelines/gl/program.h"
#include "pipelines/motor/motor_pipeline.h"

namespace mb::motor {

enum class DrawKind { Rigid = 0, Skinned = 1, Instanced = 2 };
enum class ScaleForm { Uniform = 0, PerAxis = 1, Linear = 2 };  // MB_SCALE_FALLBACK, MB_LINEAR_FALLBACK

class MotorPrograms {
public:
  // Builds the variants `scene` needs for `variant`: instanced ones only for scenes with
  // instances, MB_MORPH ones only for scenes with morph targets (method (b), MB_MORPH_ROTOR,
  // for the float and int16 rotors when `morph` is MorphMethod::Rotor; the compact rotors morph
  // by method (a) always), patch programs only for scenes with Bezier patches.
  // orthographic: every program with MB_ORTHOGRAPHIC (an orthographic View's projection).
  Status build(const Scene& scene, const MotorVariant& variant, bool referenceSkin, MorphMethod morph,
               bool orthographic = false);
  bool built() const { return built_; }
  // The program of a draw; built by build() (the caller asks only for what the scene has).
  gl::Program& draw(DrawKind kind, ScaleForm form, bool morph) const;
  gl::Program& patch(ScaleForm form) const;  // motor_patch.vs, Uniform or PerAxis
  void release();

private:
  std::unique_ptr<gl::Program> table_[3][3][2];  // [kind][form][morph]
  std::unique_ptr<gl::Program> patch_[2];        // [per-axis scale]
  bool built_ = false;
};

}  // namespace mb::motor
