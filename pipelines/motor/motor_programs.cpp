#include "pipelines/motor/motor_programs.h"

#include "pipelines/gl/instance_stream.h"
#include "pipelines/gl/morph_buffers.h"
#include "pipelines/gl/patch_geometry.h"

namespace mb::motor {

Status MotorPrograms::build(const Scene& scene, const MotorVariant& variant, bool referenceSkin,
                            MorphMethod morph, bool orthographic) {
  release();
  const bool instanced = gl::hasInstances(scene), morphs = gl::maxMorphTargets(scene) > 0;
  for (int kind = 0; kind < 3; ++kind)
    for (int form = 0; form < 3; ++form)
      for (int morphing = 0; morphing < 2; ++morphing) {
        if ((kind == 2 && (!instanced || form == 2)) || (morphing && !morphs)) continue;
        gl::Defines defines;
        if (morphing) defines = gl::morphDefines(scene);
        if (morphing && morph == MorphMethod::Rotor && !variant.compact) defines.push_back({"MB_MORPH_ROTOR", ""});
        if (kind == 1) defines.push_back({"MB_SKINNED", ""});
        if (kind == 1 && referenceSkin && form < 2) defines.push_back({"MB_SKIN_REFERENCE", ""});
        if (kind == 2) defines.push_back({"MB_INSTANCED", ""});
        if (form == 1) defines.push_back({"MB_SCALE_FALLBACK", ""});
        if (form == 2) defines.push_back({"MB_LINEAR_FALLBACK", ""});
        if (variant.compact) defines.push_back({"MB_COMPACT", ""});
        if (variant.fragmentRotor) defines.push_back({"MB_SIGNED_ROTOR", ""});
        if (variant.fragmentRotor && form == 0) defines.push_back({"MB_FRAGMENT_ROTOR", ""});
        if (orthographic) defines.push_back({"MB_ORTHOGRAPHIC", ""});
        auto program = gl::Program::fromFiles("motor.vs", "forward.fs", defines);
        if (!program) return Status::fail(program.error());
        std::unique_ptr<gl::Program>& p = table_[kind][form][morphing];
        p = program.take();
        if (kind == 1) p->bindStorageBlock("MotorJoints", 0);
        if (kind == 1 && form == 2) p->bindStorageBlock("MotorJointLinear", 1);
        if (morphing) p->bindStorageBlock("MorphDeltas", gl::kMorphBinding);
      }
  for (int fallback = 0; fallback < 2 && gl::hasPatches(scene); ++fallback) {
    gl::Defines defines;
    if (fallback) defines.push_back({"MB_SCALE_FALLBACK", ""});
    if (orthographic) defines.push_back({"MB_ORTHOGRAPHIC", ""});
    auto program = gl::Program::fromFiles("motor_patch.vs", "forward.fs", defines);
    if (!program) return Status::fail(program.error());
    patch_[fallback] = program.take();
  }
  built_ = true;
  return {};
}

gl::Program& MotorPrograms::draw(DrawKind kind, ScaleForm form, bool morph) const {
  return *table_[int(kind)][int(form)][morph ? 1 : 0];
}

gl::Program& MotorPrograms::patch(ScaleForm form) const { return *patch_[form == ScaleForm::Uniform ? 0 : 1]; }

void MotorPrograms::release() {
  for (auto& kind : table_)
    for (auto& form : kind)
      for (auto& p : form) p.reset();
  for (auto& p : patch_) p.reset();
  built_ = false;
}

}  // namespace mb::motor
