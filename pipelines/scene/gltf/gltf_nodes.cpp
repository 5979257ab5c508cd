// Nodes (validated hierarchy), skins, cameras and the default scene's roots.
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "pipelines/scene/gltf/accessors.h"
#include "pipelines/scene/gltf/gltf_convert.h"
#include "pipelines/scene/transform.h"

namespace mb {
namespace {

bool inRange(int i, size_t n) { return i >= 0 && size_t(i) < n; }

// Authored doubles must be finite as floats: 1e300 would become Inf (converting it is also
// undefined behaviour), and a NaN/Inf transform or camera silently breaks the image.
bool floatRange(const std::vector<double>& v) {
  for (double d : v)
    if (!(std::fabs(d) <= double(std::numeric_limits<float>::max()))) return false;
  return true;
}

Status convertNode(const tinygltf::Model& m, size_t i, Node* out) {
  const auto& src = m.nodes[i];
  std::string where = "node " + std::to_string(i);
  out->name = src.name;
  out->mesh = src.mesh;
  out->skin = src.skin;
  out->camera = src.camera;
  if ((src.mesh != -1 && !inRange(src.mesh, m.meshes.size())) ||
      (src.skin != -1 && !inRange(src.skin, m.skins.size())) ||
      (src.camera != -1 && !inRange(src.camera, m.cameras.size())))
    return Status::fail(where + ": mesh, skin or camera index out of range");
  if (!floatRange(src.matrix) || !floatRange(src.translation) || !floatRange(src.rotation) || !floatRange(src.scale))
    return Status::fail(where + ": matrix/translation/rotation/scale value is not finite (or out of float range)");
  if (!floatRange(src.weights)) return Status::fail(where + ": a morph weight is not finite (or out of float range)");
  out->weights.assign(src.weights.begin(), src.weights.end());
  if (src.matrix.size() == 16) {
    out->hasMatrix = true;
    for (int k = 0; k < 16; ++k) out->matrix[k / 4][k % 4] = float(src.matrix[size_t(k)]);
    out->matrixHasShear = !decomposeMatrix(out->matrix, &out->local);
    return {};
  }
  if (!src.matrix.empty() || (!src.translation.empty() && src.translation.size() != 3) ||
      (!src.rotation.empty() && src.rotation.size() != 4) || (!src.scale.empty() && src.scale.size() != 3))
    return Status::fail(where + ": matrix/translation/rotation/scale has the wrong length");
  if (!src.translation.empty()) out->local.translation = glm::vec3(src.translation[0], src.translation[1], src.translation[2]);
  if (!src.scale.empty()) out->local.scale = glm::vec3(src.scale[0], src.scale[1], src.scale[2]);
  if (!src.rotation.empty()) {
    glm::quat q(float(src.rotation[3]), float(src.rotation[0]), float(src.rotation[1]), float(src.rotation[2]));
    float len = glm::length(q);
    out->local.rotation = len > 0.0f && std::isfinite(len) ? q / len : glm::quat(1, 0, 0, 0);
  }
  return {};
}

// glTF 2.0 camera constraints (perspective: znear > 0, zfar > znear when given, 0 < yfov;
// orthographic: znear >= 0, zfar > znear) made to hold; Camera (scene.h) says how. Returns 1
// when something was repaired.
int repairCamera(Camera& c) {
  bool repaired = false;
  if (c.perspective && !(c.znear > 0.0f)) c.znear = 0.01f, repaired = true;
  if (!c.perspective && c.znear < 0.0f) c.znear = 0.0f, repaired = true;
  if (c.perspective && !(c.yfov > 0.0f && c.yfov < 3.14159265f)) c.yfov = 0.8f, repaired = true;
  const bool farGiven = !c.perspective || c.zfar != 0.0f;  // perspective zfar 0: absent (infinite)
  if (farGiven && !(c.zfar > c.znear)) c.zfar = 0.0f, repaired = true;
  return repaired ? 1 : 0;
}

// glTF 2.0 wants a scene's nodes to be roots; exporters list children too (Blender and Kenney
// files list the child of an unlisted "tmpParent"). Drawn as three.js draws them: a listed node
// whose parent chain holds no listed node becomes a root of its own, detached from its parent,
// so its subtree is drawn at the node's local transform (the parent's chain is not applied;
// three.js adds it to the scene, which re-parents it). One under a listed ancestor is already
// drawn in that ancestor's subtree and stays there, drawn once. Both are counted.
void addSceneRoots(const std::vector<int>& listed, Scene& scene) {
  const size_t n = scene.nodes.size();
  std::vector<uint8_t> isListed(n, 0);
  for (int r : listed) isListed[size_t(r)] = 1;
  // underListed[i]: node i or one of its ancestors is listed (0 unknown, 1 no, 2 yes); filled
  // walking up once per node, so deep chains cost linear time (the hierarchy has no cycle).
  std::vector<uint8_t> underListed(n, 0);
  std::vector<int> walk;
  auto coveredAbove = [&](int r) {
    walk.clear();
    int p = scene.nodes[size_t(r)].parent;
    while (p != -1 && underListed[size_t(p)] == 0 && !isListed[size_t(p)]) {
      walk.push_back(p);
      p = scene.nodes[size_t(p)].parent;
    }
    const uint8_t answer = p != -1 && (isListed[size_t(p)] || underListed[size_t(p)] == 2) ? 2 : 1;
    for (int w : walk) underListed[size_t(w)] = answer;
    return answer == 2;
  };
  std::vector<int> detach;  // decided on the file's hierarchy, before any node is detached
  std::vector<uint8_t> counted(n, 0);
  for (int r : listed) {
    if (scene.nodes[size_t(r)].parent == -1 || counted[size_t(r)]) continue;
    counted[size_t(r)] = 1;
    ++scene.stats.rootsWithParent;
    if (!coveredAbove(r)) detach.push_back(r);
  }
  for (int r : detach) {
    Node& node = scene.nodes[size_t(r)];
    std::vector<int>& siblings = scene.nodes[size_t(node.parent)].children;
    siblings.erase(std::find(siblings.begin(), siblings.end(), r));
    node.parent = -1;
  }
  for (int r : listed)  // in the scene's order
    if (scene.nodes[size_t(r)].parent == -1) scene.roots.push_back(r);
}

// Every node: its transform and indices (convertNode), its instances, its extensions named.
Status convertAllNodes(const tinygltf::Model& m, Scene& scene) {
  scene.nodes.resize(m.nodes.size());
  for (size_t i = 0; i < m.nodes.size(); ++i) {
    if (Status s = convertNode(m, i, &scene.nodes[i]); !s) return s;
    if (Status s = convertInstancing(m, i, scene); !s) return s;
    for (const auto& [ext, v] : m.nodes[i].extensions)
      if (ext != kInstancingExtension)
        scene.unsupported.push_back("node " + std::to_string(i) + ": extension " + ext + " ignored");
  }
  return {};
}

// Parent and children links from the nodes' children lists: every child exists and has one parent.
Status linkChildren(const tinygltf::Model& m, Scene& scene) {
  const size_t n = m.nodes.size();
  for (size_t i = 0; i < n; ++i) {
    for (int c : m.nodes[i].children) {
      if (!inRange(c, n)) return Status::fail("node " + std::to_string(i) + ": child " + std::to_string(c) + " does not exist");
      if (scene.nodes[size_t(c)].parent != -1 || size_t(c) == i)
        return Status::fail("node " + std::to_string(c) + " has more than one parent");
      scene.nodes[size_t(c)].parent = int(i);
      scene.nodes[i].children.push_back(c);
    }
  }
  return {};
}

// Cycle check, linear in the node count: walk up from each node until a node already known
// to reach a root (2) or one on the current walk (1: a cycle).
Status checkNoCycle(const Scene& scene) {
  const size_t n = scene.nodes.size();
  std::vector<uint8_t> state(n, 0);
  std::vector<int> walk;
  for (size_t i = 0; i < n; ++i) {
    walk.clear();
    int p = int(i);
    while (p != -1 && state[size_t(p)] == 0) {
      state[size_t(p)] = 1;
      walk.push_back(p);
      p = scene.nodes[size_t(p)].parent;
    }
    if (p != -1 && state[size_t(p)] == 1)
      return Status::fail("node hierarchy has a cycle through node " + std::to_string(p));
    for (int w : walk) state[size_t(w)] = 2;
  }
  return {};
}

// Skin `s`: its skeleton and joints (existing nodes) and one finite inverse bind per joint
// (identity when the file gives none).
Status convertSkin(const tinygltf::Model& m, size_t s, Scene& scene) {
  const size_t n = m.nodes.size();
  const auto& src = m.skins[s];
  std::string where = "skin " + std::to_string(s);
  Skin skin;
  skin.name = src.name;
  skin.skeleton = src.skeleton;
  if (src.skeleton != -1 && !inRange(src.skeleton, n)) return Status::fail(where + ": skeleton node does not exist");
  if (src.joints.empty()) return Status::fail(where + ": skin has no joints");
  for (int j : src.joints) {
    if (!inRange(j, n)) return Status::fail(where + ": joint node " + std::to_string(j) + " does not exist");
    skin.joints.push_back(j);
  }
  skin.inverseBind.assign(skin.joints.size(), glm::mat4(1.0f));
  if (src.inverseBindMatrices >= 0) {
    auto ibm = readAccessorFloat(m, src.inverseBindMatrices, "inverseBindMatrices");
    if (!ibm) return Status::fail(ibm.error());
    if (ibm->components != 16 || ibm->count < skin.joints.size())
      return Status::fail(where + ": inverseBindMatrices must be MAT4 with one per joint");
    for (size_t j = 0; j < skin.joints.size(); ++j)
      for (int k = 0; k < 16; ++k) {
        float v = ibm->values[16 * j + size_t(k)];
        if (!std::isfinite(v)) return Status::fail(where + ": inverseBindMatrices has a non-finite value");
        skin.inverseBind[j][k / 4][k % 4] = v;
      }
  }
  scene.skins.push_back(std::move(skin));
  return {};
}

// Camera `ci`: finite parameters, then the glTF constraints made to hold (counted).
Status convertCamera(const tinygltf::Model& m, size_t ci, Scene& scene) {
  const auto& c = m.cameras[ci];
  const auto& pc = c.perspective;
  const auto& oc = c.orthographic;
  if (!floatRange({pc.yfov, pc.aspectRatio, pc.znear, pc.zfar, oc.xmag, oc.ymag, oc.znear, oc.zfar}))
    return Status::fail("camera " + std::to_string(ci) + ": parameter is not finite (or out of float range)");
  Camera cam;
  cam.name = c.name;
  cam.perspective = c.type != "orthographic";
  if (cam.perspective) {
    cam.yfov = float(c.perspective.yfov);
    cam.aspect = float(c.perspective.aspectRatio);
    cam.znear = float(c.perspective.znear);
    cam.zfar = float(c.perspective.zfar);
  } else {
    cam.xmag = float(c.orthographic.xmag);
    cam.ymag = float(c.orthographic.ymag);
    cam.znear = float(c.orthographic.znear);
    cam.zfar = float(c.orthographic.zfar);
  }
  scene.stats.camerasRepaired += repairCamera(cam);
  scene.cameras.push_back(cam);
  return {};
}

// The roots drawn: the default scene's nodes (addSceneRoots), or without a scene every
// parentless node.
Status chooseRoots(const tinygltf::Model& m, Scene& scene) {
  const size_t n = scene.nodes.size();
  int which = m.defaultScene >= 0 ? m.defaultScene : (m.scenes.empty() ? -1 : 0);
  if (which >= int(m.scenes.size())) return Status::fail("default scene " + std::to_string(which) + " does not exist");
  if (which < 0) {  // no scene: every parentless node is a root
    for (size_t i = 0; i < n; ++i)
      if (scene.nodes[i].parent == -1) scene.roots.push_back(int(i));
    return {};
  }
  const std::vector<int>& listed = m.scenes[size_t(which)].nodes;
  for (int r : listed)
    if (!inRange(r, n)) return Status::fail("scene " + std::to_string(which) + ": node " + std::to_string(r) + " does not exist");
  addSceneRoots(listed, scene);
  return {};
}

}  // namespace

Status convertNodes(const tinygltf::Model& m, Scene& scene) {
  if (Status s = convertAllNodes(m, scene); !s) return s;
  if (Status s = linkChildren(m, scene); !s) return s;
  if (Status s = checkNoCycle(scene); !s) return s;
  for (size_t s = 0; s < m.skins.size(); ++s)
    if (Status ok = convertSkin(m, s, scene); !ok) return ok;
  for (size_t ci = 0; ci < m.cameras.size(); ++ci)
    if (Status ok = convertCamera(m, ci, scene); !ok) return ok;
  return chooseRoots(m, scene);
}

}  // namespace mb
