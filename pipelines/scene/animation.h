// Animation sampling shared by every pipeline: local TRS of every node for an animation state.
#pragma once
#include <vector>

#include "pipelines/scene/scene.h"

namespace mb {

// Which animation(s) to pose. anim < 0: rest pose. anim2 < 0: no blend.
struct AnimState {
  int anim = -1;
  float time = 0.0f;
  int anim2 = -1;
  float time2 = 0.0f;
  float blend = 0.0f;  // 0: only anim, 1: only anim2
};

// Local TRS of every node (scene.nodes.size() entries) for animation `anim` at `time`
// (clamped to the animation's range). Unanimated nodes keep their rest TRS; anim < 0 or out
// of range gives the rest pose.
std::vector<TRS> sampleAnimation(const Scene& scene, int anim, float time);
// The same into `pose` (resized; its storage is reused from call to call).
void sampleAnimation(const Scene& scene, int anim, float time, std::vector<TRS>& pose);

// Per-node blend: translation and scale lerp, rotation shortest-arc slerp; w = weight of b.
std::vector<TRS> blendPoses(const std::vector<TRS>& a, const std::vector<TRS>& b, float w);
// The same into `out` (which may be `a`; nodes past b's end keep a's TRS).
void blendPoses(const std::vector<TRS>& a, const std::vector<TRS>& b, float w, std::vector<TRS>& out);

// Per animation: the nodes its channels drive (those sampleAnimation changes: a valid node and
// at least one key), each once, ascending. Every other node keeps its rest TRS exactly, so a
// pipeline may keep its rest conversion for those when it poses one animation unblended.
std::vector<std::vector<int>> animatedNodes(const Scene& scene);

// Morph weights of every node (scene.nodes.size() entries) for animation `anim` at `time`:
// the animation's weights channel where one drives the node, else the node's weights, else its
// mesh's (glTF 2.0 3.7.2.2); empty for a node whose mesh has no morph targets. LINEAR weights
// interpolate linearly, STEP hold, CUBICSPLINE follow the same Hermite spline as evaluate().
// `weights` is resized; its storage is reused from call to call.
void sampleMorphWeights(const Scene& scene, int anim, float time, std::vector<std::vector<float>>& weights);
// The same for a state; with anim2, linearly blended by state.blend.
std::vector<std::vector<float>> sampleMorphWeights(const Scene& scene, const AnimState& state);

// sampleAnimation + blendPoses as the state asks.
std::vector<TRS> samplePose(const Scene& scene, const AnimState& state);

}  // namespace mb
