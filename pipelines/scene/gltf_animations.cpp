// Animations: validated T/R/S channels. Morph-weight channels are recorded as unsupported.
#include <tiny_gltf.h>

#include <cmath>

#include "pipelines/scene/accessors.h"
#include "pipelines/scene/gltf_convert.h"

namespace mb {

Status convertAnimations(const tinygltf::Model& m, Scene& scene) {
  for (size_t a = 0; a < m.animations.size(); ++a) {
    const auto& src = m.animations[a];
    Animation anim;
    anim.name = src.name;
    for (size_t c = 0; c < src.channels.size(); ++c) {
      const auto& ch = src.channels[c];
      std::string where = "animation " + std::to_string(a) + " channel " + std::to_string(c);
      if (ch.target_path == "weights") {
        scene.unsupported.push_back(where + ": morph target weights not animated");
        continue;
      }
      if (ch.target_node < 0) {
        scene.unsupported.push_back(where + ": no target node (extension target ignored)");
        continue;
      }
      if (size_t(ch.target_node) >= scene.nodes.size())
        return Status::fail(where + ": target node " + std::to_string(ch.target_node) + " does not exist");
      if (ch.sampler < 0 || size_t(ch.sampler) >= src.samplers.size())
        return Status::fail(where + ": sampler " + std::to_string(ch.sampler) + " does not exist");
      Channel out;
      out.node = ch.target_node;
      int comps = 3;
      if (ch.target_path == "translation") out.path = AnimPath::Translation;
      else if (ch.target_path == "rotation") { out.path = AnimPath::Rotation; comps = 4; }
      else if (ch.target_path == "scale") out.path = AnimPath::Scale;
      else return Status::fail(where + ": unknown path '" + ch.target_path + "'");
      const auto& smp = src.samplers[size_t(ch.sampler)];
      if (smp.interpolation == "STEP") out.interpolation = Interpolation::Step;
      else if (smp.interpolation == "CUBICSPLINE") out.interpolation = Interpolation::CubicSpline;
      else if (smp.interpolation.empty() || smp.interpolation == "LINEAR") out.interpolation = Interpolation::Linear;
      else return Status::fail(where + ": unknown interpolation '" + smp.interpolation + "'");

      auto in = readAccessorFloat(m, smp.input, "animation input");
      if (!in) return Status::fail(in.error());
      auto val = readAccessorFloat(m, smp.output, "animation output");
      if (!val) return Status::fail(val.error());
      if (in->components != 1) return Status::fail(where + ": input is not SCALAR");
      if (val->components != comps)
        return Status::fail(where + ": " + ch.target_path + " output needs " + std::to_string(comps) + " components");
      size_t perKey = out.interpolation == Interpolation::CubicSpline ? 3 : 1;
      if (in->count == 0) {
        scene.unsupported.push_back(where + ": no keyframes (channel ignored)");
        continue;
      }
      if (val->count != in->count * perKey)
        return Status::fail(where + ": " + std::to_string(in->count) + " keyframe times but " +
                            std::to_string(val->count) + " output values");
      for (size_t k = 0; k < in->count; ++k) {
        float t = in->values[k];
        if (!std::isfinite(t) || (k > 0 && t < in->values[k - 1]))
          return Status::fail(where + ": keyframe times are not finite and non-decreasing");
      }
      for (float v : val->values)
        if (!std::isfinite(v)) return Status::fail(where + ": non-finite keyframe value");
      out.times = std::move(in->values);
      out.values = std::move(val->values);
      if (out.path == AnimPath::Rotation) {  // unit keys (tangents of CUBICSPLINE stay as authored)
        for (size_t k = 0; k < out.times.size(); ++k) {
          float* q = &out.values[(k * perKey + (perKey == 3 ? 1 : 0)) * 4];
          float len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
          if (len > 0.0f) for (int i = 0; i < 4; ++i) q[i] /= len;
          else q[3] = 1.0f;
        }
      }
      anim.duration = std::max(anim.duration, out.times.back());
      anim.channels.push_back(std::move(out));
    }
    scene.animations.push_back(std::move(anim));
  }
  return {};
}

}  // namespace mb
