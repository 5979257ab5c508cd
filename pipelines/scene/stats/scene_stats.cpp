#include "pipelines/scene/scene_stats.h"

#include <algorithm>
#include <cmath>

#include "pipelines/scene/drawable.h"

namespace mb {

FileStats computeFileStats(const Scene& s) {
  FileStats f;
  f.file = s.source;
  f.loaded = true;
  f.nodes = int(s.nodes.size());
  f.meshes = int(s.meshes.size());
  f.materials = int(s.materials.size());
  f.textures = int(s.textures.size());
  f.images = int(s.images.size());
  f.cameras = int(s.cameras.size());
  std::vector<int> meshVertices(s.meshes.size(), 0);
  for (size_t m = 0; m < s.meshes.size(); ++m)
    for (const Primitive& p : s.meshes[m].primitives) {
      ++f.primitives;
      meshVertices[m] += int(p.positions.size());
      if (!p.patchPoints.empty()) {
        const long long perPatch = (long long)(s.patchLevel + 1) * (s.patchLevel + 1);
        f.patches += int(p.patchPoints.size() / 16);
        meshVertices[m] += int(std::min<long long>(perPatch * (long long)(p.patchPoints.size() / 16), 1LL << 30));
      }
      f.triangles += int(p.indices.size() / 3);
      bool normalMapped = p.material >= 0 && s.materials[size_t(p.material)].normal.texture >= 0;
      f.normalMappedPrimitives += normalMapped;
      f.authoredTangentPrimitives += p.hadTangents;
      f.skinnedPrimitives += !p.joints.empty();
    }
  for (size_t m = 0; m < s.meshes.size(); ++m)
    for (const Primitive& p : s.meshes[m].primitives) {
      f.vertices += int(p.positions.size());
      f.morphPrimitives += !p.targets.empty();
    }
  for (const Mesh& m : s.meshes) {
    const int targets = int(morphTargetCount(m));
    f.morphMeshes += targets > 0;
    f.morphTargets += targets;
    f.maxMorphTargets = std::max(f.maxMorphTargets, targets);
  }
  for (const Node& n : s.nodes) {
    f.matrixNodes += n.hasMatrix;
    if (n.mesh >= 0) {
      ++f.meshNodes;
      const long long copies = n.instances.empty() ? 1 : (long long)n.instances.size();
      f.instancedNodes += !n.instances.empty();
      f.instances += n.instances.empty() ? 0 : int(copies);
      f.drawnVertices = int(std::min<long long>(f.drawnVertices + copies * meshVertices[size_t(n.mesh)], 1LL << 30));
    }
  }
  // A curved-space scene draws its triangle list once per instance (no nodes or meshes).
  f.vertices += int(s.curved.positions.size());
  f.drawnVertices += int(s.curved.positions.size() * s.curved.instances.size());
  f.skins = int(s.skins.size());
  for (const Skin& k : s.skins) {
    f.joints += int(k.joints.size());
    f.maxJointsPerSkin = std::max(f.maxJointsPerSkin, int(k.joints.size()));
  }
  f.animations = int(s.animations.size());
  for (const Animation& a : s.animations)
    for (const Channel& c : a.channels) {
      ++f.channels;
      f.translationChannels += c.path == AnimPath::Translation;
      f.rotationChannels += c.path == AnimPath::Rotation;
      f.scaleChannels += c.path == AnimPath::Scale;
      f.weightsChannels += c.path == AnimPath::Weights;
      f.linearChannels += c.interpolation == Interpolation::Linear;
      f.stepChannels += c.interpolation == Interpolation::Step;
      f.cubicChannels += c.interpolation == Interpolation::CubicSpline;
    }
  f.scale = analyzeScale(s);
  f.unsupported = s.unsupported;
  f.fallbacks = s.stats;
  f.compression = s.compression;
  f.notDrawn = whyNothingDrawn(s);
  return f;
}

FileStats failedFileStats(const std::string& file, const std::string& error) {
  FileStats f;
  f.file = file;
  f.error = error;
  return f;
}

nlohmann::json toJson(const LoadStats& s) {
  return {{"flatNormalsGenerated", s.flatNormalsGenerated}, {"tangentsGenerated", s.tangentsGenerated},
          {"badNormalsReplaced", s.badNormalsReplaced}, {"badTangentsReplaced", s.badTangentsReplaced},
          {"weightsRenormalised", s.weightsRenormalised}, {"weightsZeroSum", s.weightsZeroSum},
          {"influencesTruncated", s.influencesTruncated}, {"nonFinitePositions", s.nonFinitePositions},
          {"skippedPrimitives", s.skippedPrimitives}, {"normalsRenormalised", s.normalsRenormalised},
          {"jointsOutOfRange", s.jointsOutOfRange}, {"stripsFansConverted", s.stripsFansConverted},
          {"degenerateUvTriangles", s.degenerateUvTriangles}, {"tangentSplitVertices", s.tangentSplitVertices},
          {"imagesNotDecoded", s.imagesNotDecoded}, {"accessorBoundsMismatch", s.accessorBoundsMismatch},
          {"keyframeTimesNotIncreasing", s.keyframeTimesNotIncreasing},
          {"rotationKeysNormalised", s.rotationKeysNormalised}, {"camerasRepaired", s.camerasRepaired},
          {"binChunkUnaligned", s.binChunkUnaligned}, {"basisuTexturesNotDecoded", s.basisuTexturesNotDecoded},
          {"dracoCountMismatch", s.dracoCountMismatch}, {"jsonChunkUnpadded", s.jsonChunkUnpadded},
          {"unusedTexturesWithoutImage", s.unusedTexturesWithoutImage},
          {"instanceRotationsNormalised", s.instanceRotationsNormalised},
          {"instancingDrawnOnce", s.instancingDrawnOnce}, {"rootsWithParent", s.rootsWithParent},
          {"webpTexturesWithoutSource", s.webpTexturesWithoutSource},
          {"accessorsPastBufferView", s.accessorsPastBufferView}, {"zeroAreaPrimitives", s.zeroAreaPrimitives}};
}

nlohmann::json toJson(const CompressionStats& c) {
  return {{"draco", {{"primitives", c.dracoPrimitives}, {"compressedBytes", c.dracoCompressedBytes},
                     {"decodedBytes", c.dracoDecodedBytes}}},
          {"meshopt", {{"bufferViews", c.meshoptViews}, {"compressedBytes", c.meshoptCompressedBytes},
                       {"decodedBytes", c.meshoptDecodedBytes}}},
          {"webpImages", c.webpImages}};
}

std::string describeCompression(const CompressionStats& c) {
  std::string out;
  auto add = [&](const std::string& part) { out += (out.empty() ? "" : "; ") + part; };
  if (c.dracoPrimitives)
    add("KHR_draco_mesh_compression " + std::to_string(c.dracoPrimitives) + " primitives, " +
        std::to_string(c.dracoCompressedBytes) + " compressed -> " + std::to_string(c.dracoDecodedBytes) + " decoded bytes");
  if (c.meshoptViews)
    add("meshopt " + std::to_string(c.meshoptViews) + " bufferViews, " + std::to_string(c.meshoptCompressedBytes) +
        " compressed -> " + std::to_string(c.meshoptDecodedBytes) + " decoded bytes");
  if (c.webpImages) add("EXT_texture_webp " + std::to_string(c.webpImages) + " images decoded");
  return out.empty() ? "none" : out;
}

nlohmann::json toJson(const FileStats& f) {
  nlohmann::json j = {{"file", f.file}, {"loaded", f.loaded}};
  if (!f.loaded) {
    j["error"] = f.error;
    return j;
  }
  const ScaleReport& r = f.scale;
  j["geometry"] = {{"nodes", f.nodes}, {"matrixNodes", f.matrixNodes}, {"meshes", f.meshes},
                   {"primitives", f.primitives}, {"vertices", f.vertices}, {"triangles", f.triangles},
                   {"meshNodes", f.meshNodes}, {"drawnVertices", f.drawnVertices}, {"patches", f.patches},
                   {"instancedNodes", f.instancedNodes}, {"instances", f.instances}};
  j["materials"] = {{"materials", f.materials}, {"textures", f.textures}, {"images", f.images},
                    {"normalMappedPrimitives", f.normalMappedPrimitives},
                    {"authoredTangentPrimitives", f.authoredTangentPrimitives}};
  j["skinning"] = {{"skins", f.skins}, {"joints", f.joints}, {"maxJointsPerSkin", f.maxJointsPerSkin},
                   {"skinnedPrimitives", f.skinnedPrimitives}};
  j["animation"] = {{"animations", f.animations}, {"channels", f.channels},
                    {"translation", f.translationChannels}, {"rotation", f.rotationChannels},
                    {"scale", f.scaleChannels}, {"linear", f.linearChannels}, {"step", f.stepChannels},
                    {"cubicspline", f.cubicChannels}, {"weights", f.weightsChannels}};
  j["morph"] = {{"meshes", f.morphMeshes}, {"primitives", f.morphPrimitives}, {"targets", f.morphTargets},
                {"maxTargetsPerMesh", f.maxMorphTargets}, {"animatedWeightsChannels", f.weightsChannels}};
  j["scale"] = {{"uniformNodes", r.uniformNodes}, {"nonUniformNodes", r.nonUniformNodes},
                {"negativeNodes", r.negativeNodes}, {"shearNodes", r.shearNodes},
                {"animatedScaleNodes", r.animatedScaleNodes}, {"animatedNonUniformNodes", r.animatedNonUniformNodes},
                {"nonUniform", r.nonUniformScale}, {"negative", r.negativeScale},
                {"animated", r.animatedScale}, {"animatedNonUniform", r.animatedNonUniformScale},
                {"nonUniformOnlyOnLeaves", r.nonUniformOnlyOnLeaves},
                // The statistics' one relative tolerance (scale_analysis.h): 1e-4.
                {"paperTolerance", kSimilarityTolerance}, {"scaleChannels", r.scaleChannels},
                {"changingScaleChannels", r.changingScaleChannels},
                {"constantScaleChannels", r.constantScaleChannels},
                {"constantScaleChannelsOffRest", r.constantScaleChannelsOffRest},
                {"nonUniformChangingChannels", r.nonUniformChangingChannels},
                {"innerNonUniformNodes", r.innerNonUniformNodes}};
  if (r.innerNonUniformNode >= 0) {
    const glm::vec3 sc = r.innerNonUniformScale;
    // Infinite (shear, a zero component) is written as null by JSON; say which.
    j["scale"]["innerNonUniformityMax"] = std::isfinite(r.innerNonUniformityMax) ? nlohmann::json(r.innerNonUniformityMax)
                                                                                  : nlohmann::json("shear or zero component");
    j["scale"]["innerNonUniformExample"] = {{"node", r.innerNonUniformNode},
                                            {"name", r.innerNonUniformName},
                                            {"scale", {sc.x, sc.y, sc.z}}};
  }
  j["cameras"] = f.cameras;
  j["unsupported"] = f.unsupported;
  j["fallbacks"] = toJson(f.fallbacks);
  j["compression"] = toJson(f.compression);
  j["notDrawn"] = f.notDrawn.empty() ? nlohmann::json(nullptr) : nlohmann::json(f.notDrawn);
  return j;
}

nlohmann::json aggregateJson(const std::vector<FileStats>& files) {
  nlohmann::json each = nlohmann::json::array();
  for (const FileStats& f : files) each.push_back(toJson(f));
  return aggregateFileJson(each);
}

nlohmann::json aggregateFileJson(const nlohmann::json& files) {
  int loaded = 0, animated = 0, animatedNonUniform = 0, nonUniform = 0, negative = 0, leavesOnly = 0,
      withUnsupported = 0, withFallbacks = 0, skinned = 0, normalMapped = 0;
  // The paper's 1e-4 rule: changing scale channels, of them non-uniform, inner non-uniform nodes
  // (and of those beyond 1 %, so a reader sees how far beyond the tolerance they are).
  int changing = 0, changingNonUniform = 0, inner = 0, innerBeyondPercent = 0, constantOnly = 0;
  long vertices = 0, triangles = 0, primitives = 0, joints = 0, channels = 0;
  const nlohmann::json noFallbacks = toJson(LoadStats{});
  for (const nlohmann::json& f : files) {
    if (!f.value("loaded", false)) continue;
    ++loaded;
    const nlohmann::json& sc = f["scale"];
    animated += sc.value("animated", false);
    animatedNonUniform += sc.value("animatedNonUniform", false);
    nonUniform += sc.value("nonUniform", false);
    negative += sc.value("negative", false);
    leavesOnly += sc.value("nonUniform", false) && sc.value("nonUniformOnlyOnLeaves", false);
    changing += sc.value("changingScaleChannels", 0) > 0;
    constantOnly += sc.value("changingScaleChannels", 0) == 0 && sc.value("constantScaleChannels", 0) > 0;
    changingNonUniform += sc.value("nonUniformChangingChannels", 0) > 0;
    inner += sc.value("innerNonUniformNodes", 0) > 0;
    const nlohmann::json worst = sc.value("innerNonUniformityMax", nlohmann::json());
    innerBeyondPercent += worst.is_string() || (worst.is_number() && worst.get<double>() > 0.01);
    withUnsupported += !f["unsupported"].empty();
    withFallbacks += f["fallbacks"] != noFallbacks;
    skinned += f["skinning"].value("skins", 0) > 0;
    normalMapped += f["materials"].value("normalMappedPrimitives", 0) > 0;
    vertices += f["geometry"].value("vertices", 0);
    triangles += f["geometry"].value("triangles", 0);
    primitives += f["geometry"].value("primitives", 0);
    joints += f["skinning"].value("joints", 0);
    channels += f["animation"].value("channels", 0);
  }
  auto frac = [&](int n) { return loaded ? double(n) / loaded : 0.0; };
  return {{"files", files.size()}, {"loaded", loaded}, {"failed", int(files.size()) - loaded},
          {"vertices", vertices}, {"triangles", triangles}, {"primitives", primitives},
          {"joints", joints}, {"channels", channels},
          {"filesWithAnimatedScale", animated}, {"fractionAnimatedScale", frac(animated)},
          {"filesWithAnimatedNonUniformScale", animatedNonUniform},
          {"fractionAnimatedNonUniformScale", frac(animatedNonUniform)},
          {"filesWithNonUniformScale", nonUniform}, {"fractionNonUniformScale", frac(nonUniform)},
          {"filesWithNonUniformOnlyOnLeaves", leavesOnly},
          {"paperTolerance", kSimilarityTolerance},
          {"filesWithChangingScale", changing}, {"fractionChangingScale", frac(changing)},
          {"filesWithOnlyConstantScaleChannels", constantOnly},
          {"filesWithNonUniformChangingScale", changingNonUniform},
          {"filesWithInnerNonUniformScale", inner}, {"filesWithInnerNonUniformScaleBeyond1Percent", innerBeyondPercent},
          {"filesWithNegativeScale", negative}, {"fractionNegativeScale", frac(negative)},
          {"filesSkinned", skinned}, {"filesNormalMapped", normalMapped},
          {"filesWithUnsupported", withUnsupported}, {"filesWithFallbacks", withFallbacks}};
}

}  // namespace mb
