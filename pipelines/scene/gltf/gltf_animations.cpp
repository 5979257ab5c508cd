// Animations: validated T/R/S channels and morph weights channels (one value per target of the
// node's mesh per key, glTF 2.0 3.11).
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>

#include "pipelines/scene/gltf/accessors.h"
#include "pipelines/scene/gltf/gltf_convert.h"

namespace mb {
namespace {

// glTF requires strictly increasing input times. Equal times are drawable (a jump: the sampler
// never interpolates across a zero interval); decreasing ones are sorted, each key moving with
// its `floatsPerKey` values (stable, so equal times keep their order). Returns 1 when the times
// did not strictly increase, else 0.
int sortKeys(Channel& c, size_t floatsPerKey) {
  bool increasing = true, ordered = true;
  for (size_t k = 1; k < c.times.size(); ++k) {
    increasing &= c.times[k] > c.times[k - 1];
    ordered &= c.times[k] >= c.times[k - 1];
  }
  if (ordered) return increasing ? 0 : 1;
  std::vector<size_t> order(c.times.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return c.times[a] < c.times[b]; });
  std::vector<float> times(order.size()), values(c.values.size());
  for (size_t k = 0; k < order.size(); ++k) {
    times[k] = c.times[order[k]];
    std::copy_n(c.values.begin() + long(order[k] * floatsPerKey), floatsPerKey, values.begin() + long(k * floatsPerKey));
  }
  c.times = std::move(times);
  c.values = std::move(values);
  return 1;
}

}  // namespace

Status convertAnimations(const tinygltf::Model& m, Scene& scene) {
  for (size_t a = 0; a < m.animations.size(); ++a) {
    const auto& src = m.animations[a];
    Animation anim;
    anim.name = src.name;
    for (size_t c = 0; c < src.channels.size(); ++c) {
      const auto& ch = src.channels[c];
      std::string where = "animation " + std::to_string(a) + " channel " + std::to_string(c);
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
      else if (ch.target_path == "weights") {
        const Node& node = scene.nodes[size_t(ch.target_node)];
        comps = node.mesh >= 0 ? int(morphTargetCount(scene.meshes[size_t(node.mesh)])) : 0;
        if (comps == 0) {
          scene.unsupported.push_back(where + ": weights of a node without morph targets (channel ignored)");
          continue;
        }
        out.path = AnimPath::Weights;
        out.weightCount = comps;
      }
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
      if (out.path == AnimPath::Weights) {  // SCALAR outputs, `comps` per key value
        if (val->components != 1) return Status::fail(where + ": weights output is not SCALAR");
        val->components = comps;
        val->count /= size_t(comps);  // checked against the keys below (a remainder fails there)
        if (val->values.size() != val->count * size_t(comps))
          return Status::fail(where + ": " + std::to_string(val->values.size()) + " weights are not a multiple of " +
                              std::to_string(comps) + " targets");
      }
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
      for (float t : in->values)
        if (!std::isfinite(t)) return Status::fail(where + ": keyframe time is not finite");
      for (float v : val->values)
        if (!std::isfinite(v)) return Status::fail(where + ": non-finite keyframe value");
      out.times = std::move(in->values);
      out.values = std::move(val->values);
      scene.stats.keyframeTimesNotIncreasing += sortKeys(out, perKey * size_t(comps));
      if (out.path == AnimPath::Rotation) {  // unit keys (tangents of CUBICSPLINE stay as authored)
        for (size_t k = 0; k < out.times.size(); ++k) {
          float* q = &out.values[(k * perKey + (perKey == 3 ? 1 : 0)) * 4];
          float len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
          scene.stats.rotationKeysNormalised += !(std::fabs(len - 1.0f) <= kUnitQuaternionTolerance);
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
