#include "harness/render/counter_glossary.h"

#include "pipelines/scene/scene_stats.h"

namespace mb {

const std::vector<CounterEntry>& counterGlossary() {
  static const std::vector<CounterEntry> g = {
      // PipelineStats (pipelines/pipeline.h): measured from the pipeline's own uploads and draws.
      {"PipelineStats", "vertexBytes", "bytes", "vertex buffer bytes of the shading attributes (position, normal/tangent frame or tangent rotor, uv0) as uploaded"},
      {"PipelineStats", "skinVertexBytes", "bytes", "vertex buffer bytes of the skinning attributes (joints, weights)"},
      {"PipelineStats", "extraVertexBytes", "bytes", "optional streams uploaded only when the file has them (uv1, vertex colour)"},
      {"PipelineStats", "indexBytes", "bytes", "index buffer bytes"},
      {"PipelineStats", "textureBytes", "bytes", "texture bytes handed to glTexImage2D (RGBA8, level 0; the mipmaps the driver generates are not counted)"},
      {"PipelineStats", "uniformBytesPerFrame", "bytes", "per-frame plus per-draw uniform bytes of the last render (transforms: matrices or motors)"},
      {"PipelineStats", "patchBytes", "bytes", "Bezier patch control points uploaded (16 x 3 floats per patch, GL_RGB32F buffer texture; 0 without patches)"},
      {"PipelineStats", "patchPatternBytes", "bytes", "the Bezier patches' shared (u, v) refinement pattern, (level + 1)^2 x 2 floats, drawn instanced per patch; not a vertex format, so counted neither in vertexBytes nor in vertices"},
      {"PipelineStats", "skinBytesPerFrame", "bytes", "joint palette bytes of the last update (matrices or motors per joint)"},
      {"PipelineStats", "vertices", "vertices", "vertices uploaded"},
      {"PipelineStats", "instanceBytes", "bytes", "per-instance transforms of the last render (EXT_mesh_gpu_instancing or --instances), streamed once per frame as vertex attributes with divisor 1: what the pipeline uploads per draw, node world x instance composed on the CPU (matrix: model + normal mat4; affine, qtangent, hybrid: mat4x3 + mat3 + mirror; motor, motor_q: motor + scale, a vec3 scale on the fallback)"},
      {"PipelineStats", "instances", "instances", "instances whose transforms instanceBytes holds (instanceBytes / instances = bytes per instance)"},
      {"PipelineStats", "drawnVertices", "vertices", "vertices the last render drew: each draw's vertices times its instances (Bezier patches: the refinement pattern's vertices per patch)"},
      {"PipelineStats", "floatsPerVertex", "floats", "shading-attribute floats per vertex, from the upload stride"},
      {"PipelineStats", "floatsPerTransform", "floats", "floats per node transform sent to the GPU (transform uniform bytes / 4 / transforms); 0 when none is sent (every draw skinned and the pipeline's palette moves the mesh, or every draw instanced: the report shows \"none\")"},
      {"PipelineStats", "floatsPerTransformWithScale", "floats", "floats per node transform including the per-draw scale uniform it needs (motor: 8 + 1 scale; a pipeline without one: floatsPerTransform)"},
      {"PipelineStats", "normalMappedVertexBytes", "bytes", "the part of vertexBytes uploaded for primitives whose material has a normal texture (the paper's 12-vs-9 floats case)"},
      {"PipelineStats", "normalMappedVertices", "vertices", "the part of vertices uploaded for primitives whose material has a normal texture"},
      {"PipelineStats", "floatsPerJoint", "floats", "floats per joint of the skin palette (0 without skins)"},
      {"PipelineStats", "draws", "draw calls", "draw calls of the last render"},
      {"PipelineStats", "conversionMs", "ms", "load-time conversion inside prepare (CPU, wall clock; e.g. frames to tangent rotors)"},
      {"PipelineStats", "updateMs", "ms", "the last update: sampling, hierarchy, skin palette (CPU, wall clock)"},
      {"PipelineStats", "updateSamplingMs", "ms", "phase of the last update timed by phase; null when not timed (render, compare and the report never time phases; `motorbench time` times them apart from the whole update: `update_phases_ms`; the report's timing section shows them): keyframe search and interpolation of each animation posed"},
      {"PipelineStats", "updateBlendingMs", "ms", "the same update: mixing the two animations of a blend (matrix pipelines: TRS slerp; motor pipelines: motor blend + normalize)"},
      {"PipelineStats", "updateConversionMs", "ms", "the same update: per-frame representation changes (sampled TRS to local matrix or motor with its scale check; affine: mat4 to mat4x3; hybrid: motors to mat4x3)"},
      {"PipelineStats", "updateHierarchyMs", "ms", "the same update: world transforms, parent world x local in parent-first order"},
      {"PipelineStats", "updatePaletteMs", "ms", "the same update: skin palettes, joint world x inverse bind (matrix: also the mesh-node inverse and the normal matrices)"},
      {"PipelineStats", "nonUniformScaleNodes", "nodes", "motor pipeline: nodes with non-uniform scale, carried by the per-leaf scale fallback (exact on leaves, approximated on inner nodes and joints)"},
      {"PipelineStats", "negativeScaleNodes", "nodes", "motor pipeline: nodes with a negative scale component (mirrored; matrix: det < 0)"},
      {"PipelineStats", "shearMatrixNodes", "nodes", "motor pipeline: authored matrices with shear, replaced by the nearest rotation and mean scale"},
      {"PipelineStats", "zeroScalarFrames", "vertices", "motor pipeline: tangent frames whose rotor scalar was exactly 0 (a 180-degree turn of the basis frame); handedness is kept by the sign bit and |scalar| raised to 1/32767 so it survives packing"},
      {"PipelineStats", "biasedFrames", "vertices", "int16 frame formats (qtangent, motor_q, hybrid): frames whose scalar |s| (rotor) or |w| (quaternion) the bias rule raised to 1/32767 so the handedness sign survives packing"},
      {"PipelineStats", "scaleFallbackInstances", "instances", "motor pipelines: instances of the last render whose scale (node world x instance) is non-uniform or negative, drawn with the per-leaf scale fallback (MB_SCALE_FALLBACK, a vec3 scale per instance)"},
      {"PipelineStats", "rotorSplitVertices", "vertices", "motor_cf: vertices duplicated so that every triangle's three tangent rotors lie in one hemisphere and interpolate without passing through zero (a rotor field around a torus' tube comes back negated)"},
      {"PipelineStats", "rotorUnresolvedTriangles", "triangles", "motor_cf: triangles whose corner frames differ by more than 180 degrees, so no choice of signs keeps all three rotors in one hemisphere; drawn after the others with the frame extracted per vertex (motor_c's way, the scale-fallback program) instead of an interpolated rotor (an interpolated rotor would be shortened)"},
      {"PipelineStats", "linearFallbackDraws", "draws", "motor pipelines, exact fallback: rigid draws of the last render whose world transform is not a similarity (non-uniform or sheared, inherited from an inner node), drawn with a general linear part before the motor"},
      {"PipelineStats", "skinFallbackDraws", "draws", "motor pipelines, exact fallback: skinned draws of the last render whose joint palette is not one common uniform scale (per-joint scales, scaled or sheared joints)"},
      {"PipelineStats", "skinFallbackJoints", "joints", "motor pipelines, exact fallback: the joints of the palettes of those skinned draws"},
      {"PipelineStats", "morphNotDrawnNodes", "nodes", "drawn nodes with a non-zero morph weight that this pipeline drew in their base shape (it morphed no draw; every glTF pipeline morphs, so 0 unless one regresses)"},
      {"PipelineStats", "fallbackVertices", "vertices", "motor pipelines, exact fallback: the vertices the linear and skin fallback draws of the last render drew (0 for pipelines that need no fallback)"},
      {"PipelineStats", "skinFallbackVertices", "vertices", "motor pipelines, exact fallback: of fallbackVertices, those the skin fallback draws drew (their vertex shader blends linear parts too)"},
      // LoadStats (pipelines/scene/scene.h): what the loader had to fix; `inspect` lists them.
      {"LoadStats", "flatNormalsGenerated", "primitives", "primitives without NORMAL: flat normals generated"},
      {"LoadStats", "tangentsGenerated", "primitives", "normal-mapped primitives without TANGENT: tangents generated from the uvs"},
      {"LoadStats", "badNormalsReplaced", "vertices", "zero-length or NaN normals replaced"},
      {"LoadStats", "badTangentsReplaced", "vertices", "zero-length, NaN or normal-parallel tangents replaced"},
      {"LoadStats", "weightsRenormalised", "vertices", "skin weights that did not sum to 1, rescaled"},
      {"LoadStats", "weightsZeroSum", "vertices", "all skin weights 0: bound to joint 0"},
      {"LoadStats", "influencesTruncated", "vertices", "more than 4 influences (JOINTS_1...): the 4 largest kept"},
      {"LoadStats", "nonFinitePositions", "vertices", "NaN or infinite positions, set to 0"},
      {"LoadStats", "skippedPrimitives", "primitives", "primitives not drawn (points, lines, no POSITION; each listed under unsupported with its reason); a file that draws nothing is refused by render, compare and time"},
      {"LoadStats", "normalsRenormalised", "vertices", "normals whose length differed from 1 by more than 1e-3, normalised"},
      {"LoadStats", "jointsOutOfRange", "influences", "influences naming a joint the skin lacks, given weight 0"},
      {"LoadStats", "stripsFansConverted", "primitives", "TRIANGLE_STRIP / TRIANGLE_FAN primitives converted to triangle lists"},
      {"LoadStats", "degenerateUvTriangles", "triangles", "tangent generation: triangles with zero uv area (no tangent contribution)"},
      {"LoadStats", "tangentSplitVertices", "vertices", "vertices duplicated because their triangles disagree in tangent handedness"},
      {"LoadStats", "imagesNotDecoded", "images", "images that could not be decoded, sampled as 1x1 white (listed under unsupported)"},
      {"LoadStats", "accessorBoundsMismatch", "accessors", "invalid file: accessors whose min/max disagree with their data (compared as glTF says: raw values, floats rounded to single precision); the data is drawn, the bounds are not used"},
      {"LoadStats", "keyframeTimesNotIncreasing", "channels", "invalid file: animation channels whose input times do not strictly increase; keys stably sorted by time, equal times kept (a jump)"},
      {"LoadStats", "rotationKeysNormalised", "keyframes", "invalid file: rotation keyframes whose length differs from 1 by more than 0.00769 (the glTF validator's tolerance), normalised; zero -> identity"},
      {"LoadStats", "camerasRepaired", "cameras", "invalid file: cameras with zfar <= znear, a negative znear (perspective: <= 0) or yfov outside (0, pi): zfar made infinite (drawn at znear x 1e4), znear 0.01 (orthographic 0), yfov 0.8"},
      {"LoadStats", "binChunkUnaligned", "files", "invalid file: GLB BIN chunk length not a multiple of 4 (three.js and the Sample Viewer read it): the chunk zero-padded to the next multiple of 4"},
      {"LoadStats", "dracoCountMismatch", "primitives", "invalid file: KHR_draco_mesh_compression primitives whose decoded point (or index) count differs from the count an accessor declares; the decoded geometry is drawn, as three.js draws it"},
      {"LoadStats", "jsonChunkUnpadded", "files", "invalid file: GLB JSON chunk length not a multiple of 4 (glTF 2.0 requires trailing spaces); read as three.js reads it, the BIN chunk right after the JSON's last byte (or at the next multiple of 4 when padding bytes sit there)"},
      {"LoadStats", "unusedTexturesWithoutImage", "textures", "invalid file: textures no material uses whose source image does not exist; kept without image (a texture a material uses stays an error, naming the texture and image)"},
      {"LoadStats", "basisuTexturesNotDecoded", "textures", "KHR_texture_basisu (KTX2) textures: no BasisU decoder in Debian; the texture's fallback image is used, else it is drawn untextured (listed under unsupported)"},
      {"LoadStats", "instanceRotationsNormalised", "instances", "EXT_mesh_gpu_instancing: instance ROTATIONs whose length differs from 1 by more than 0.00769, normalised; zero -> identity"},
      {"LoadStats", "instancingDrawnOnce", "nodes", "EXT_mesh_gpu_instancing on a skinned node or a Bezier patch mesh: drawn once at the node, its instances ignored (listed under unsupported)"},
      {"LoadStats", "rootsWithParent", "nodes", "invalid file: nodes a scene lists as roots that have a parent (Blender and Kenney exports list the child of an unlisted \"tmpParent\"); drawn as three.js draws them: without a listed ancestor, a root of its own at its local transform (the parent's chain not applied); under a listed ancestor, once, in that ancestor's subtree"},
      {"LoadStats", "webpTexturesWithoutSource", "textures", "textures whose EXT_texture_webp names no image (no source, or one that does not exist); the texture's own source is used, and without one it is drawn untextured (listed under unsupported when a material uses it)"},
      {"LoadStats", "accessorsPastBufferView", "accessors", "invalid file: accessors whose elements run past the end of their bufferView but stay inside its buffer; the buffer's bytes are read (past the buffer's end stays an error naming the accessor)"},
      {"LoadStats", "zeroAreaPrimitives", "primitives", "triangle primitives whose every triangle has zero area at rest (collinear or repeated corners): kept, listed under unsupported; a file whose drawn primitives are all such (and neither skinned nor morphed) is refused by render, compare and time"},
      // Image metrics (harness/render/image_metrics.h): compare, report and check.
      {"ImageMetrics", "rmse", "", "root mean square of the channel differences (bytes / 255), RGBA, every pixel"},
      {"ImageMetrics", "psnr", "dB", "20 log10(1 / rmse); null (infinite) when the images are identical"},
      {"ImageMetrics", "identical", "", "true when every byte agrees"},
      {"ImageMetrics", "meanError", "", "mean |difference| over every channel of every pixel (bytes / 255)"},
      {"ImageMetrics", "maxError", "", "largest channel difference (bytes / 255; 1/255 = one byte step)"},
      {"ImageMetrics", "maxErrorPixel", "", "where maxError first occurs: x (right), y (down), channel (0..3 = RGBA)"},
      {"ImageMetrics", "fractionOver1", "fraction", "fraction of pixels (0..1) with some channel off by more than 1/255"},
      {"ImageMetrics", "fractionOver2", "fraction", "fraction of pixels with some channel off by more than 2/255"},
      {"ImageMetrics", "fractionOver4", "fraction", "fraction of pixels with some channel off by more than 4/255"},
      {"ImageMetrics", "flip", "", "LDR-FLIP (Andersson et al. 2020, harness/render/flip.h), per pixel 0..1 at 67 ppd: mean, weightedMedian (the authors' error-weighted median), max, maxAt, pixelsPerDegree"},
  };
  return g;
}

const CounterEntry* findCounter(const std::string& group, const std::string& key) {
  for (const CounterEntry& e : counterGlossary())
    if (e.group == group && e.key == key) return &e;
  return nullptr;
}

nlohmann::json glossaryJson() {
  nlohmann::json j = nlohmann::json::object();
  for (const CounterEntry& e : counterGlossary()) j[e.group][e.key] = {{"unit", e.unit}, {"meaning", e.meaning}};
  return j;
}

std::vector<std::string> loaderFallbackLines(const Scene& scene) {
  std::vector<std::string> lines;
  const nlohmann::json stats = toJson(scene.stats);  // items() must not outlive it
  for (const auto& [key, value] : stats.items()) {
    if (!value.is_number() || value.get<double>() == 0) continue;
    const CounterEntry* e = findCounter("LoadStats", key);
    std::string line = "loader fallback: " + key + " " + value.dump();
    if (e) line += (e->unit.empty() ? "" : " " + e->unit) + ": " + e->meaning;
    lines.push_back(line);
  }
  return lines;
}

nlohmann::json loaderFallbackJson(const Scene& scene) {
  nlohmann::json j = nlohmann::json::object();
  const nlohmann::json stats = toJson(scene.stats);
  for (const auto& [key, value] : stats.items())
    if (value.is_number() && value.get<double>() != 0) j[key] = value;
  return j;
}

}  // namespace mb
