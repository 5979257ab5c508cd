// The glTF/GLB seeds of the committed fuzz corpus (see seed_corpus.h; declared in seed_files.h): one small valid file per
// feature family, named after what it holds.
#include "tests/fuzz/seed_corpus.h"

namespace mb::fuzz {

// Interleaved POSITION/NORMAL/TEXCOORD_0 in one strided view, and positions in a padded stride
// read from a non-zero accessor byteOffset.
inline Doc interleavedDoc() {
  Doc d;
  struct V {
    float p[3], n[3], t[2];
  };
  std::vector<V> v = {{{0, 0, 0}, {0, 0, 1}, {0, 1}}, {{1, 0, 0}, {0, 0, 1}, {1, 1}}, {{1, 1, 0}, {0, 0, 1}, {1, 0}}, {{0, 1, 0}, {0, 0, 1}, {0, 0}}};
  int bv = d.view(v.data(), v.size() * sizeof(V), int(sizeof(V)), 34962);
  int pos = d.accessor(bv, kFloat, 4, "VEC3");
  d.j["accessors"][pos]["min"] = {0, 0, 0};
  d.j["accessors"][pos]["max"] = {1, 1, 0};
  int nrm = d.accessor(bv, kFloat, 4, "VEC3", 12);
  int uv = d.accessor(bv, kFloat, 4, "VEC2", 24);
  int ix = d.indices16({0, 1, 2, 0, 2, 3});
  d.mesh({{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}}}, {"indices", ix}});
  // Second mesh: 20-byte stride (VEC3 + 8 bytes of padding), accessor starting 4 bytes in.
  std::vector<float> padded;
  for (const auto& p : std::vector<glm::vec3>{{2, 0, 0}, {3, 0, 0}, {2, 1, 0}}) padded.insert(padded.end(), {-9.0f, p.x, p.y, p.z, -9.0f});
  int bv2 = d.view(padded.data(), padded.size() * 4, 20, 34962);
  int pos2 = d.accessor(bv2, kFloat, 3, "VEC3", 4);
  d.j["accessors"][pos2]["min"] = {2, 0, 0};
  d.j["accessors"][pos2]["max"] = {3, 1, 0};
  d.mesh({{"attributes", {{"POSITION", pos2}}}});
  d.node({{"mesh", 0}});
  d.node({{"mesh", 1}});
  d.scene({0, 1});
  d.finish();
  return d;
}

// Positions with a sparse substitution whose indices are `ict`; `base`: false = no bufferView
// (zeros plus the sparse values).
inline Doc sparseDoc(int ict, bool base) {
  Doc d;
  std::vector<glm::vec3> tri = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  int pos = base ? d.positions(tri) : d.accessor(-1, kFloat, 4, "VEC3");
  Bytes idx;
  for (float i : {1.0f, 3.0f}) encodeValue(idx, ict, false, i);
  std::vector<glm::vec3> val = {{2, 0, 0}, {2, 2, 0}};
  int iv = d.view(idx.data(), idx.size());
  int vv = d.view(val.data(), val.size() * 12);
  auto& a = d.j["accessors"][pos];
  a["sparse"] = {{"count", 2}, {"indices", {{"bufferView", iv}, {"componentType", ict}}}, {"values", {{"bufferView", vv}}}};
  a["min"] = {0, 0, 0};
  a["max"] = {2, 2, 0};
  d.mesh({{"attributes", {{"POSITION", pos}}}, {"indices", d.indices16({0, 1, 2, 2, 1, 3})}});
  d.node({{"mesh", 0}});
  d.scene({0});
  d.finish();
  return d;
}

// A morph-target quad, three animated nodes and one channel per path with `interp`; outputs of
// rotation stored as `rotCt` (normalized when not float, KHR_mesh_quantization).
inline Doc animationDoc(const std::string& interp, int rotCt = kFloat) {
  Doc d;
  hostile::quad(d);
  d.j["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", d.vec3(std::vector<glm::vec3>(4, {0, 0, 0.5f}))}}};
  d.j["meshes"][0]["weights"] = {0.0};
  int a = d.node({{"name", "a"}, {"translation", {1, 0, 0}}});
  int b = d.node({{"name", "b"}, {"children", {a}}});
  d.j["scenes"][0]["nodes"].push_back(b);
  const bool cubic = interp == "CUBICSPLINE";
  const int k = cubic ? 3 : 1;  // values per key: in-tangent, value, out-tangent
  int in = d.scalars({0.0f, 0.5f, 1.0f});
  auto keys = [&](std::vector<float> v, int comps) {  // 3 keys; tangents zero for CUBICSPLINE
    std::vector<float> out;
    for (int key = 0; key < 3; ++key)
      for (int part = 0; part < k; ++part)
        for (int c = 0; c < comps; ++c) out.push_back(cubic && part != 1 ? 0.0f : v[size_t(key * comps + c)]);
    return out;
  };
  std::vector<float> rot = {0, 0, 0, 1, 0, 0.3826834f, 0, 0.9238795f, 0, 0.7071068f, 0, 0.7071068f};
  Json samplers = Json::array(), channels = Json::array();
  auto add = [&](int output, int node, const char* path) {
    samplers.push_back({{"input", in}, {"output", output}, {"interpolation", interp}});
    channels.push_back({{"sampler", int(samplers.size()) - 1}, {"target", {{"node", node}, {"path", path}}}});
  };
  add(typed(d, kFloat, false, "VEC3", 3, keys({1, 0, 0, 1, 1, 0, 1, 0, 1}, 3)), a, "translation");
  add(typed(d, rotCt, rotCt != kFloat, "VEC4", 4, keys(rot, 4)), b, "rotation");
  add(typed(d, kFloat, false, "VEC3", 3, keys({1, 1, 1, 2, 1, 1, 1, 1, 1}, 3)), a, "scale");
  add(typed(d, kFloat, false, "SCALAR", 1, keys({0, 1, 0}, 1)), 0, "weights");
  d.arr("animations").push_back({{"name", interp}, {"samplers", samplers}, {"channels", channels}});
  if (rotCt != kFloat) useExtension(d, "KHR_mesh_quantization", true);
  d.finish();
  return d;
}

// Skinned ribbon with 4 joints; `ibm` false drops inverseBindMatrices (identity binds);
// `jointCt`/`weightCt`: JOINTS_0 and WEIGHTS_0 storage; `twoSets` adds JOINTS_1/WEIGHTS_1.
inline Doc skinDoc(bool ibm, int jointCt = kUShort, int weightCt = kFloat, bool twoSets = false) {
  Doc d;
  hostile::skinnedRibbon(d, 4);
  if (!ibm) d.j["skins"][0].erase("inverseBindMatrices");
  auto& attrs = d.j["meshes"][0]["primitives"][0]["attributes"];
  const size_t nv = 10;  // (4 + 1) vertex pairs
  std::vector<float> jt, wt, jt1, wt1;
  for (size_t v = 0; v < nv; ++v) {
    float a = float(std::min<size_t>(v / 2, 3)), b = float(std::min<size_t>(v / 2 + 1, 3));
    jt.insert(jt.end(), {a, b, 0, 0});
    const float w = twoSets ? 0.4f : 0.5f;
    wt.insert(wt.end(), {w, w, 0, 0});
    jt1.insert(jt1.end(), {0, 1, 2, 3});
    wt1.insert(wt1.end(), {0.2f, 0, 0, 0});
  }
  if (jointCt != kUShort || weightCt != kFloat) {
    attrs["JOINTS_0"] = typed(d, jointCt, false, "VEC4", 4, jt);
    attrs["WEIGHTS_0"] = typed(d, weightCt, weightCt != kFloat, "VEC4", 4, wt);
  }
  if (twoSets) {
    attrs["WEIGHTS_0"] = typed(d, weightCt, weightCt != kFloat, "VEC4", 4, wt);
    attrs["JOINTS_1"] = typed(d, kUByte, false, "VEC4", 4, jt1);
    attrs["WEIGHTS_1"] = typed(d, kUShort, true, "VEC4", 4, wt1);
  }
  d.finish();
  return d;
}

inline Doc cameraDoc(const Json& camera) {
  Doc d;
  hostile::quad(d);
  d.arr("cameras").push_back(camera);
  int cn = d.node({{"camera", 0}, {"translation", {0, 0, 4}}, {"rotation", {0, 0.0499792f, 0, 0.9987503f}}});
  d.j["scenes"][0]["nodes"].push_back(cn);
  d.finish();
  return d;
}

// Every texture slot, each from its own small image (PNG and JPEG), TEXCOORD_1 on occlusion,
// alpha MASK, double-sided, emissive factor, samplers with every wrap mode.
inline Doc everySlotDoc() {
  Doc d;
  std::vector<int> tex;
  const char* kinds[] = {"png_rgba8", "png_rgb8", "png_rgb16", "png_grey8", "jpeg_rgb_420_q90"};
  auto imgs = imageSeeds();
  for (int i = 0; i < 5; ++i) {
    const SeedFile* f = nullptr;
    for (const auto& s : imgs)
      if (s.name.rfind(kinds[i], 0) == 0) f = &s;
    int bv = d.view(f->bytes.data(), f->bytes.size());
    int img = Doc::push(d.arr("images"), Json{{"bufferView", bv}, {"mimeType", i == 4 ? "image/jpeg" : "image/png"}});
    int wrap[3] = {10497, 33071, 33648};
    int smp = Doc::push(d.arr("samplers"), Json{{"wrapS", wrap[i % 3]}, {"wrapT", wrap[(i + 1) % 3]}, {"magFilter", 9728 + (i % 2)}, {"minFilter", 9984 + (i % 4)}});
    tex.push_back(d.texture(img, smp));
  }
  Json m = {{"name", "every-slot"},
            {"pbrMetallicRoughness",
             {{"baseColorTexture", {{"index", tex[0]}}}, {"metallicRoughnessTexture", {{"index", tex[1]}}}, {"baseColorFactor", {1, 0.8, 0.6, 1}}, {"metallicFactor", 0.3}, {"roughnessFactor", 0.6}}},
            {"normalTexture", {{"index", tex[2]}, {"scale", 0.5}}},
            {"occlusionTexture", {{"index", tex[3]}, {"strength", 0.7}, {"texCoord", 1}}},
            {"emissiveTexture", {{"index", tex[4]}}},
            {"emissiveFactor", {0.2, 0.1, 0}},
            {"alphaMode", "MASK"},
            {"alphaCutoff", 0.4},
            {"doubleSided", true}};
  int mat = d.material(m);
  hostile::quad(d, true, true, mat);
  d.j["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_1"] = d.vec2(std::vector<glm::vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  d.finish();
  return d;
}

// KHR extensions on the root, a node, a material and a texture reference: the loader ignores
// (lists as unsupported) KHR_materials_unlit, KHR_materials_clearcoat and KHR_lights_punctual;
// KHR_texture_transform and KHR_materials_emissive_strength are drawn. (Draco primitives are
// decoded; their malformed payloads are hostile cases, tests/hostile.)
inline Doc ignoredExtensionsDoc() {
  Doc d;
  auto png = hostile::checkerPng();
  int tex = d.texture(d.image(png));
  Json base = {{"index", tex}, {"extensions", {{"KHR_texture_transform", {{"offset", {0.5, 0}}, {"scale", {2, 2}}}}}}};
  Json ext = {{"KHR_materials_emissive_strength", {{"emissiveStrength", 3.0}}},
              {"KHR_materials_unlit", Json::object()},
              {"KHR_materials_clearcoat", {{"clearcoatFactor", 0.5}}}};
  int mat = d.material({{"pbrMetallicRoughness", {{"baseColorTexture", base}}}, {"extensions", ext}});
  hostile::quad(d, true, true, mat);
  d.j["extensions"] = {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}, {"intensity", 5.0}}, {{"type", "spot"}, {"spot", {{"outerConeAngle", 0.5}}}}}}}}};
  d.j["nodes"][0]["extensions"] = {{"KHR_lights_punctual", {{"light", 0}}}};
  for (const char* e : {"KHR_texture_transform", "KHR_materials_emissive_strength", "KHR_materials_unlit", "KHR_materials_clearcoat", "KHR_lights_punctual"})
    useExtension(d, e);
  d.finish();
  return d;
}

// Strip, fan, points, lines, line strip/loop, an indexed and a non-indexed triangle list in one mesh; a second scene whose
// nodes use a matrix; `scene` = 1.
inline Doc primitivesDoc() {
  Doc d;
  int pos = d.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 0.5f, 0}});
  Json prims = Json::array();
  for (int mode : {5, 6, 0, 1, 3, 2}) prims.push_back({{"attributes", {{"POSITION", pos}}}, {"mode", mode}});
  prims.push_back({{"attributes", {{"POSITION", pos}}}, {"indices", d.indices32({0, 1, 2, 1, 3, 2, 3, 4, 1})}});
  int pos6 = d.positions({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}});
  prims.push_back({{"attributes", {{"POSITION", pos6}}}, {"mode", 4}});  // non-indexed list
  d.arr("meshes").push_back({{"primitives", prims}});
  d.node({{"mesh", 0}});
  d.node({{"mesh", 0}, {"matrix", {0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 3, 0, 0, 1}}});
  d.node({{"children", {1}}, {"scale", {1, 2, 1}}});
  d.j["scenes"] = {{{"nodes", {0}}}, {{"nodes", {2}}, {"name", "second"}}};
  d.j["scene"] = 1;
  d.finish();
  return d;
}

// The project's writer (GlbBuilder, as the built-in scenes use it): a textured, skinned strip
// with LINEAR, STEP and CUBICSPLINE channels sharing one input accessor.
inline Bytes writerGlb() {
  GlbBuilder b;
  MeshData m;
  for (int k = 0; k < 3; ++k)
    for (int side = 0; side < 2; ++side) {
      m.positions.push_back({side ? 0.2f : -0.2f, 0.5f * float(k), 0});
      m.normals.push_back({0, 0, 1});
      m.tangents.push_back({1, 0, 0, 1});
      m.uv0.push_back({float(side), 0.5f * float(k)});
      m.joints.push_back({uint16_t(k < 2 ? 0 : 1), 1, 0, 0});
      m.weights.push_back({0.7f, 0.3f, 0, 0});
    }
  m.indices = {0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4};
  std::vector<uint8_t> rgba;
  for (int i = 0; i < 16; ++i) rgba.insert(rgba.end(), {uint8_t(i * 16), 128, uint8_t(255 - i * 16), 255});
  MaterialDesc md;
  md.name = "writer";
  md.baseColorTexture = b.addTexturePng("writer", 4, 4, rgba);
  md.normalTexture = md.baseColorTexture;
  int mesh = b.addMesh("strip", m, b.addMaterial(md));
  int root = b.addNode("root"), j0 = b.addNode("j0"), j1 = b.addNode("j1", {0, 0.5f, 0});
  b.addChild(root, j0);
  b.addChild(j0, j1);
  int skinned = b.addNode("skinned");
  b.setMesh(skinned, mesh, b.addSkin("skin", {j0, j1}, b.addInverseBindMatrices({glm::mat4(1.0f), glm::mat4(1.0f)})));
  b.addRoot(root);
  b.addRoot(skinned);
  int anim = b.addAnimation("all");
  std::vector<float> t = {0, 1};
  b.addChannel(anim, j1, "rotation", t, {0, 0, 0, 1, 0, 0, 0.3826834f, 0.9238795f});
  b.addChannel(anim, j0, "translation", t, {0, 0, 0, 0.5f, 0, 0}, "STEP");
  b.addChannel(anim, root, "scale", t, {0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0, 2, 2, 2, 0, 0, 0}, "CUBICSPLINE");
  auto glb = b.writeGlb();
  return glb ? *glb : Bytes{};
}

// Every loader seed, name -> bytes; .gltf files with external files come with them
// (same stem).
std::vector<SeedFile> loaderSeeds() {
  using hostile::toGlb, hostile::toGltfEmbedded, hostile::toGltfExternal;
  std::vector<SeedFile> s;
  // Every component type, normalized and not (KHR_mesh_quantization; normalized uint is not
  // valid glTF but read all the same).
  for (int ct : {kByte, kUByte, kShort, kUShort, kUInt, kFloat})
    for (bool norm : {false, true}) {
      if (norm && ct == kFloat) continue;
      s.push_back({std::string("accessor_") + componentName(ct) + (norm ? "_normalized" : "") + ".glb", toGlb(quantizedQuad(ct, norm))});
    }
  s.push_back({"accessor_interleaved_padded_stride.glb", toGlb(interleavedDoc())});
  for (int ict : {kUByte, kUShort, kUInt}) s.push_back({std::string("sparse_indices_") + componentName(ict) + ".glb", toGlb(sparseDoc(ict, true))});
  s.push_back({"sparse_without_bufferview.glb", toGlb(sparseDoc(kUShort, false))});
  // Embedded images: every PNG kind and the JPEGs, one GLB each.
  for (const SeedFile& img : imageSeeds()) {
    const bool jpeg = img.name.rfind("jpeg", 0) == 0;
    s.push_back({"image_" + img.name.substr(0, img.name.find('.')) + ".glb", toGlb(texturedQuad(img.bytes, jpeg ? "image/jpeg" : "image/png"))});
  }
  for (const char* interp : {"LINEAR", "STEP", "CUBICSPLINE"}) s.push_back({std::string("anim_") + interp + ".glb", toGlb(animationDoc(interp))});
  s.push_back({"anim_rotation_short_normalized.glb", toGlb(animationDoc("LINEAR", kShort))});
  s.push_back({"anim_rotation_byte_normalized.glb", toGlb(animationDoc("STEP", kByte))});
  s.push_back({"skin_with_inverse_binds.glb", toGlb(skinDoc(true))});
  s.push_back({"skin_without_inverse_binds.glb", toGlb(skinDoc(false))});
  s.push_back({"skin_joints_ubyte_weights_unorm8.glb", toGlb(skinDoc(true, kUByte, kUByte))});
  s.push_back({"skin_two_sets_weights_unorm16.glb", toGlb(skinDoc(true, kUShort, kUShort, true))});
  s.push_back({"camera_perspective.glb", toGlb(cameraDoc({{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"aspectRatio", 1.5}, {"znear", 0.1}, {"zfar", 100}}}}))});
  s.push_back({"camera_perspective_infinite.glb", toGlb(cameraDoc({{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.05}}}}))});
  s.push_back({"camera_orthographic.glb", toGlb(cameraDoc({{"type", "orthographic"}, {"orthographic", {{"xmag", 2}, {"ymag", 1.5}, {"znear", 0.01}, {"zfar", 20}}}}))});
  s.push_back({"material_every_texture_slot.glb", toGlb(everySlotDoc())});
  s.push_back({"extensions_ignored_khr.glb", toGlb(ignoredExtensionsDoc())});
  s.push_back({"primitives_modes_two_scenes.glb", toGlb(primitivesDoc())});
  s.push_back({"writer_glbbuilder_skinned_textured.glb", writerGlb()});
  hostile::Doc rich = hostile::richDoc();
  s.push_back({"rich.glb", toGlb(rich)});
  // data: URIs (buffer, PNG image, JPEG image) and external neighbours.
  s.push_back({"datauri_rich.gltf", toGltfEmbedded(rich)});
  {
    Doc d = hostile::detail::quadDoc();
    auto imgs = imageSeeds();
    Json images = Json::array();
    for (const auto& f : imgs)
      if (f.name == "png_palette8_trns.png" || f.name == "jpeg_rgb_444_q100.jpg")
        images.push_back({{"uri", std::string("data:image/") + (f.name[0] == 'p' ? "png" : "jpeg") + ";base64," + hostile::base64(f.bytes)}});
    d.j["images"] = images;
    d.j["textures"] = {{{"source", 0}}, {{"source", 1}}};
    d.j["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}, {"emissiveTexture", {{"index", 1}}}}};
    d.j["meshes"][0]["primitives"][0]["material"] = 0;
    s.push_back({"datauri_images_png_jpeg.gltf", toGltfEmbedded(d)});
  }
  {
    Doc d = skinDoc(true);
    s.push_back({"external_bin_skin.gltf", toGltfExternal(d, "external_bin_skin.bin")});
    s.push_back({"external_bin_skin.bin", d.bin});
  }
  {
    Doc d = hostile::detail::quadDoc();
    d.j["images"] = {{{"uri", "external_image_grey_alpha.png"}}};
    d.j["textures"] = {{{"source", 0}}};
    d.j["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    d.j["meshes"][0]["primitives"][0]["material"] = 0;
    s.push_back({"external_bin_and_image.gltf", toGltfExternal(d, "external_bin_and_image.bin")});
    s.push_back({"external_bin_and_image.bin", d.bin});
    for (const auto& f : imageSeeds())
      if (f.name == "png_grey_alpha8.png") s.push_back({"external_image_grey_alpha.png", f.bytes});
  }
  return s;
}

}  // namespace mb::fuzz
