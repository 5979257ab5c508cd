// The motor family's skinning method as an independent CPU reference for corpus-check's skinned
// rule: motor skinning blends joint motors (dual quaternion linear blending, not the matrices'
// linear blend), so its images differ from matrix's by design and are judged against this
// reference instead: the same pose, skinned on the CPU with GLM dual quaternions, drawn by the
// matrix pipeline. README: Corpus check.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/result.h"
#include "pipelines/scene/animation.h"
#include "pipelines/scene/scene.h"

namespace mb {

// One vertex skinned by the motor family's method, from the joint matrices J = world(joint) *
// inverse bind. Each J is split into its polar factors, J = [R S | t] (R a rotation, S = R^T L
// symmetric; for a similarity S = s I); the rigid parts (R, t) are blended as GLM unit dual
// quaternions with the reference's hemisphere rule (each joint after the first negated when its
// real part's dot with the running sum is <= 0) and normalised, the S blended linearly; then
// x -> R_b S_b x + t_b, normals by R_b S_b^-T, tangents by R_b S_b (both normalised).
struct SkinnedVertex {
  glm::vec3 position, normal, tangent;
};
SkinnedVertex dualQuaternionSkin(const std::vector<glm::mat4>& jointMatrices, const glm::u16vec4& joints,
                                 const glm::vec4& weights, const glm::vec3& position, const glm::vec3& normal,
                                 const glm::vec3& tangent);

// While it lives, every skinned node of `scene` drawn at `anim` has its primitives replaced by
// their (morphed) dualQuaternionSkin result (moved into the node's frame by its inverse world, so that the
// node's own transform puts them back) and its skin removed; the destructor restores the scene.
// available() is false, with the reason, when the reference cannot stand for the method here: a
// mesh skinned by one node and drawn by another, a singular node world. Morph targets are
// applied first, at the frame's weights (glTF order: morph, then skin), and removed.
class PreSkinnedScene {
public:
  PreSkinnedScene(Scene& scene, const AnimState& anim);
  ~PreSkinnedScene();
  PreSkinnedScene(const PreSkinnedScene&) = delete;
  PreSkinnedScene& operator=(const PreSkinnedScene&) = delete;
  bool available() const { return why_.empty(); }
  const std::string& why() const { return why_; }

private:
  Scene& scene_;
  std::string why_;
  std::vector<std::pair<int, int>> skins_;  // node, its skin: restored
  std::vector<std::pair<int, Mesh>> meshes_;  // mesh index, its original: restored
};

}  // namespace mb
