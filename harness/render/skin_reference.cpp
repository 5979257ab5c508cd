#include "harness/render/skin_reference.h"

#include <algorithm>
#include <cmath>
#include <utility>

#define GLM_ENABLE_EXPERIMENTAL  // glm::dualquat
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/dual_quaternion.hpp>

#include "pipelines/scene/camera_rule.h"
#include "pipelines/scene/morph.h"

namespace mb {
namespace {

// The rotation of the polar decomposition L = R S (Newton's iteration Q <- (Q + Q^-T) / 2, which
// converges to the orthogonal factor for any non-singular L); a reflection is left to S (R is
// proper). Singular L: R = identity (S = L), as the pipelines' fallback does.
glm::dmat3 polarRotation(const glm::dmat3& l) {
  if (std::abs(glm::determinant(l)) < 1e-30) return glm::dmat3(1.0);
  glm::dmat3 q = l;
  for (int i = 0; i < 60; ++i) {
    const glm::dmat3 next = 0.5 * (q + glm::transpose(glm::inverse(q)));
    double change = 0;
    for (int c = 0; c < 3; ++c) change = std::max(change, glm::length(next[c] - q[c]));
    q = next;
    if (change < 1e-15) break;
  }
  return glm::determinant(q) < 0 ? -q : q;
}

struct Joint {
  glm::dualquat rigid;  // unit: R and t
  glm::dmat3 s{1.0}, normalS{1.0};  // S, and S^-T (blended apart, as the pipelines do)
};

Joint splitJoint(const glm::mat4& j) {
  const glm::dmat3 l(j);
  const glm::dmat3 r = polarRotation(l);
  Joint out;
  out.s = glm::transpose(r) * l;
  out.normalS = std::abs(glm::determinant(out.s)) < 1e-30 ? glm::dmat3(1.0) : glm::transpose(glm::inverse(out.s));
  const glm::quat rotation = glm::quat_cast(glm::mat3(r));
  out.rigid = glm::dualquat(rotation, glm::vec3(j[3]));  // GLM: rotate, then translate
  return out;
}

// The primitive's morph targets added with `weights` into its base streams (morph.h, glTF 2.0
// 3.7.2.2), and the targets removed.
void applyMorph(Primitive& p, const std::vector<float>& weights) {
  if (p.targets.empty()) return;
  for (size_t i = 0; i < p.positions.size(); ++i) {
    p.positions[i] = morphedPosition(p, i, weights);
    if (i < p.normals.size()) p.normals[i] = morphedNormal(p, i, weights);
    if (i < p.tangents.size()) p.tangents[i] = morphedTangent(p, i, weights);
  }
  p.targets.clear();
}

}  // namespace

SkinnedVertex dualQuaternionSkin(const std::vector<glm::mat4>& jointMatrices, const glm::u16vec4& joints,
                                 const glm::vec4& weights, const glm::vec3& position, const glm::vec3& normal,
                                 const glm::vec3& tangent) {
  glm::dualquat sum(glm::quat(0, 0, 0, 0), glm::quat(0, 0, 0, 0));
  glm::dmat3 s(0.0), normalS(0.0);
  for (int k = 0; k < 4; ++k) {
    if (weights[k] == 0.0f || joints[k] >= jointMatrices.size()) continue;
    const Joint j = splitJoint(jointMatrices[joints[k]]);
    float w = weights[k];
    if (k > 0 && glm::dot(sum.real, j.rigid.real) <= 0.0f) w = -w;  // the hemisphere rule
    sum.real = sum.real + j.rigid.real * w;
    sum.dual = sum.dual + j.rigid.dual * w;
    s += double(weights[k]) * j.s;
    normalS += double(weights[k]) * j.normalS;
  }
  const glm::dualquat unit = glm::normalize(sum);  // both parts over |real|
  const glm::dmat3 r(glm::mat3_cast(unit.real));
  const glm::quat t = unit.dual * glm::conjugate(unit.real) * 2.0f;  // the translation's vector part
  SkinnedVertex v;
  v.position = glm::vec3(r * (s * glm::dvec3(position)) + glm::dvec3(t.x, t.y, t.z));
  v.normal = glm::vec3(glm::normalize(r * (normalS * glm::dvec3(normal))));
  v.tangent = glm::vec3(glm::normalize(r * (s * glm::dvec3(tangent))));
  return v;
}

PreSkinnedScene::PreSkinnedScene(Scene& scene, const AnimState& anim) : scene_(scene) {
  const std::vector<glm::mat4> world = worldMatrices(scene, samplePose(scene, anim));
  const std::vector<std::vector<float>> morphWeights = sampleMorphWeights(scene, anim);
  std::vector<int> users(scene.meshes.size(), 0);
  for (int n : nodesInDrawOrder(scene))
    if (scene.nodes[size_t(n)].mesh >= 0 && size_t(scene.nodes[size_t(n)].mesh) < scene.meshes.size())
      ++users[size_t(scene.nodes[size_t(n)].mesh)];
  for (int n : nodesInDrawOrder(scene)) {
    Node& node = scene.nodes[size_t(n)];
    if (node.skin < 0 || size_t(node.skin) >= scene.skins.size() || node.mesh < 0 || size_t(node.mesh) >= scene.meshes.size())
      continue;
    Mesh& mesh = scene.meshes[size_t(node.mesh)];
    if (users[size_t(node.mesh)] > 1) {
      why_ = "a skinned mesh drawn by more than one node";
      return;
    }
    const glm::dmat4 nodeWorld(world[size_t(n)]);
    if (std::abs(glm::determinant(glm::dmat3(nodeWorld))) < 1e-30) {
      why_ = "a skinned node with a singular world transform";
      return;
    }
    const Skin& skin = scene.skins[size_t(node.skin)];
    std::vector<glm::mat4> palette;
    for (size_t k = 0; k < skin.joints.size(); ++k) {
      const int joint = skin.joints[k];
      const glm::mat4 jointWorld = joint >= 0 && size_t(joint) < world.size() ? world[size_t(joint)] : glm::mat4(1.0f);
      palette.push_back(jointWorld * (k < skin.inverseBind.size() ? skin.inverseBind[k] : glm::mat4(1.0f)));
    }
    // Into the node's frame: the matrix pipeline draws the primitive at node world * local.
    const glm::dmat4 toNode = glm::inverse(nodeWorld);
    const glm::dmat3 normalToNode = glm::transpose(glm::dmat3(nodeWorld));
    meshes_.emplace_back(node.mesh, mesh);
    const std::vector<float>& morph = n < int(morphWeights.size()) ? morphWeights[size_t(n)] : std::vector<float>{};
    for (Primitive& p : mesh.primitives) {
      if (p.joints.size() != p.positions.size() || p.weights.size() != p.positions.size()) continue;
      applyMorph(p, morph);  // glTF order: morph, then skin
      for (size_t i = 0; i < p.positions.size(); ++i) {
        const glm::vec3 n = i < p.normals.size() ? p.normals[i] : glm::vec3(0, 0, 1);
        const glm::vec3 t = i < p.tangents.size() ? glm::vec3(p.tangents[i]) : glm::vec3(1, 0, 0);
        const SkinnedVertex v = dualQuaternionSkin(palette, p.joints[i], p.weights[i], p.positions[i], n, t);
        p.positions[i] = glm::vec3(toNode * glm::dvec4(glm::dvec3(v.position), 1.0));
        if (i < p.normals.size()) p.normals[i] = glm::vec3(glm::normalize(normalToNode * glm::dvec3(v.normal)));
        if (i < p.tangents.size())
          p.tangents[i] = glm::vec4(glm::vec3(glm::normalize(glm::dmat3(toNode) * glm::dvec3(v.tangent))), p.tangents[i].w);
      }
      p.joints.clear();
      p.weights.clear();
    }
    skins_.emplace_back(n, node.skin);
    node.skin = -1;
  }
}

PreSkinnedScene::~PreSkinnedScene() {
  for (auto& [n, skin] : skins_) scene_.nodes[size_t(n)].skin = skin;
  for (auto& [m, mesh] : meshes_) scene_.meshes[size_t(m)] = std::move(mesh);
}

}  // namespace mb
