// "teapot": Newell's teapot (data/teapot.bpt, Martin Newell 1975) as bicubic Bezier patches
// carried by MB_bezier_patches primitives (gltf_patches.cpp), so pipelines tessellate it. The
// body turns once about its up axis in 4 s; the lid (patches 21-28, its own node, a child of
// the body) lifts, turns once against the body and sets down again.
#include <tiny_gltf.h>

#include <cmath>

#include "pipelines/scene/builtin/bpt_reader.h"
#include "pipelines/scene/builtin/builtin_internal.h"

namespace mb {

const char* teapotBpt();  // generated from data/teapot.bpt (CMakeLists.txt)

namespace {

constexpr int kLidFirst = 20, kLidLast = 27;  // 0-based patch indices of the lid

int addPatchMesh(GlbBuilder& b, const std::string& name, const std::vector<glm::vec3>& points, int material) {
  tinygltf::Model& m = b.model();
  tinygltf::Primitive p;
  p.mode = TINYGLTF_MODE_POINTS;
  p.material = material;
  p.attributes["POSITION"] = b.addFloatAccessor(&points[0].x, points.size(), 3, true);
  tinygltf::Value::Object ext;
  ext["degree"] = tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(3), tinygltf::Value(3)});
  p.extensions["MB_bezier_patches"] = tinygltf::Value(ext);
  tinygltf::Mesh mesh;
  mesh.name = name;
  mesh.primitives.push_back(p);
  m.meshes.push_back(mesh);
  ++b.facts().meshes;
  ++b.facts().primitives;
  return int(m.meshes.size() - 1);
}

// Rotation by `turns` full turns about +Z (the teapot's up axis), as glTF x, y, z, w.
void pushTurn(std::vector<float>& out, float turns) {
  glm::quat q = glm::angleAxis(6.28318530718f * turns, glm::vec3(0, 0, 1));
  out.insert(out.end(), {q.x, q.y, q.z, q.w});
}

}  // namespace

void buildTeapot(GlbBuilder& b) {
  auto parsed = parseBpt(teapotBpt(), "teapot.bpt");
  std::vector<glm::vec3> body, lid;
  if (parsed)  // the embedded file is checked by tests/scene/test_scene_bpt.cpp
    for (size_t i = 0; i < parsed->size(); ++i) {
      size_t patch = i / 16;
      (patch >= size_t(kLidFirst) && patch <= size_t(kLidLast) ? lid : body).push_back((*parsed)[i]);
    }
  MaterialDesc glaze;
  glaze.name = "glaze";
  glaze.baseColor = glm::vec4(0.80f, 0.42f, 0.22f, 1.0f);
  glaze.metallic = 0.0f;
  glaze.roughness = 0.3f;
  int material = b.addMaterial(glaze);
  // Double-sided: the lifted lid shows the inside of the body.
  b.model().materials[size_t(material)].doubleSided = true;
  b.model().extensionsUsed.push_back("MB_bezier_patches");

  int up = b.addNode("z_up", glm::vec3(0.0f), glm::angleAxis(-1.57079632679f, glm::vec3(1, 0, 0)));
  int bodyNode = b.addNode("body");
  int lidNode = b.addNode("lid");
  b.addChild(up, bodyNode);
  b.addChild(bodyNode, lidNode);
  b.addRoot(up);
  if (!body.empty()) b.setMesh(bodyNode, addPatchMesh(b, "teapot_body", body, material));
  if (!lid.empty()) b.setMesh(lidNode, addPatchMesh(b, "teapot_lid", lid, material));

  int anim = b.addAnimation("lift_lid");
  const std::vector<float> times = {0, 1, 2, 3, 4};
  std::vector<float> bodyTurn, lidTurn;
  for (int k = 0; k <= 4; ++k) {
    pushTurn(bodyTurn, 0.25f * float(k));   // quarter turns: keys stay < 180 degrees apart
    pushTurn(lidTurn, -0.25f * float(k));
  }
  b.addChannel(anim, bodyNode, "rotation", times, bodyTurn);
  b.addChannel(anim, lidNode, "rotation", times, lidTurn);
  b.addChannel(anim, lidNode, "translation", times, {0, 0, 0, 0, 0, 0.4f, 0, 0, 0.7f, 0, 0, 0.4f, 0, 0, 0});
}

}  // namespace mb
