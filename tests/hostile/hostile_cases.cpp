// The hostile-input catalogue's cases (tests/hostile/hostile_cases.h says what each kind of case
// means). Compiled once (mb_test_hostile, tests/CMakeLists.txt) instead of in every test file
// that includes the header.
#include "tests/hostile/hostile_cases.h"

#include <cstring>
#include <initializer_list>
#include <limits>

namespace mb::hostile {

// GLB container corruption.
std::vector<Case> containerCases() {
  using namespace detail;
  std::vector<Case> cs;
  const Bytes good = toGlb(quadDoc());
  const GlbLayout L = glbLayout(good);
  auto patched = [&](size_t at, uint32_t v) {
    Bytes b = good;
    put32(b, at, v);
    return b;
  };
  cs.push_back(error("empty.glb", {}, {"empty", "short", "truncat", "size"}, "zero bytes"));
  cs.push_back(error("header_only.glb", Bytes(good.begin(), good.begin() + 12), {"short", "truncat", "size", "invalid"},
                     "12-byte GLB header and nothing else"));
  {
    Bytes b = good;
    b[3] = 'X';
    cs.push_back(error("bad_magic.glb", b, {"magic", "json", "parse"}, "magic 'glTX' instead of 'glTF'"));
  }
  cs.push_back(error("version_1.glb", patched(4, 1), {"version"}, "GLB container version 1"));
  cs.push_back(error("version_3.glb", patched(4, 3), {"version"}, "GLB container version 3"));
  cs.push_back(error("length_beyond_file.glb", patched(8, uint32_t(good.size() + 64)), {"length", "truncat", "size", "invalid"},
                     "header length 64 bytes more than the file"));
  cs.push_back(error("length_max.glb", patched(8, 0xFFFFFFFFu), {"length", "truncat", "size", "invalid"}, "header length 4 GiB"));
  cs.push_back(error("length_drops_bin.glb", patched(8, uint32_t(L.jsonEnd)), {"buffer", "bin", "length", "size"},
                     "header length ends after the JSON chunk: BIN chunk cut off, buffer 0 has no data"));
  cs.push_back(error("json_chunk_length_beyond_file.glb", patched(12, uint32_t(good.size())), {"length", "chunk", "invalid", "json"},
                     "JSON chunk length larger than the file"));
  cs.push_back(error("json_chunk_length_huge.glb", patched(12, 0xFFFFFFF0u), {"length", "chunk", "invalid", "exceed"},
                     "JSON chunk length 0xFFFFFFF0 (20 + length overflows 32 bits)"));
  cs.push_back(error("json_chunk_length_zero.glb", patched(12, 0), {"length", "chunk", "invalid", "json"}, "JSON chunk length 0"));
  cs.push_back(error("json_chunk_length_short.glb", patched(12, get32(good, 12) - 8), {"json", "parse", "chunk", "bin", "invalid"},
                     "JSON chunk length 8 bytes short: JSON cut, BIN chunk header misplaced"));
  cs.push_back(error("json_chunk_wrong_type.glb", patched(16, 0x12345678u), {"chunk", "json", "type", "invalid"},
                     "first chunk type is not JSON"));
  cs.push_back(error("bin_chunk_length_beyond_file.glb", patched(L.binHeader, uint32_t(good.size())), {"bin", "chunk", "length", "exceed"},
                     "BIN chunk length larger than the file"));
  cs.push_back(error("bin_chunk_length_huge.glb", patched(L.binHeader, 0xFFFFFFFCu), {"bin", "chunk", "length", "exceed"},
                     "BIN chunk length 0xFFFFFFFC"));
  cs.push_back(error("bin_chunk_length_short.glb", patched(L.binHeader, 8), {"buffer", "bin", "length", "size", "exceed"},
                     "BIN chunk length 8: buffer 0 byteLength exceeds it"));
  cs.push_back(fallback("bin_chunk_length_unaligned.glb", patched(L.binHeader, get32(good, L.binHeader) - 1), &LoadStats::binChunkUnaligned, 1,
                        "BIN chunk length not a multiple of 4 (as three.js and the Sample Viewer do: zero-padded, counted)"));
  {
    // The JSON chunk unpadded (length 4k + 1..3), the BIN chunk right after it.
    std::string json(good.begin() + 20, good.begin() + long(L.jsonEnd));
    while (!json.empty() && json.back() == ' ') json.pop_back();
    if (json.size() % 4 == 0) json += ' ';
    Bytes b(good.begin(), good.begin() + 20);
    put32(b, 12, uint32_t(json.size()));
    appendBytes(b, json.data(), json.size());
    b.insert(b.end(), good.begin() + long(L.binHeader), good.end());
    put32(b, 8, uint32_t(b.size()));
    cs.push_back(fallback("json_chunk_length_unpadded.glb", b, &LoadStats::jsonChunkUnpadded, 1,
                          "JSON chunk length not a multiple of 4, BIN chunk right after it (read as three.js does, counted)"));
  }
  cs.push_back(error("bin_chunk_wrong_type.glb", patched(L.binHeader + 4, 0x41414141u), {"bin", "chunk", "type", "invalid"},
                     "second chunk type is not BIN"));
  {
    Bytes b = good;
    b.resize(b.size() + 100, 0xAB);
    put32(b, 8, uint32_t(b.size()));
    cs.push_back(loads("trailing_garbage_chunk.glb", b, "100 bytes of an unknown chunk after BIN (ignored, as the spec allows)"));
  }
  {
    // GLB whose JSON references buffer 0 without uri, but there is no BIN chunk at all.
    Doc d = quadDoc();
    cs.push_back(error("glb_without_bin.glb", glbContainer(d.j.dump(), {}), {"buffer", "bin"}, "GLB buffer 0 has no uri and no BIN chunk"));
  }
  return cs;
}

// JSON-level corruption.
std::vector<Case> jsonCases() {
  using namespace detail;
  std::vector<Case> cs;
  const std::string good = quadDoc().j.dump();
  cs.push_back(error("broken_json.gltf", toBytes(good.substr(0, good.size() / 2)), {"json", "parse"}, "JSON cut in the middle"));
  cs.push_back(error("broken_json.glb", glbContainer(good.substr(0, good.size() - 7) + "@@@@@@@", quadDoc().bin), {"json", "parse"},
                     "GLB whose JSON chunk ends in garbage"));
  cs.push_back(error("json_not_object.gltf", toBytes("[1,2,3]"), {"json", "object", "asset", "parse"}, "top-level JSON is an array"));
  cs.push_back(error("json_empty.gltf", toBytes(""), {"json", "empty", "parse", "short"}, "empty .gltf"));
  cs.push_back(error("json_binary_junk.gltf", Bytes{0xFF, 0xFE, 0x00, 0x01, 0x7B, 0x22, 0x00}, {"json", "parse"}, "binary junk"));
  cs.push_back(error("json_deep_nesting.gltf", toBytes("{\"asset\":{\"version\":\"2.0\"},\"extras\":" + std::string(100000, '[') + std::string(100000, ']') + "}"),
                     {"json", "depth", "nest", "parse"}, "100,000 nested arrays (recursion depth)"));
  {
    Doc d = quadDoc();
    d.j.erase("asset");
    cs.push_back(error("missing_asset.gltf", toGltfEmbedded(d), {"asset", "version"}, "no asset object"));
  }
  {
    // A glTF 1.0 file: objects are dictionaries keyed by id, not arrays. Loading it as 2.0
    // would silently give an empty scene.
    Json j = {{"asset", {{"version", "1.0"}}},
              {"scene", "defaultScene"},
              {"scenes", {{"defaultScene", {{"nodes", {"node_1"}}}}}},
              {"nodes", {{"node_1", {{"meshes", {"mesh_1"}}}}}},
              {"meshes", {{"mesh_1", {{"primitives", {{{"attributes", {{"POSITION", "acc_pos"}}}, {"mode", 4}}}}}}}},
              {"accessors", {{"acc_pos", {{"bufferView", "bv"}, {"componentType", kFloat}, {"count", 3}, {"type", "VEC3"}}}}},
              {"bufferViews", {{"bv", {{"buffer", "buf"}, {"byteLength", 36}}}}},
              {"buffers", {{"buf", {{"byteLength", 36}, {"uri", "data:application/octet-stream;base64," + base64(Bytes(36, 0))}}}}}};
    cs.push_back(error("gltf_1_0.gltf", toBytes(j.dump(1)), {"version", "1.0"}, "a glTF 1.0 file (dictionaries, asset.version 1.0)"));
  }
  {
    Doc d = quadDoc();
    d.j["accessors"][0]["count"] = "four";
    cs.push_back(error("wrong_json_type.gltf", toGltfEmbedded(d), {"count", "accessor", "type"}, "accessor.count is a string"));
  }
  {
    Doc d = quadDoc();
    d.j["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    d.j["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    d.j["meshes"][0]["primitives"][0]["extensions"] = {{"KHR_draco_mesh_compression", {{"bufferView", 0}, {"attributes", {{"POSITION", 0}}}}}};
    cs.push_back(error("required_extension_draco.glb", toGlb(d), {"KHR_draco_mesh_compression: Draco data does not decode"},
                       "Draco extension pointing at the raw POSITION bytes (not a Draco stream)"));
  }
  return cs;
}

namespace {

// The cases `steps` append to one list, in their order.
std::vector<Case> appended(std::initializer_list<void (*)(std::vector<Case>&)> steps) {
  std::vector<Case> cs;
  for (auto* step : steps) step(cs);
  return cs;
}

// A finished quad document modified by `edit`, as .glb.
Bytes glb(const std::function<void(Doc&, QuadIds&)>& e) { return toGlb(detail::quadDoc(e)); }

// Counts, offsets and references out of range, wrong index and element types, strides, alignment.
void accessorRangeCases(std::vector<Case>& cs) {
  using namespace detail;
  cs.push_back(error("accessor_count_beyond_view.glb", glb([](Doc& d, QuadIds& q) { d.j["accessors"][q.pos]["count"] = 100; }),
                     {"range", "exceed", "bounds", "too small", "beyond", "outside", "past"}, "POSITION count 100 in a 48-byte bufferView"));
  // Past its view, inside the buffer: the next view's bytes (the uvs) are read, as the glossary
  // says. Elements 0 and 2: the last normal's (y, z) and uv 0's x; uv 2 and uv 3's x.
  Case pastView = fallback("accessor_offset_beyond_view.glb", glb([](Doc& d, QuadIds& q) { d.j["accessors"][q.nrm]["byteOffset"] = 40; }),
                           &LoadStats::accessorsPastBufferView, 1,
                           "NORMAL byteOffset 40 leaves 8 of 48 bytes, the uv and index views follow (read, counted)");
  pastView.check = [](const Scene& s) -> std::string {
    const auto& n = s.meshes[0].primitives[0].normals;
    return n.size() == 4 && n[0] == glm::vec3(0, 1, 0) && n[2] == glm::vec3(1, 0, 0) ? "" : "normals are not the buffer's bytes";
  };
  cs.push_back(pastView);
  cs.push_back(error("accessor_offset_beyond_buffer.glb", glb([](Doc& d, QuadIds& q) { d.j["accessors"][q.nrm]["byteOffset"] = 88; }),
                     {"past the end of buffer 0"}, "NORMAL byteOffset 88: its 4 normals end 44 bytes past the end of the buffer"));
  cs.push_back(error("accessor_index_missing.glb", glb([](Doc& d, QuadIds&) { d.j["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 42; }),
                     {"accessor"}, "POSITION refers to accessor 42 (there are 4)"));
  cs.push_back(error("accessor_index_negative.glb", glb([](Doc& d, QuadIds&) { d.j["meshes"][0]["primitives"][0]["indices"] = -5; }),
                     {"accessor", "indices", "index"}, "indices accessor -5"));
  cs.push_back(error("bufferview_beyond_buffer.glb", glb([](Doc& d, QuadIds&) { d.j["bufferViews"][0]["byteLength"] = 4096; }),
                     {"bufferview", "buffer view", "range", "exceed", "bounds"}, "bufferView 0 is 4096 bytes, the buffer far fewer"));
  cs.push_back(error("bufferview_offset_beyond_buffer.glb", glb([](Doc& d, QuadIds&) { d.j["bufferViews"][1]["byteOffset"] = 1u << 30; }),
                     {"bufferview", "buffer view", "range", "exceed", "bounds"}, "bufferView 1 starts at 1 GiB"));
  cs.push_back(error("bufferview_bad_buffer.glb", glb([](Doc& d, QuadIds&) { d.j["bufferViews"][0]["buffer"] = 7; }),
                     {"buffer"}, "bufferView refers to buffer 7"));
  cs.push_back(error("accessor_bad_bufferview.glb", glb([](Doc& d, QuadIds& q) { d.j["accessors"][q.pos]["bufferView"] = 99; }),
                     {"bufferview", "buffer view"}, "accessor refers to bufferView 99"));
  cs.push_back(error("index_out_of_range.glb", glb([](Doc& d, QuadIds& q) { pokeBin<uint16_t>(d, q.idx, 4, 0, 1000); }),
                     {"index", "indices"}, "index 1000 with 4 vertices"));
  cs.push_back(error("index_float_component.glb", glb([](Doc& d, QuadIds& q) { d.j["accessors"][q.idx]["componentType"] = kFloat; }),
                     {"index", "indices", "component"}, "indices stored as FLOAT"));
  cs.push_back(error("index_vec3_type.glb", glb([](Doc& d, QuadIds& q) {
                       d.j["accessors"][q.idx]["type"] = "VEC3";
                       d.j["accessors"][q.idx]["count"] = 2;
                     }),
                     {"index", "indices", "type", "scalar"}, "indices accessor of type VEC3"));
  cs.push_back(error("position_vec2.glb", glb([](Doc& d, QuadIds& q) { d.j["accessors"][q.pos]["type"] = "VEC2"; }),
                     {"position", "type", "vec3"}, "POSITION of type VEC2"));
  cs.push_back(error("position_bad_component_type.glb", glb([](Doc& d, QuadIds& q) { d.j["accessors"][q.pos]["componentType"] = 1234; }),
                     {"component", "type"}, "componentType 1234"));
  cs.push_back(error("normal_count_mismatch.glb", glb([](Doc& d, QuadIds& q) { d.j["accessors"][q.nrm]["count"] = 3; }),
                     {"count", "normal", "mismatch"}, "NORMAL has 3 elements, POSITION 4"));
  cs.push_back(error("stride_smaller_than_element.glb", glb([](Doc& d, QuadIds& q) {
                       d.j["bufferViews"][d.j["accessors"][q.pos]["bufferView"].get<int>()]["byteStride"] = 4;
                     }),
                     {"stride"}, "POSITION (12-byte VEC3) in a bufferView with byteStride 4"));
  cs.push_back(error("stride_overruns_view.glb", glb([](Doc& d, QuadIds& q) {
                       d.j["bufferViews"][d.j["accessors"][q.pos]["bufferView"].get<int>()]["byteStride"] = 252;
                     }),
                     {"range", "exceed", "bounds", "too small", "beyond", "outside", "past", "stride"},
                     "byteStride 252 makes 4 elements need 768 bytes of a 48-byte view"));
  {
    // Misaligned: the spec requires component-size alignment; a loader may reject it or read it
    // correctly (never through a misaligned float*: UBSan watches).
    Doc d;
    std::vector<uint8_t> raw(1 + 36);
    std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    std::memcpy(raw.data() + 1, p.data(), 36);
    int bv = d.view(raw.data(), raw.size());
    int pos = d.accessor(bv, kFloat, 3, "VEC3", 1);
    d.j["accessors"][pos]["min"] = {0, 0, 0};
    d.j["accessors"][pos]["max"] = {1, 1, 0};
    int nrm = d.vec3(std::vector<glm::vec3>(3, {0, 0, 1}));
    d.mesh({{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}}}});
    d.node({{"mesh", 0}});
    d.scene({0});
    d.finish();
    Case c = error("misaligned_accessor_offset.glb", toGlb(d), {"align"}, "float accessor at byteOffset 1");
    c.check = positionsEqual(p);
    cs.push_back(c);
  }
}

// Counts and lengths that would allocate gigabytes if trusted.
void hugeCountCases(std::vector<Case>& cs) {
  using namespace detail;
  cs.push_back(error("huge_accessor_count_2p31.glb", glb([](Doc& d, QuadIds& q) { d.j["accessors"][q.pos]["count"] = uint64_t(1) << 31; }),
                     {"range", "exceed", "bounds", "too small", "beyond", "outside", "past", "count", "large"},
                     "POSITION count 2^31: must fail without allocating 24 GiB"));
  cs.push_back(error("huge_accessor_count_wraps_32bit.glb", glb([](Doc& d, QuadIds& q) { d.j["accessors"][q.pos]["count"] = (uint64_t(1) << 32) + 4; }),
                     {"range", "exceed", "bounds", "too small", "beyond", "outside", "past", "count", "large"},
                     "POSITION count 2^32+4 (4 if truncated to 32 bits)"));
  cs.push_back(error("huge_accessor_count_wraps_64bit.glb", glb([](Doc& d, QuadIds& q) { d.j["accessors"][q.pos]["count"] = uint64_t(1) << 62; }),
                     {"range", "exceed", "bounds", "too small", "beyond", "outside", "past", "count", "large", "overflow"},
                     "POSITION count 2^62: count*12 wraps to 0 in 64 bits"));
  // An accessor without bufferView is all zeros (spec), so nothing in the file bounds its count.
  cs.push_back(error("huge_count_without_bufferview.glb", glb([](Doc& d, QuadIds& q) {
                       d.j["accessors"][q.pos].erase("bufferView");
                       d.j["accessors"][q.pos]["count"] = uint64_t(1) << 26;
                       d.j["meshes"][0]["primitives"][0].erase("indices");
                       d.j["meshes"][0]["primitives"][0]["attributes"].erase("NORMAL");
                       d.j["meshes"][0]["primitives"][0]["attributes"].erase("TEXCOORD_0");
                     }),
                     {"large", "count", "exceed", "limit"}, "2^26 zero positions without bufferView: ~2.4 GB decoded from a 1 kB file"));
  {
    Doc d;
    skinnedRibbon(d, 3, true, false);
    d.finish();
    d.j["accessors"][5].erase("bufferView");
    d.j["accessors"][5]["count"] = (uint64_t(1) << 26) - 1;
    cs.push_back(error("huge_mat4_count_without_bufferview.glb", toGlb(d), {"large", "count", "exceed", "limit"},
                       "inverseBindMatrices: 2^26-1 MAT4 without bufferView: 4 GiB of zeros"));
  }
  {
    // Just under the loader's element cap, with a real (tiny) bufferView: the range check must
    // come before the 4 GiB of MAT4 values are allocated.
    Doc d;
    skinnedRibbon(d, 3, true, false);
    d.finish();
    d.j["accessors"][5]["count"] = (uint64_t(1) << 26) - 1;
    cs.push_back(error("huge_mat4_count_small_view.glb", toGlb(d), {"range", "exceed", "bounds", "past", "large", "count"},
                       "inverseBindMatrices: 2^26-1 MAT4 in a 192-byte bufferView"));
  }
  cs.push_back(error("huge_index_count.glb", glb([](Doc& d, QuadIds& q) { d.j["accessors"][q.idx]["count"] = uint64_t(3) << 30; }),
                     {"range", "exceed", "bounds", "too small", "beyond", "outside", "past", "count", "large"}, "3*2^30 indices"));
  cs.push_back(error("huge_buffer_bytelength.glb", glb([](Doc& d, QuadIds&) { d.j["buffers"][0]["byteLength"] = uint64_t(1) << 40; }),
                     {"buffer", "length", "size", "exceed"}, "buffer byteLength 2^40 in a GLB: must fail without allocating"));
  {
    Doc d = quadDoc();
    d.j["buffers"][0]["byteLength"] = uint64_t(1) << 40;
    cs.push_back(error("huge_buffer_bytelength_datauri.gltf", toGltfEmbedded(d), {"buffer", "length", "size", "uri", "decode", "data"},
                       "buffer byteLength 2^40 with a small data: URI"));
  }
  cs.push_back(error("huge_bufferview_bytelength.glb", glb([](Doc& d, QuadIds&) { d.j["bufferViews"][0]["byteLength"] = uint64_t(1) << 40; }),
                     {"bufferview", "buffer view", "range", "exceed", "bounds", "length"}, "bufferView byteLength 2^40"));
  cs.push_back(error("huge_bufferview_offset_wraps.glb", glb([](Doc& d, QuadIds&) { d.j["bufferViews"][0]["byteOffset"] = ~uint64_t(0) - 7; }),
                     {"bufferview", "buffer view", "range", "exceed", "bounds", "offset"}, "bufferView byteOffset 2^64-8 (offset+length wraps)"));
  {
    Case c = loads("accessor_without_bufferview.glb", glb([](Doc& d, QuadIds& q) {
                     d.j["accessors"][q.nrm].erase("bufferView");
                   }),
                   "NORMAL accessor without bufferView: all zeros per spec, so zero normals are replaced");
    c.outcome = Outcome::Fallback;
    c.counter = &LoadStats::badNormalsReplaced;
    c.atLeast = 4;
    cs.push_back(c);
  }
}

// data: URIs.
void dataUriCases(std::vector<Case>& cs) {
  using namespace detail;
  auto uriCase = [&](const std::string& file, const std::string& uri, const std::string& why) {
    Doc d = quadDoc();
    d.j["buffers"][0]["uri"] = uri;
    cs.push_back(error(file, toBytes(d.j.dump()), {"uri", "data", "decode", "base64", "buffer"}, why));
  };
  uriCase("datauri_bad_base64.gltf", "data:application/octet-stream;base64,@@@@!!!!", "data: URI with non-base64 characters");
  uriCase("datauri_unknown_mime.gltf", "data:text/html;base64,AAAAAAAA", "data: URI with mime text/html");
  uriCase("datauri_not_base64.gltf", "data:application/octet-stream,hello", "data: URI without ;base64 (percent-encoded): 5 bytes for a larger byteLength");
  uriCase("datauri_truncated.gltf", "data:application/octet-stream;base64,AAAA", "data: URI decoding to 3 bytes for a larger byteLength");
  uriCase("datauri_empty.gltf", "data:", "data: URI with nothing after the colon");
}

// Sparse accessors.
void sparseCases(std::vector<Case>& cs) {
  using namespace detail;
  auto sparseDoc = [](uint8_t index, int count, const std::function<void(Doc&, int)>& more = {}) {
    Doc d;
    QuadIds q = quad(d);
    std::vector<uint8_t> idx = {index, 0, 0, 0};
    std::vector<glm::vec3> val(size_t(std::clamp(count, 1, 16)), {0, 0, 5});
    int iv = d.view(idx.data(), 4);
    int vv = d.view(val.data(), val.size() * 12);
    d.j["accessors"][q.pos]["sparse"] = {{"count", count},
                                         {"indices", {{"bufferView", iv}, {"componentType", kUByte}}},
                                         {"values", {{"bufferView", vv}}}};
    if (more) more(d, q.pos);
    d.finish();
    return toGlb(d);
  };
  cs.push_back(error("sparse_index_out_of_range.glb", sparseDoc(200, 1), {"sparse"}, "sparse index 200 for a 4-element accessor"));
  cs.push_back(error("sparse_count_exceeds.glb", sparseDoc(1, 9), {"sparse"}, "sparse count 9 for a 4-element accessor"));
  cs.push_back(error("sparse_count_huge.glb", sparseDoc(1, 1 << 30), {"sparse", "range", "exceed"}, "sparse count 2^30"));
  cs.push_back(error("sparse_indices_view_missing.glb", sparseDoc(1, 1, [](Doc& d, int a) { d.j["accessors"][a]["sparse"]["indices"]["bufferView"] = 77; }),
                     {"sparse", "bufferview", "buffer view"}, "sparse indices in bufferView 77"));
  {
    Case c = loads("sparse_valid.glb", sparseDoc(2, 1), "a valid sparse substitution of vertex 2");
    auto p = quadPositions();
    p[2] = {0, 0, 5};
    c.check = positionsEqual(p);
    cs.push_back(c);
  }
}

}  // namespace

// Accessors, buffer views, indices, strides, alignment, huge counts, data: URIs, sparse.
std::vector<Case> accessorCases() { return appended({accessorRangeCases, hugeCountCases, dataUriCases, sparseCases}); }

namespace {

constexpr float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();

// Non-finite positions; zero, NaN and missing normals.
void positionNormalCases(std::vector<Case>& cs) {
  using namespace detail;
  // Vertices 2 and 3 (set to the origin) leave the triangle 0 1 2 its area: the quad still draws.
  cs.push_back(fallback("nan_positions.glb", glb([&](Doc& d, QuadIds& q) {
                          pokeBin(d, q.pos, 2, 0, nan);
                          pokeBin(d, q.pos, 3, 2, nan);
                        }),
                        &LoadStats::nonFinitePositions, 2, "two vertices with a NaN coordinate (set to 0, counted)"));
  cs.push_back(fallback("inf_positions.glb", glb([&](Doc& d, QuadIds& q) {
                          pokeBin(d, q.pos, 0, 1, inf);  // vertices 0 and 1: the triangle 0 2 3 keeps its area
                          pokeBin(d, q.pos, 1, 0, -inf);
                        }),
                        &LoadStats::nonFinitePositions, 2, "+Inf and -Inf coordinates"));
  cs.push_back(fallback("zero_normals.glb", glb([&](Doc& d, QuadIds& q) {
                          for (int v = 0; v < 4; ++v) pokeBin(d, q.nrm, size_t(v), 2, 0.0f);
                        }),
                        &LoadStats::badNormalsReplaced, 4, "all normals (0,0,0)"));
  cs.push_back(fallback("nan_normals.glb", glb([&](Doc& d, QuadIds& q) { pokeBin(d, q.nrm, 1, 1, nan); }),
                        &LoadStats::badNormalsReplaced, 1, "a NaN normal"));
  cs.push_back(fallback("no_normals.glb", toGlb(quadDoc({}, false)), &LoadStats::flatNormalsGenerated, 1, "no NORMAL: flat normals"));
}

// Tangents generated for normal-mapped primitives, or authored and unusable.
void tangentCases(std::vector<Case>& cs) {
  using namespace detail;
  {
    // Degenerate UVs on a normal-mapped primitive without TANGENT: tangent generation divides
    // by the UV determinant, which is 0 for every triangle.
    Doc d;
    int mat = normalMappedMaterial(d);
    QuadIds q = quad(d, true, true, mat);
    for (int v = 0; v < 4; ++v) {
      pokeBin(d, q.uv, size_t(v), 0, 0.5f);
      pokeBin(d, q.uv, size_t(v), 1, 0.5f);
    }
    d.finish();
    Case c = fallback("degenerate_uvs.glb", toGlb(d), &LoadStats::tangentsGenerated, 1,
                      "normal-mapped, all UVs equal: generated tangents must be finite unit vectors");
    c.check = hasTangents();
    cs.push_back(c);
  }
  {
    Doc d;
    int mat = normalMappedMaterial(d);
    quad(d, true, true, mat);
    d.finish();
    Case c = fallback("tangents_generated.glb", toGlb(d), &LoadStats::tangentsGenerated, 1, "normal-mapped without TANGENT");
    c.check = hasTangents();
    cs.push_back(c);
  }
  {
    Doc d;
    int mat = normalMappedMaterial(d);
    QuadIds q = quad(d, true, true, mat);
    int t = d.vec4(std::vector<glm::vec4>(4, {0, 0, 0, 0}));
    d.j["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] = t;
    (void)q;
    d.finish();
    Case c = fallback("zero_tangents.glb", toGlb(d), &LoadStats::badTangentsReplaced, 4, "authored TANGENT all (0,0,0,0)");
    c.check = hasTangents();
    cs.push_back(c);
  }
  {
    Doc d;
    int mat = normalMappedMaterial(d);
    quad(d, true, true, mat);
    int t = d.vec4(std::vector<glm::vec4>(4, {0, 0, 1, 1}));  // parallel to the normal
    d.j["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] = t;
    d.finish();
    Case c = fallback("tangents_parallel_to_normal.glb", toGlb(d), &LoadStats::badTangentsReplaced, 4,
                      "authored tangents equal to the normal");
    c.check = hasTangents();
    cs.push_back(c);
  }
}

// Skin weights and influences.
void weightCases(std::vector<Case>& cs) {
  using namespace detail;
  {
    Doc d;
    skinnedRibbon(d, 2, true, false);
    d.finish();
    for (int v = 0; v < 6; v += 2) pokeBin(d, 3, size_t(v), 0, 0.0f), pokeBin(d, 3, size_t(v), 1, 0.0f);
    cs.push_back(fallback("weights_zero_sum.glb", toGlb(d), &LoadStats::weightsZeroSum, 3, "three vertices with all-zero weights"));
  }
  {
    Doc d;
    skinnedRibbon(d, 2, true, false);
    d.finish();
    pokeBin(d, 3, 1, 0, 2.0f);
    cs.push_back(fallback("weights_not_normalised.glb", toGlb(d), &LoadStats::weightsRenormalised, 1, "weights summing to 2.5"));
  }
  {
    Doc d;
    skinnedRibbon(d, 2, true, false);
    d.finish();
    pokeBin(d, 3, 0, 0, nan);
    pokeBin(d, 3, 1, 1, -1.0f);
    Case c = fallback("weights_nan_negative.glb", toGlb(d), &LoadStats::weightsRenormalised, 0,
                      "a NaN and a negative weight: repaired (invariants check finite, >= 0, sum 1)");
    cs.push_back(c);
  }
  {
    Doc d;
    skinnedRibbon(d, 4, true, false);
    auto& attr = d.j["meshes"][0]["primitives"][0]["attributes"];
    std::vector<glm::u16vec4> j1(10, {3, 2, 1, 0});
    std::vector<glm::vec4> w1(10, {0.1f, 0.1f, 0.1f, 0.1f});
    attr["JOINTS_1"] = d.joints(j1);
    attr["WEIGHTS_1"] = d.vec4(w1);
    d.finish();
    cs.push_back(fallback("influences_8.glb", toGlb(d), &LoadStats::influencesTruncated, 10, "JOINTS_1/WEIGHTS_1: 8 influences per vertex"));
  }
}

// Huge finite coordinates; non-finite values without a repair.
void extremeValueCases(std::vector<Case>& cs) {
  using namespace detail;
  {
    // Huge but finite coordinates: loads; bounds arithmetic must not overflow to Inf/NaN later.
    Doc d;
    QuadIds q = quad(d);
    for (int v = 0; v < 4; ++v) pokeBin(d, q.pos, size_t(v), 0, (v & 1 ? 3e38f : -3e38f));
    d.finish();
    cs.push_back(loads("huge_positions.glb", toGlb(d), "coordinates +-3e38"));
  }
  // Non-finite values where no repair is defined: the texture lookup (UVs), vertex colour,
  // skinning matrix or node transform would be NaN on the GPU -- a silently wrong image.
  cs.push_back(error("nan_uvs.glb", glb([&](Doc& d, QuadIds& q) { pokeBin(d, q.uv, 2, 1, nan); }), {"finite", "nan", "TEXCOORD"},
                     "a NaN texture coordinate"));
  {
    Doc d;
    QuadIds q = quad(d);
    int col = d.vec4(std::vector<glm::vec4>(4, {1, 1, 1, 1}));
    d.j["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = col;
    d.finish();
    pokeBin(d, col, 3, 0, inf);
    (void)q;
    cs.push_back(error("inf_colors.glb", toGlb(d), {"finite", "inf", "COLOR"}, "an infinite vertex colour"));
  }
  {
    Doc d;
    skinnedRibbon(d, 3, true, false);
    d.finish();
    pokeBin(d, 5, 1, 13, nan);  // joint 1's inverse bind translation.y
    cs.push_back(error("nan_inverse_bind.glb", toGlb(d), {"finite", "nan", "inverse"}, "a NaN in an inverse bind matrix"));
  }
  {
    Doc d;
    quad(d);
    d.finish();
    d.j["nodes"][0]["translation"] = {1e300, 0, 0};
    cs.push_back(error("node_translation_1e300.glb", toGlb(d), {"finite", "node", "translation", "range"},
                       "translation 1e300 (infinite as float)"));
  }
  {
    Doc d;
    quad(d);
    d.finish();
    d.j["nodes"][0]["matrix"] = {1e300, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    cs.push_back(error("node_matrix_1e300.glb", toGlb(d), {"finite", "node", "matrix", "range"}, "matrix entry 1e300"));
  }
  {
    Doc d;
    quad(d);
    d.arr("cameras").push_back({{"type", "perspective"}, {"perspective", {{"yfov", 1e300}, {"znear", 0.1}}}});
    d.j["nodes"][0]["camera"] = 0;
    d.finish();
    cs.push_back(error("camera_yfov_1e300.glb", toGlb(d), {"finite", "camera", "range"}, "camera yfov 1e300"));
  }
}

}  // namespace

// Numbers: NaN/Inf, zero vectors, degenerate UVs, weights.
std::vector<Case> numericCases() { return appended({positionNormalCases, tangentCases, weightCases, extremeValueCases}); }

namespace {

// A finished quad document modified by `e` (before finish()), as .glb.
Bytes glbWith(const std::function<void(Doc&)>& e) {
  Doc d;
  quad(d);
  e(d);
  d.finish();
  return toGlb(d);
}

// Scales, matrices and rotations that are valid but degenerate.
void transformCases(std::vector<Case>& cs) {
  using namespace detail;
  {
    Case c = loads("nonuniform_scale.glb", glbWith([](Doc& d) { d.j["nodes"][0]["scale"] = {1, 2, 3}; }),
                   "node scale (1,2,3): kept as authored (the motor pipeline falls back to a matrix)");
    c.check = nodeScaleIs(0, {1, 2, 3});
    cs.push_back(c);
  }
  {
    Case c = loads("negative_scale.glb", glbWith([](Doc& d) { d.j["nodes"][0]["scale"] = {-1, 1, 1}; }), "node scale (-1,1,1): reflection");
    c.check = nodeScaleIs(0, {-1, 1, 1});
    cs.push_back(c);
  }
  {
    Case c = loads("zero_scale.glb", glbWith([](Doc& d) { d.j["nodes"][0]["scale"] = {0, 0, 0}; }), "node scale 0");
    c.check = nodeScaleIs(0, {0, 0, 0});
    cs.push_back(c);
  }
  {
    Case c = loads("matrix_reflection.glb", glbWith([](Doc& d) {
                     d.j["nodes"][0]["matrix"] = {0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 2, 0, 5, 6, 7, 1};  // swaps x/y: det < 0
                   }),
                   "node matrix with negative determinant");
    c.check = trsMatchesMatrix(0);
    cs.push_back(c);
  }
  {
    Case c = loads("matrix_shear.glb", glbWith([](Doc& d) { d.j["nodes"][0]["matrix"] = {1, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; }),
                   "node matrix with shear");
    c.check = [](const Scene& s) -> std::string { return s.nodes[0].matrixHasShear ? "" : "shear not flagged"; };
    cs.push_back(c);
  }
  {
    Case c = loads("matrix_singular.glb", glbWith([](Doc& d) { d.j["nodes"][0]["matrix"] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 3, 1}; }),
                   "all-zero 3x3 part: decomposition must not produce NaN");
    c.check = [](const Scene& s) -> std::string { return finite(s.nodes[0].local) ? "" : "NaN TRS"; };
    cs.push_back(c);
  }
  cs.push_back(loads("rotation_zero_quaternion.glb", glbWith([](Doc& d) { d.j["nodes"][0]["rotation"] = {0, 0, 0, 0}; }),
                     "rotation (0,0,0,0): must not become NaN"));
  cs.push_back(loads("rotation_unnormalised.glb", glbWith([](Doc& d) { d.j["nodes"][0]["rotation"] = {0, 0, 3, 4}; }),
                     "rotation of length 5"));
}

// Cycles, shared children and references out of range.
void nodeGraphErrorCases(std::vector<Case>& cs) {
  using namespace detail;
  cs.push_back(error("cycle_self.glb", glbWith([](Doc& d) { d.j["nodes"][0]["children"] = {0}; }), {"cycle", "parent", "own"},
                     "node 0 is its own child"));
  cs.push_back(error("cycle_two_nodes.glb", glbWith([](Doc& d) {
                       d.node({{"children", {0}}});
                       d.j["nodes"][0]["children"] = {1};
                     }),
                     {"cycle", "parent", "descendant"}, "node 0 -> 1 -> 0"));
  cs.push_back(error("cycle_unreachable.glb", glbWith([](Doc& d) {
                       d.node({{"children", {2}}});
                       d.node({{"children", {1}}});
                     }),
                     {"cycle", "parent", "descendant"}, "nodes 1 <-> 2, not in any scene"));
  cs.push_back(error("two_parents.glb", glbWith([](Doc& d) {
                       d.node({{"children", {0}}});
                       d.node({{"children", {0}}});
                       d.j["scenes"][0]["nodes"] = {1, 2};
                     }),
                     {"parent"}, "node 0 is a child of nodes 1 and 2"));
  cs.push_back(error("child_listed_twice.glb", glbWith([](Doc& d) {
                       d.node({{"children", {0, 0}}});
                       d.j["scenes"][0]["nodes"] = {1};
                     }),
                     {"parent", "child", "twice", "duplicate"}, "node 1 lists child 0 twice"));
  cs.push_back(error("child_out_of_range.glb", glbWith([](Doc& d) { d.j["nodes"][0]["children"] = {99}; }), {"node", "child"},
                     "child 99 of 1 node"));
  cs.push_back(error("scene_root_out_of_range.glb", glbWith([](Doc& d) { d.j["scenes"][0]["nodes"] = {0, 5}; }), {"node", "scene", "root"},
                     "scene lists node 5"));
  cs.push_back(error("default_scene_out_of_range.glb", glbWith([](Doc& d) { d.j["scene"] = 3; }), {"scene"}, "scene 3 of 1"));
  cs.push_back(error("node_mesh_out_of_range.glb", glbWith([](Doc& d) { d.j["nodes"][0]["mesh"] = 9; }), {"mesh"}, "node mesh 9"));
  cs.push_back(error("node_skin_out_of_range.glb", glbWith([](Doc& d) { d.j["nodes"][0]["skin"] = 2; }), {"skin"}, "node skin 2, no skins"));
  cs.push_back(error("node_camera_out_of_range.glb", glbWith([](Doc& d) { d.j["nodes"][0]["camera"] = 0; }), {"camera"},
                     "node camera 0, no cameras"));
}

// Deep chains and a file without scenes.
void hierarchyShapeCases(std::vector<Case>& cs) {
  using namespace detail;
  {
    // A 10,000-deep chain: recursion in the loader or pose code would blow the stack.
    Doc d;
    quad(d);
    const int depth = 10000;
    for (int i = 1; i < depth; ++i) {
      d.j["nodes"][i - 1]["children"] = {i};
      d.node({{"translation", {0, 0.001, 0}}});
    }
    d.finish();
    cs.push_back(loads("deep_hierarchy_10000.glb", toGlb(d), "a chain of 10,000 nodes"));
  }
  {
    // 100,000 nodes in one chain (2 MB of JSON): anything quadratic in depth hangs.
    Doc d;
    quad(d);
    const int depth = 100000;
    Json& nodes = d.j["nodes"];
    for (int i = 1; i < depth; ++i) {
      nodes[size_t(i - 1)]["children"] = {i};
      nodes.push_back(Json::object());
    }
    d.finish();
    cs.push_back(loads("deep_hierarchy_100000.glb", toGlb(d), "a chain of 100,000 nodes: must stay linear"));
  }
  {
    Doc d;
    quad(d);
    d.j["scenes"] = Json::array();
    d.j.erase("scene");
    d.finish();
    cs.push_back(loads("no_scene.glb", toGlb(d), "no scenes: nodes without a scene (roots may be empty or all parentless nodes)"));
  }
}

}  // namespace

// Transforms and the node graph.
std::vector<Case> graphCases() { return appended({transformCases, nodeGraphErrorCases, hierarchyShapeCases}); }

namespace {

// Skins: many joints, joint indices and inverse bind matrices.
void skinCases(std::vector<Case>& cs) {
  using namespace detail;
  {
    Doc d;
    skinnedRibbon(d, 1000);
    d.finish();
    Case c = loads("joints_1000.glb", toGlb(d), "one skin with 1,000 joints in a 1,000-deep chain, animated");
    c.check = [](const Scene& s) -> std::string {
      return s.skins.size() == 1 && s.skins[0].joints.size() == 1000 ? "" : "skin does not have 1000 joints";
    };
    cs.push_back(c);
  }
  {
    Doc d;
    skinnedRibbon(d, 1000, false);
    d.finish();
    cs.push_back(loads("joints_1000_flat.glb", toGlb(d), "one skin with 1,000 sibling joints"));
  }
  auto skinned = [](const std::function<void(Doc&)>& e, int joints = 3) {
    Doc d;
    skinnedRibbon(d, joints);
    d.finish();
    e(d);
    return toGlb(d);
  };
  cs.push_back(fallback("joint_index_beyond_skin.glb", skinned([](Doc& d) { pokeBin<uint16_t>(d, 2, 3, 1, 40); }),
                        &LoadStats::jointsOutOfRange, 1, "JOINTS_0 value 40 with a 3-joint skin: influence dropped, counted"));
  cs.push_back(error("skin_joint_node_out_of_range.glb", skinned([](Doc& d) { d.j["skins"][0]["joints"][1] = 500; }), {"joint", "node", "skin"},
                     "skin joint refers to node 500"));
  cs.push_back(error("skin_no_joints.glb", skinned([](Doc& d) { d.j["skins"][0]["joints"] = Json::array(); }), {"joint", "skin"},
                     "skin with an empty joints array"));
  cs.push_back(error("inverse_bind_count_mismatch.glb", skinned([](Doc& d) { d.j["accessors"][5]["count"] = 1; }), {"inverse", "bind", "count"},
                     "1 inverse bind matrix for 3 joints"));
  cs.push_back(error("inverse_bind_not_mat4.glb", skinned([](Doc& d) { d.j["accessors"][5]["type"] = "VEC4"; }), {"inverse", "bind", "mat4", "type"},
                     "inverse bind matrices of type VEC4"));
}

// Animation.
void animationCases(std::vector<Case>& cs) {
  using namespace detail;
  auto anim = [](const std::function<void(Doc&, Json&)>& e) {
    Doc d;
    skinnedRibbon(d, 3);
    d.finish();
    e(d, d.j["animations"][0]);
    return toGlb(d);
  };
  cs.push_back(error("anim_count_mismatch.glb", anim([](Doc& d, Json& a) {
                       int in = a["samplers"][0]["input"].get<int>();
                       d.j["accessors"][in]["count"] = 1;
                     }),
                     {"sampler", "count", "animation", "input", "output"}, "2 output values for 1 input time"));
  cs.push_back(error("anim_cubic_count_mismatch.glb", anim([](Doc&, Json& a) { a["samplers"][0]["interpolation"] = "CUBICSPLINE"; }),
                     {"sampler", "count", "animation", "cubic", "output"}, "CUBICSPLINE with 2 outputs for 2 keys (needs 6)"));
  cs.push_back(error("anim_bad_interpolation.glb", anim([](Doc&, Json& a) { a["samplers"][0]["interpolation"] = "QUADRATIC"; }),
                     {"interpolation", "sampler"}, "interpolation QUADRATIC"));
  cs.push_back(error("anim_target_node_out_of_range.glb", anim([](Doc&, Json& a) { a["channels"][0]["target"]["node"] = 77; }),
                     {"node", "channel", "target"}, "channel targets node 77"));
  cs.push_back(error("anim_sampler_out_of_range.glb", anim([](Doc&, Json& a) { a["channels"][0]["sampler"] = 4; }), {"sampler"},
                     "channel uses sampler 4"));
  cs.push_back(error("anim_output_wrong_type.glb", anim([](Doc& d, Json& a) {
                       int out = a["samplers"][0]["output"].get<int>();
                       d.j["accessors"][out]["type"] = "VEC3";
                     }),
                     {"rotation", "type", "output", "vec4"}, "rotation channel with VEC3 output"));
  cs.push_back(fallback("anim_times_decreasing.glb", anim([](Doc& d, Json& a) {
                          int in = a["samplers"][0]["input"].get<int>();
                          pokeBin(d, in, 0, 0, 5.0f);
                        }),
                        &LoadStats::keyframeTimesNotIncreasing, 1, "input times 5, 1: keys sorted by time, counted"));
  cs.push_back(error("anim_times_nan.glb", anim([](Doc& d, Json& a) {
                       int in = a["samplers"][0]["input"].get<int>();
                       pokeBin(d, in, 1, 0, std::numeric_limits<float>::quiet_NaN());
                     }),
                     {"time", "finite", "nan", "input"}, "input time NaN"));
  {
    Case c = fallback("anim_zero_quaternions.glb", anim([](Doc& d, Json& a) {
                        int out = a["samplers"][0]["output"].get<int>();
                        for (int k = 0; k < 2; ++k) pokeBin(d, out, size_t(k), 3, 0.0f);
                      }),
                      &LoadStats::rotationKeysNormalised, 2, "rotation keys (0,0,0,0): identity, counted; sampled poses must stay finite");
    cs.push_back(c);
  }
  {
    Case c = loads("anim_weights_path.glb", anim([](Doc&, Json& a) { a["channels"][0]["target"]["path"] = "weights"; }),
                   "weights channel on a node without morph targets: ignored, listed in Scene::unsupported");
    c.check = listsUnsupported("weights of a node without morph targets", "weights channel");
    cs.push_back(c);
  }
}

// A normal-mapped quad document modified by `e` (before finish()).
Doc textured(const std::function<void(Doc&)>& e) {
  Doc d;
  int mat = normalMappedMaterial(d);
  quad(d, true, true, mat);
  e(d);
  d.finish();
  return d;
}

// Materials and textures.
void materialCases(std::vector<Case>& cs) {
  using namespace detail;
  cs.push_back(error("texture_missing_image.glb", toGlb(textured([](Doc& d) { d.j["textures"][0]["source"] = 9; })), {"image", "source", "texture"},
                     "texture source 9, one image"));
  cs.push_back(fallback("texture_missing_image_unused.glb", toGlb(textured([](Doc& d) { d.j["textures"].push_back({{"source", 9}}); })),
                        &LoadStats::unusedTexturesWithoutImage, 1,
                        "a second texture with source 9 (one image) that no material uses (kept without image, counted)"));
  cs.push_back(error("material_texture_out_of_range.glb",
                     toGlb(textured([](Doc& d) { d.j["materials"][0]["normalTexture"]["index"] = 12; })), {"texture"},
                     "normalTexture index 12, one texture"));
  cs.push_back(error("texture_sampler_out_of_range.glb", toGlb(textured([](Doc& d) { d.j["textures"][0]["sampler"] = 3; })), {"sampler"},
                     "texture sampler 3, no samplers"));
  cs.push_back(error("primitive_material_out_of_range.glb", toGlb(textured([](Doc& d) { d.j["meshes"][0]["primitives"][0]["material"] = 5; })),
                     {"material"}, "primitive material 5, one material"));
  cs.push_back(imageFallback("image_corrupt.glb", toGlb(textured([](Doc& d) {
                       int bv = d.j["images"][0]["bufferView"].get<int>();
                       size_t off = d.j["bufferViews"][bv]["byteOffset"].get<size_t>();
                       for (size_t i = 8; i < 40; ++i) d.bin[off + i] ^= 0x5A;
                     })),
                     {"image", "decode", "png"}, "PNG with a scrambled IHDR"));
}

// Images that cannot be decoded or are out of range.
void imageCases(std::vector<Case>& cs) {
  using namespace detail;
  // A quad whose base colour texture is the given PNG bytes.
  auto withPng = [](const Bytes& pngBytes) {
    Doc d;
    int tex = d.texture(d.image(pngBytes));
    int mat = d.material({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", tex}}}}}});
    quad(d, true, true, mat);
    d.finish();
    return toGlb(d);
  };
  // A PNG header claiming 60000 x 60000 (13.4 GB decoded) with one row of data: must fail
  // (stb_image: "too large") without allocating gigabytes.
  cs.push_back(imageFallback("image_dimension_bomb.glb", withPng(png(60000, 60000, Bytes(16, 200), 4, 1)),
                             {"image", "decode", "png", "large", "size", "pixels"}, "PNG claiming 60000x60000 pixels with 16 bytes of data"));
  // 16000 x 16000 RGBA stays under stb_image's own 2^30-byte limit: without a size check of
  // its own the loader lets stb reserve ~1 GB for a file of a few hundred bytes.
  cs.push_back(imageFallback("image_dimension_bomb_1gb.glb", withPng(png(16000, 16000, Bytes(16, 200), 4, 1)),
                             {"image", "decode", "png", "large", "size", "pixels"}, "PNG claiming 16000x16000 pixels with 16 bytes of data"));
  {
    // A PNG whose IDAT chunk declares 1.1 GB in a 4 kB file (stb_image reserved it before reading).
    Bytes p = checkerPng();
    const size_t idat = 8 + 25;  // signature + IHDR chunk
    p[idat] = 0x45;
    p[idat + 1] = 0x4E;
    cs.push_back(imageFallback("image_chunk_length_1gb.glb", withPng(p), {"image", "corrupt", "png", "chunk"},
                               "PNG IDAT chunk claiming 1.1 GB"));
  }
  cs.push_back(error("image_bufferview_out_of_range.glb", toGlb(textured([](Doc& d) { d.j["images"][0]["bufferView"] = 40; })),
                     {"image", "bufferview", "buffer view"}, "image bufferView 40"));
}

// External files (written next to the .gltf by the test).
void externalFileCases(std::vector<Case>& cs) {
  using namespace detail;
  {
    Doc d = quadDoc();
    cs.push_back(error("missing_external_buffer.gltf", toGltfExternal(d, "missing_buffer_file.bin"), {"missing_buffer_file.bin"},
                       "buffer uri names a file that does not exist"));
  }
  {
    Doc d = quadDoc();
    Case c = error("external_buffer_too_short.gltf", toGltfExternal(d, "external_buffer_too_short.bin"),
                   {"size", "length", "short", "bytelength", "exceed"}, "external .bin shorter than byteLength");
    c.sidecars.push_back({"external_buffer_too_short.bin", Bytes(d.bin.begin(), d.bin.begin() + 10)});
    cs.push_back(c);
  }
  {
    Doc d = quadDoc();
    Case c = loads("external_buffer_ok.gltf", toGltfExternal(d, "external_buffer_ok.bin"), "valid .gltf + .bin pair");
    c.sidecars.push_back({"external_buffer_ok.bin", d.bin});
    cs.push_back(c);
  }
  {
    Doc d = quadDoc();
    d.j["images"] = {{{"uri", "missing_image_file.png"}}};
    d.j["textures"] = {{{"source", 0}}};
    d.j["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    d.j["meshes"][0]["primitives"][0]["material"] = 0;
    cs.push_back(imageFallback("missing_external_image.gltf", toGltfExternal(d, "missing_image_buffer.bin"), {"missing_image_file.png"},
                       "image uri names a file that does not exist"));
    cs.back().sidecars.push_back({"missing_image_buffer.bin", d.bin});
  }
  {
    Doc d = quadDoc();
    d.j["images"] = {{{"uri", "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAA"}}};
    d.j["textures"] = {{{"source", 0}}};
    d.j["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    d.j["meshes"][0]["primitives"][0]["material"] = 0;
    cs.push_back(imageFallback("image_datauri_truncated.gltf", toGltfEmbedded(d), {"image", "decode", "png"}, "image data: URI of a cut PNG"));
  }
}

// Primitives.
void primitiveCases(std::vector<Case>& cs) {
  using namespace detail;
  auto prim = [](const std::function<void(Json&)>& e) {
    Doc d;
    quad(d);
    e(d.j["meshes"][0]["primitives"][0]);
    d.finish();
    return toGlb(d);
  };
  cs.push_back(fallback("mode_points.glb", prim([](Json& p) { p["mode"] = 0; }), &LoadStats::skippedPrimitives, 1,
                        "POINTS primitive: skipped, counted, listed"));
  cs.push_back(fallback("mode_lines.glb", prim([](Json& p) { p["mode"] = 1; }), &LoadStats::skippedPrimitives, 1, "LINES primitive"));
  cs.push_back(fallback("mode_invalid.glb", prim([](Json& p) { p["mode"] = 42; }), &LoadStats::skippedPrimitives, 1, "mode 42: skipped"));
  cs.push_back(fallback("no_position.glb", prim([](Json& p) { p["attributes"].erase("POSITION"); }), &LoadStats::skippedPrimitives, 1,
                        "primitive without POSITION: skipped"));
  cs.push_back(error("index_count_not_triangles.glb", prim([](Json& p) { p["indices"] = 99; }), {"accessor", "indices"},
                     "indices accessor 99"));
  {
    Doc d;
    QuadIds q = quad(d);
    d.j["accessors"][q.idx]["count"] = 5;
    d.finish();
    // Documented fallback without a counter: the trailing indices are dropped and listed.
    Case c = loads("index_count_not_multiple_of_3.glb", toGlb(d), "TRIANGLES with 5 indices: the partial triangle is dropped and listed");
    c.check = listsUnsupported("trailing", "dropped indices");
    cs.push_back(c);
  }
  {
    Doc d;
    QuadIds q = quad(d);
    d.j["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", q.nrm}}};
    d.finish();
    Case c = loads("morph_target.glb", toGlb(d), "morph target (the normals as POSITION deltas): loaded, weight 0");
    c.check = [](const Scene& sc) -> std::string {
      const Primitive& p = sc.meshes.at(0).primitives.at(0);
      if (p.targets.size() != 1 || p.targets[0].positions.size() != p.positions.size()) return "morph target not loaded";
      return sc.meshes[0].weights == std::vector<float>{0.0f} ? "" : "default weight not 0";
    };
    cs.push_back(c);
  }
}

}  // namespace

// Skins, animation, materials, textures, images, external files, primitives.
std::vector<Case> contentCases() { return appended({skinCases, animationCases, materialCases, imageCases, externalFileCases, primitiveCases}); }

// Valid glTF 2.0 that tinygltf 2.7 refuses (pipelines/scene/repair/conformance.h)
// and the URI cases that stay errors. tests/scene/test_scene_conformance.cpp checks each
// against its plain equivalent; here they feed the hostile corpus and the fuzz seeds.
std::vector<Case> conformanceCases() {
  using namespace detail;
  std::vector<Case> cs;
  auto embedded = [](const std::function<void(Doc&, QuadIds&)>& e) { return toGltfEmbedded(quadDoc(e)); };
  {
    Doc d = quadDoc();
    std::function<void(Json&)> floatify = [&](Json& j) {
      if (j.is_number_integer()) j = j.get<double>();
      if (j.is_structured())
        for (auto& e : j) floatify(e);
    };
    floatify(d.j);
    cs.push_back(loads("whole_number_floats.glb", toGlb(d), "every integer written as a float (\"count\": 4.0)"));
  }
  {
    Case c = loads("indices_without_bufferview.glb", toGlb(quadDoc([](Doc& d, QuadIds& q) { d.j["accessors"][q.idx].erase("bufferView"); })),
                   "indices accessor without bufferView: six zero indices");
    c.check = [](const Scene& s) {
      return s.meshes.size() == 1 && s.meshes[0].primitives[0].indices == std::vector<uint32_t>(6, 0u) ? "" : "indices not six zeros";
    };
    cs.push_back(c);
  }
  {
    Doc d = quadDoc();  // finished: buffer 0 holds the quad
    d.j["buffers"].push_back({{"byteLength", 1u << 30}});
    cs.push_back(loads("unread_buffer_without_uri.gltf", toGltfEmbedded(d),
                       "a second buffer without uri (1 GiB declared) that no bufferView reads"));
  }
  {
    Doc d = quadDoc();
    d.j["buffers"].insert(d.j["buffers"].begin(), Json{{"byteLength", 64}});
    for (auto& v : d.j["bufferViews"]) v["buffer"] = 1;
    d.j["buffers"][1]["uri"] = "data:application/octet-stream;base64," + base64(d.bin);
    cs.push_back(loads("glb_placeholder_buffer.glb", glbContainer(d.j.dump(), {}), "GLB buffer 0 without uri and no BIN chunk, read by nothing"));
  }
  {
    Doc d = quadDoc();
    std::string uri = "data:application/gltf-buffer,";
    for (uint8_t b : d.bin) {
      static const char* hex = "0123456789ABCDEF";
      uri += std::string("%") + hex[b >> 4] + hex[b & 15];
    }
    d.j["buffers"][0]["uri"] = uri;
    cs.push_back(loads("datauri_percent_encoded.gltf", toBytes(d.j.dump()), "data: URI without ;base64: percent-encoded bytes (RFC 2397)"));
  }
  {
    Doc d = quadDoc();
    d.j["buffers"][0]["uri"] = "http://example.com/quad.bin";
    cs.push_back(error("buffer_uri_http.gltf", toGltfEmbedded(d), {"http"}, "buffer uri http://...: never fetched"));
  }
  cs.push_back(error("min_version_2_1.gltf", embedded([](Doc& d, QuadIds&) { d.j["asset"]["minVersion"] = "2.1"; }), {"minversion"},
                     "asset.minVersion 2.1"));
  cs.push_back(fallback("accessor_bounds_wrong.glb", toGlb(quadDoc([](Doc& d, QuadIds& q) { d.j["accessors"][q.pos]["max"] = {5, 5, 5}; })),
                        &LoadStats::accessorBoundsMismatch, 1, "POSITION max (5,5,5), data reaches (1,1,0): counted"));
  cs.push_back(fallback("camera_zfar_below_znear.glb", toGlb(quadDoc([](Doc& d, QuadIds&) {
                          d.j["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 1.0}, {"zfar", 0.5}}}}};
                          d.j["nodes"].push_back({{"camera", 0}});
                        })),
                        &LoadStats::camerasRepaired, 1, "camera zfar 0.5 below znear 1: infinite far plane, counted"));
  return cs;
}

// Compressed geometry and image formats: payloads made by the real encoders
// (tests/support/compressed_gltf.h), then broken.
std::vector<Case> compressionCases() {
  using namespace detail;
  std::vector<Case> cs;
  const Bytes quadGlb = toGlb(quadDoc());
  auto edited = [](const Bytes& glb, const std::function<void(compressed::Glb&)>& edit) {
    compressed::Glb g = compressed::splitGlb(glb);
    edit(g);
    return compressed::joinGlb(g);
  };
  const Bytes draco = compressed::dracoCompressed(quadGlb);
  auto dracoView = [](compressed::Glb& g) -> Json& {
    return g.json["bufferViews"][g.json["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["bufferView"].get<size_t>()];
  };
  {
    Case c = loads("draco_quad.glb", draco, "the quad through Draco's encoder (valid; decoded)");
    c.check = [](const Scene& s) { return s.compression.dracoPrimitives == 1 ? "" : "Draco primitive not decoded"; };
    cs.push_back(c);
  }
  cs.push_back(error("draco_payload_garbage.glb", edited(draco, [&](compressed::Glb& g) {
                       const Json& v = dracoView(g);
                       for (size_t i = 0; i < v["byteLength"].get<size_t>(); ++i) g.bin[v["byteOffset"].get<size_t>() + i] = uint8_t(i * 151 + 7);
                     }),
                     {"Draco data does not decode"}, "Draco payload overwritten with pseudo-random bytes"));
  cs.push_back(error("draco_payload_truncated.glb", edited(draco, [&](compressed::Glb& g) {
                       Json& v = dracoView(g);
                       v["byteLength"] = v["byteLength"].get<size_t>() / 2;
                     }),
                     {"Draco data does not decode"}, "Draco bufferView cut to half the stream"));
  cs.push_back(fallback("draco_count_mismatch.glb", edited(draco, [](compressed::Glb& g) { g.json["accessors"][0]["count"] = 5; }),
                        &LoadStats::dracoCountMismatch, 1,
                        "POSITION declares 5 vertices, the Draco stream holds 4 (the decoded 4 drawn, as three.js does; counted)"));
  cs.push_back(error("draco_attribute_id_missing.glb", edited(draco, [](compressed::Glb& g) {
                       g.json["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]["NORMAL"] = 42;
                     }),
                     {"no attribute with id 42"}, "NORMAL names Draco attribute id 42, which the stream lacks"));
  cs.push_back(error("draco_type_mismatch.glb", edited(draco, [](compressed::Glb& g) { g.json["accessors"][1]["type"] = "VEC2"; }),
                     {"the Draco data has 4 of 3"}, "NORMAL declared VEC2, the Draco attribute has 3 components"));

  const Bytes meshopt = compressed::meshoptCompressed(quadGlb);
  auto meshoptExt = [](compressed::Glb& g) -> Json& {
    for (Json& v : g.json["bufferViews"])
      if (v.contains("extensions")) return v["extensions"]["EXT_meshopt_compression"];
    throw std::runtime_error("no meshopt view");
  };
  {
    Case c = loads("meshopt_quad.glb", meshopt, "the quad through meshoptimizer's encoder; the fallback buffer has no data");
    c.check = positionsEqual(quadPositions());
    cs.push_back(c);
  }
  cs.push_back(error("meshopt_payload_garbage.glb", edited(meshopt, [&](compressed::Glb& g) {
                       const Json& e = meshoptExt(g);
                       for (size_t i = 0; i < e["byteLength"].get<size_t>(); ++i) g.bin[e["byteOffset"].get<size_t>() + i] = 0xFF;
                     }),
                     {"data does not decode"}, "meshopt vertex stream overwritten with 0xFF"));
  cs.push_back(error("meshopt_bad_stride.glb", edited(meshopt, [&](compressed::Glb& g) { meshoptExt(g)["byteStride"] = 6; }),
                     {"byteStride 6"}, "ATTRIBUTES byteStride 6 (not a multiple of 4)"));
  cs.push_back(error("meshopt_count_huge.glb", edited(meshopt, [&](compressed::Glb& g) { meshoptExt(g)["count"] = uint64_t(1) << 30; }),
                     {"limit"}, "count 2^30: would decode to 12 GiB"));
  cs.push_back(error("meshopt_source_outside_buffer.glb", edited(meshopt, [&](compressed::Glb& g) { meshoptExt(g)["byteOffset"] = 1u << 30; }),
                     {"lies outside buffer"}, "compressed bytes claimed at 1 GiB into a small buffer"));
  cs.push_back(error("meshopt_unknown_filter.glb", edited(meshopt, [&](compressed::Glb& g) { meshoptExt(g)["filter"] = "WAVELET"; }),
                     {"filter 'WAVELET'"}, "filter WAVELET (not in the extension)"));

  {  // WebP whose RIFF size runs past the image data: not decoded, counted.
    Doc d;
    Bytes webp = compressed::losslessWebp(2, 2, Bytes(16, 200));
    put32(webp, 4, uint32_t(webp.size() + 64));
    const int img = d.image(webp);
    d.j["images"][size_t(img)]["mimeType"] = "image/webp";
    const int tex = d.push(d.arr("textures"), Json{{"extensions", {{"EXT_texture_webp", {{"source", img}}}}}});
    quad(d, true, true, d.material({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", tex}}}}}}));
    d.finish();
    cs.push_back(imageFallback("webp_riff_size_beyond_data.glb", toGlb(d), {"truncated WebP"},
                               "WebP RIFF size 64 bytes beyond the image data"));
  }
  {  // A texture whose only source is KTX2 (KHR_texture_basisu): no decoder, counted.
    Doc d;
    const int img = d.image(Bytes{0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n'});
    d.j["images"][size_t(img)]["mimeType"] = "image/ktx2";
    const int tex = d.push(d.arr("textures"), Json{{"extensions", {{"KHR_texture_basisu", {{"source", img}}}}}});
    quad(d, true, true, d.material({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", tex}}}}}}));
    d.finish();
    Case c = fallback("basisu_texture_only.glb", toGlb(d), &LoadStats::basisuTexturesNotDecoded, 1,
                      "texture whose only source is KTX2 (KHR_texture_basisu): drawn untextured, counted, listed");
    c.check = listsUnsupported("KHR_texture_basisu (KTX2) not decoded", "basisu fallback");
    cs.push_back(c);
  }
  return cs;
}

// EXT_mesh_gpu_instancing on the quad's node: per-instance TRANSLATION / ROTATION / SCALE.
std::vector<Case> instancingCases() {
  using namespace detail;
  std::vector<Case> cs;
  // The quad drawn as three instances; `edit` may change the accessors or the extension.
  auto instanced = [](const std::function<void(Doc&, Json& attributes)>& edit) {
    return toGlb(quadDoc([&](Doc& d, QuadIds&) {
      Json attributes = {{"TRANSLATION", d.vec3({{0, 0, 0}, {3, 0, 0}, {6, 0, 0}})},
                         {"ROTATION", d.vec4({{0, 0, 0, 1}, {0, 0.70710678f, 0, 0.70710678f}, {0, 0, 0, 1}})},
                         {"SCALE", d.vec3({{1, 1, 1}, {2, 2, 2}, {1, 0.5f, 1}})}};
      edit(d, attributes);
      d.j["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"] = {{"attributes", attributes}};
      d.j["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
    }));
  };
  {
    Case c = loads("instancing_valid.glb", instanced([](Doc&, Json&) {}), "three instances: drawn three times");
    c.check = [](const Scene& s) {
      const auto& in = s.nodes[0].instances;
      if (in.size() != 3) return std::string("expected 3 instances");
      if (in[1].translation != glm::vec3(3, 0, 0) || in[1].scale != glm::vec3(2) || in[2].scale != glm::vec3(1, 0.5f, 1))
        return std::string("instance TRS not as written");
      return std::string(std::abs(in[1].rotation.y - 0.70710678f) < 1e-6f ? "" : "rotation not as written");
    };
    cs.push_back(c);
  }
  {
    // ROTATION as normalized SHORT (allowed by the extension): 32767 reads as 1.
    Case c = loads("instancing_rotation_short.glb", instanced([](Doc& d, Json& a) {
                     const std::vector<int16_t> q = {0, 0, 0, 32767, 0, 0, 32767, 0, 0, 0, 0, 32767};
                     int bv = d.view(q.data(), q.size() * 2);
                     int acc = d.accessor(bv, kShort, 3, "VEC4");
                     d.j["accessors"][acc]["normalized"] = true;
                     a["ROTATION"] = acc;
                   }),
                   "instance ROTATION as normalized int16");
    c.check = [](const Scene& s) {
      const auto& in = s.nodes[0].instances;
      return in.size() == 3 && in[1].rotation == glm::quat(0, 0, 0, 1) ? "" : "int16 rotation not decoded to (0,0,1,0)";
    };
    cs.push_back(c);
  }
  cs.push_back(error("instancing_count_mismatch.glb", instanced([](Doc& d, Json& a) { a["SCALE"] = d.vec3({{1, 1, 1}, {1, 1, 1}}); }),
                     {"counts must agree"}, "SCALE has 2 instances, TRANSLATION and ROTATION 3"));
  cs.push_back(error("instancing_rotation_vec3.glb", instanced([](Doc& d, Json& a) { a["ROTATION"] = d.vec3({{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}); }),
                     {"ROTATION accessor", "VEC4"}, "ROTATION accessor of type VEC3"));
  cs.push_back(error("instancing_rotation_unnormalized_short.glb", instanced([](Doc& d, Json& a) {
                       const std::vector<int16_t> q(12, 0);
                       a["ROTATION"] = d.accessor(d.view(q.data(), q.size() * 2), kShort, 3, "VEC4");
                     }),
                     {"ROTATION accessor", "normalized"}, "ROTATION as int16 without normalized"));
  cs.push_back(error("instancing_translation_nan.glb", instanced([](Doc& d, Json& a) {
                       pokeBin(d, a["TRANSLATION"].get<int>(), 1, 0, std::numeric_limits<float>::quiet_NaN());
                     }),
                     {"non-finite"}, "TRANSLATION of instance 1 is NaN"));
  cs.push_back(error("instancing_missing_accessor.glb", instanced([](Doc&, Json& a) { a["SCALE"] = 99; }),
                     {"does not exist"}, "SCALE names accessor 99"));
  cs.push_back(error("instancing_no_attributes.glb", instanced([](Doc&, Json& a) { a = Json::object(); }),
                     {"no attributes"}, "the extension without any attribute"));
  cs.push_back(fallback("instancing_zero_rotation.glb", instanced([](Doc& d, Json& a) {
                          pokeBin(d, a["ROTATION"].get<int>(), 2, 3, 0.0f);
                        }),
                        &LoadStats::instanceRotationsNormalised, 1, "instance ROTATION (0,0,0,0): identity, counted"));
  {
    Doc d;
    skinnedRibbon(d, 3);
    d.j["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"] = {{"attributes", {{"TRANSLATION", d.vec3({{0, 0, 0}, {2, 0, 0}})}}}};
    d.finish();
    Case c = fallback("instancing_skinned.glb", toGlb(d), &LoadStats::instancingDrawnOnce, 1,
                      "instancing on a skinned node: drawn once, counted and listed");
    c.check = [](const Scene& s) { return s.nodes[0].instances.empty() ? "" : "a skinned node kept its instances"; };
    cs.push_back(c);
  }
  return cs;
}

// Every hand-made case.
std::vector<Case> allCases() {
  std::vector<Case> all;
  for (auto part : {containerCases, jsonCases, accessorCases, numericCases, graphCases, contentCases, conformanceCases,
                    compressionCases, instancingCases}) {
    auto v = part();
    for (auto& c : v) all.push_back(std::move(c));
  }
  return all;
}

}  // namespace mb::hostile
