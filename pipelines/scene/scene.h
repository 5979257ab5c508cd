// The pipeline-neutral Scene: what the glTF loader produces and every pipeline consumes.
// Attributes are decoded into tight float streams; transforms are kept as authored (TRS or
// matrix). Nothing here is pipeline-specific: each pipeline's prepare() converts it.
#pragma once
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace mb {

struct TRS {
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // glm order (w, x, y, z)
  glm::vec3 scale{1.0f};
};

struct Node {
  std::string name;
  TRS local;                      // rest pose; decomposed from `matrix` when authored as one
  bool hasMatrix = false;         // authored as a 4x4 matrix
  glm::mat4 matrix{1.0f};         // as authored (column-major, glTF convention)
  bool matrixHasShear = false;    // matrix not representable exactly as TRS
  int parent = -1;
  std::vector<int> children;
  int mesh = -1, skin = -1, camera = -1;
  // EXT_mesh_gpu_instancing (gltf_instancing.cpp) or `--instances N` (instancing.h): the mesh
  // is drawn once per entry, instance i at node world * instances[i]; empty: drawn once at the
  // node's world. Never set on a skinned node or a Bezier patch mesh (instancing.h).
  std::vector<TRS> instances;
  // Morph target weights authored on the node (glTF `weights`); empty: the mesh's apply.
  std::vector<float> weights;
};

// One morph target of a primitive (glTF 2.0 3.7.2.2): per-vertex deltas added, weighted, to
// the base streams before any transform or skin. Each stream has one entry per vertex of the
// primitive after hygiene (a vertex the loader split carries its source's deltas) or is empty
// when the target does not morph that attribute. Tangent deltas are xyz (w is never morphed).
struct MorphTarget {
  std::vector<glm::vec3> positions, normals, tangents;
};

struct Primitive {
  // Streams all have positions.size() entries (or are empty when absent).
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;     // always filled after loading (flat normals generated)
  std::vector<glm::vec4> tangents;    // xyz + handedness w in {-1,+1}; filled when the
                                      // material is normal-mapped (generated if absent)
  std::vector<glm::vec2> uv0, uv1;
  std::vector<glm::vec4> colors;      // COLOR_0 as RGBA
  std::vector<glm::u16vec4> joints;   // JOINTS_0 (at most 4 influences kept)
  std::vector<glm::vec4> weights;     // WEIGHTS_0, L1-normalised
  std::vector<uint32_t> indices;      // triangle list; generated 0..n-1 when not indexed
  int material = -1;                  // -1: default material
  bool hadTangents = false;           // TANGENT was authored
  bool generatedNormals = false;
  bool generatedTangents = false;
  // Bicubic Bezier patches (a .bpt file, or a glTF primitive with MB_bezier_patches): 16
  // control points per patch, row by row (point 4 * row + column; u runs along a row, v across
  // the rows). Such a primitive has no vertex streams; pipelines tessellate it
  // (pipelines/scene/bezier.h). Empty for ordinary triangle primitives.
  std::vector<glm::vec3> patchPoints;
  // Morph targets (all primitives of a mesh have the same number, glTF 2.0 3.7.2.2).
  std::vector<MorphTarget> targets;
};

struct Mesh {
  std::string name;
  std::vector<Primitive> primitives;
  // Default morph weights (glTF mesh `weights`), one per target; zeros when not authored.
  std::vector<float> weights;
};

// Targets of the mesh (its first primitive's; every primitive has the same count).
inline size_t morphTargetCount(const Mesh& m) {
  return m.primitives.empty() ? 0 : m.primitives.front().targets.size();
}

// KHR_texture_transform on a textureInfo: uv' = T(offset) * R(rotation) * S(scale) * (uv, 1).
// R turns the uvs counter-clockwise as seen in uv space, whose v axis points down: u' = cos u +
// sin v, v' = -sin u + cos v (https://github.com/KhronosGroup/glTF/issues/1563; three.js, Babylon.js and the Sample Viewer; the
// GLSL listing of the extension's README has the opposite sign).
struct UvTransform {
  glm::vec2 offset{0.0f};
  float rotation = 0.0f;  // radians
  glm::vec2 scale{1.0f};
};

struct TextureRef {
  int texture = -1;    // index into Scene::textures, -1 = none
  int texCoord = 0;    // which TEXCOORD_n (KHR_texture_transform's texCoord when it has one)
  float scale = 1.0f;  // normalTexture.scale or occlusionTexture.strength
  bool hasTransform = false;  // KHR_texture_transform present (false: uvs sampled as they are)
  UvTransform transform;
};

// The 3x3 matrix (column-major, glm) of a UvTransform: what forward.fs multiplies (uv, 1) by.
inline glm::mat3 uvTransformMatrix(const UvTransform& t) {
  const float c = std::cos(t.rotation), s = std::sin(t.rotation);
  return glm::mat3(c * t.scale.x, -s * t.scale.x, 0.0f,  // column 0: R * S * (1, 0)
                   s * t.scale.y, c * t.scale.y, 0.0f,   // column 1: R * S * (0, 1)
                   t.offset.x, t.offset.y, 1.0f);        // column 2: the offset
}

enum class AlphaMode { Opaque, Mask, Blend };

struct Material {
  std::string name;
  glm::vec4 baseColorFactor{1.0f};
  float metallicFactor = 1.0f, roughnessFactor = 1.0f;
  glm::vec3 emissiveFactor{0.0f};  // times KHR_materials_emissive_strength's emissiveStrength
  TextureRef baseColor, metallicRoughness, normal, occlusion, emissive;
  AlphaMode alphaMode = AlphaMode::Opaque;
  float alphaCutoff = 0.5f;
  bool doubleSided = false;
};

struct Sampler {  // GL enums; glTF defaults
  int magFilter = 0x2601;  // GL_LINEAR
  int minFilter = 0x2703;  // GL_LINEAR_MIPMAP_LINEAR
  int wrapS = 0x2901, wrapT = 0x2901;  // GL_REPEAT
};

struct Image {
  std::string name;
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // width*height*4, decoded
};

struct Texture {
  int image = -1, sampler = -1;  // sampler -1: default Sampler
};

struct Skin {
  std::string name;
  std::vector<int> joints;              // node indices
  std::vector<glm::mat4> inverseBind;   // one per joint (identity when absent)
  int skeleton = -1;
};

enum class AnimPath { Translation, Rotation, Scale, Weights };
enum class Interpolation { Linear, Step, CubicSpline };

struct Channel {
  int node = -1;
  AnimPath path = AnimPath::Translation;
  Interpolation interpolation = Interpolation::Linear;
  std::vector<float> times;
  // Packed keyframe values: 3 floats per key (T, S), 4 (R, glTF order x,y,z,w) or, for
  // Weights, `weightCount` (the node's mesh's morph target count).
  // CUBICSPLINE: per key [in-tangent, value, out-tangent], as glTF stores them.
  std::vector<float> values;
  int weightCount = 0;  // Weights channels only
};

struct Animation {
  std::string name;
  std::vector<Channel> channels;
  float duration = 0.0f;  // max input time
};

// Loaded values are the repaired ones (LoadStats::camerasRepaired): perspective znear <= 0 ->
// 0.01, yfov outside (0, pi) -> 0.8, a zfar <= znear -> 0 (infinite); orthographic znear < 0 ->
// 0, zfar <= znear -> 0.
struct Camera {
  std::string name;
  bool perspective = true;
  float yfov = 0.8f, aspect = 0.0f, znear = 0.1f, zfar = 100.0f;  // aspect 0: viewport's;
                                                                  // zfar 0 (loaded): infinite
  float xmag = 1.0f, ymag = 1.0f;                                 // orthographic
};

// What the loader had to do to the data; each counter is reported by `inspect`.
struct LoadStats {
  int flatNormalsGenerated = 0;       // primitives without NORMAL
  int tangentsGenerated = 0;          // normal-mapped primitives without TANGENT
  int badNormalsReplaced = 0;         // zero-length / NaN normals (vertices)
  int badTangentsReplaced = 0;        // zero-length / NaN / parallel tangents (vertices)
  int weightsRenormalised = 0;        // vertices whose weights did not sum to 1
  int weightsZeroSum = 0;             // vertices with all-zero weights (bound to joint 0)
  int influencesTruncated = 0;        // vertices with > 4 influences (JOINTS_1...)
  int nonFinitePositions = 0;         // NaN / Inf positions (vertices, set to 0)
  int skippedPrimitives = 0;          // non-triangle modes etc. (listed in unsupported)
  int normalsRenormalised = 0;        // normals whose length differed from 1 by > 1e-3
  int jointsOutOfRange = 0;           // influences naming a joint the skin lacks (weight 0)
  int stripsFansConverted = 0;        // TRIANGLE_STRIP / TRIANGLE_FAN primitives -> lists
  int degenerateUvTriangles = 0;      // tangent generation: triangles with zero uv area
  int tangentSplitVertices = 0;       // vertices duplicated because corners disagree in w
  int imagesNotDecoded = 0;           // images replaced by 1x1 white (listed in unsupported)
  // Invalid but drawable (glTF 2.0 forbids them; drawn with the repair the glossary states).
  int accessorBoundsMismatch = 0;     // accessors whose min/max disagree with their data (ignored)
  int keyframeTimesNotIncreasing = 0; // channels whose input times do not strictly increase (sorted)
  int rotationKeysNormalised = 0;     // rotation keyframes off unit length by > 0.00769 (normalised)
  int camerasRepaired = 0;            // cameras with zfar <= znear, bad znear or yfov (Camera)
  int binChunkUnaligned = 0;          // GLB BIN chunk length not a multiple of 4 (padded with zeros)
  int basisuTexturesNotDecoded = 0;   // KHR_texture_basisu sources (no decoder): fallback image or white
  // Invalid files three.js and the Khronos Sample Viewer draw, drawn as they do.
  int dracoCountMismatch = 0;         // Draco primitives whose decoded count differs from an accessor's (decoded used)
  int jsonChunkUnpadded = 0;          // GLB JSON chunk length not a multiple of 4 (read as three.js reads it)
  int unusedTexturesWithoutImage = 0; // textures no material uses whose source image does not exist (kept without)
  // EXT_mesh_gpu_instancing (gltf_instancing.cpp).
  int instanceRotationsNormalised = 0;  // instance ROTATIONs off unit length by > 0.00769
  int instancingDrawnOnce = 0;          // instanced skinned / Bezier patch nodes: drawn once
  // Real files other viewers load: drawn as three.js draws them (gltf_nodes.cpp), from the
  // image or bytes there are (gltf_materials.cpp, accessors.cpp), or named because nothing of
  // them can be drawn (gltf_mesh.cpp). The glossary says how each is drawn.
  int rootsWithParent = 0;              // scene roots that have a parent: drawn as roots, once
  int webpTexturesWithoutSource = 0;    // EXT_texture_webp naming no image: the texture's own source used
  int accessorsPastBufferView = 0;      // accessors reading past their bufferView, inside its buffer
  int zeroAreaPrimitives = 0;           // triangle primitives whose every triangle has zero area
};

// Geometry and images the loader decoded from a compression or image-format extension
// (draco_decode.cpp, meshopt_decode.cpp, image_decode.cpp); `inspect` shows them. Bytes are
// those of the compressed payloads read and of the decoded data they produced.
struct CompressionStats {
  int dracoPrimitives = 0;          // KHR_draco_mesh_compression primitives decoded
  uint64_t dracoCompressedBytes = 0, dracoDecodedBytes = 0;
  int meshoptViews = 0;             // EXT_/KHR_meshopt_compression bufferViews decoded
  uint64_t meshoptCompressedBytes = 0, meshoptDecodedBytes = 0;
  int webpImages = 0;               // EXT_texture_webp images decoded
};

// A primitive the loader did not turn into geometry, and why ("mode 1 (lines)", ...).
struct SkippedPrimitive {
  int mesh = -1, primitive = -1;
  std::string reason;
};

// Curved space: spherical S3 and hyperbolic H3 scenes, built in code (glTF has no
// curved space). Points are vec4 (x, y, z, w) on the quadric x^2+y^2+z^2 + kappa w^2 = kappa
// (kappa = +1: S3, -1: H3, origin (0,0,0,1)); normals are tangent vectors there. Isometries
// are 4x4 matrices (O(4) / O(3,1)) as the scene's generator made them, in double; each
// pipeline converts them to its own form (a motor pipeline to motors) in prepare().
enum class Space { Euclidean, Spherical, Hyperbolic };

// A rotation of the coordinate plane (i, j) of R^4 by angle0 + rate * t: j < 3 turns e_i
// towards e_j; j = 3 moves the origin towards +e_i by that distance (S3: a rotation, H3: a
// boost). The camera's pose (camera -> world) is the product of its moves, first one leftmost.
struct CurvedMove {
  int i = 0, j = 1;
  double angle0 = 0.0, rate = 0.0;
};

struct CurvedScene {
  Space space = Space::Euclidean;           // Euclidean: not a curved scene (every glTF)
  std::vector<glm::vec4> positions;         // triangle list shared by every instance
  std::vector<glm::vec4> normals;           // tangent at each position, unit in the form
  std::vector<glm::dmat4> instances;        // object -> world isometry per instance
  std::vector<glm::vec4> lights;            // 3 point lights (world), red / green / blue
  float lightStrength = 0.3f;               // diffuse factor of each light
  std::vector<CurvedMove> camera;           // camera -> world at time t (AnimState::time)
  float yfov = 1.5707964f;                  // vertical field of view
};

// The automatic camera's rule for a scene (camera_rule.h, frameScene): Fit, the default, fits
// the posed vertices to the frame (a flat scene seen from its front); BoundingSphere frames
// their padded bounding sphere, the rule the built-in scenes' goldens and committed figures were
// made with (loadScene sets it for them).
enum class Framing { Fit, BoundingSphere };

struct Scene {
  std::string source;  // file path or built-in name
  Framing framing = Framing::Fit;
  std::vector<Node> nodes;
  std::vector<int> roots;  // root nodes of the default (or first) scene
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<Sampler> samplers;
  std::vector<Image> images;
  std::vector<Skin> skins;
  std::vector<Animation> animations;
  std::vector<Camera> cameras;
  std::vector<std::string> unsupported;  // features present but not rendered, one line each
  LoadStats stats;
  CompressionStats compression;
  std::vector<SkippedPrimitive> skipped;  // also listed in `unsupported`, counted in stats
  CurvedScene curved;  // space != Euclidean: a curved-space scene (no nodes or meshes)
  // Refinement-pattern level N at which pipelines tessellate patch primitives: a uv grid of
  // (N+1)^2 vertices and 2 N^2 triangles drawn once per patch. A render setting the caller may
  // change before prepare() (`motorbench time --level N`).
  int patchLevel = 16;
};

// The skin of node n when it is drawn skinned (a mesh and a valid skin index), else null.
inline const Skin* drawnSkin(const Scene& scene, size_t n) {
  const Node& node = scene.nodes[n];
  return node.mesh >= 0 && node.skin >= 0 && size_t(node.skin) < scene.skins.size() ? &scene.skins[size_t(node.skin)]
                                                                                      : nullptr;
}

}  // namespace mb
