#include "harness/report/vertex_fetch.h"

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <meshoptimizer.h>

#include "harness/report/content_kinds.h"
#include "pipelines/gl/gpu_geometry.h"
#include "pipelines/gl/scene_textures.h"

namespace mb::report {
namespace {

using json = nlohmann::json;

// meshoptimizer asserts on these (a release build would read out of bounds): checked first.
bool analysable(const Primitive& p, unsigned stride) {
  if (stride == 0 || stride > 256 || p.indices.size() < 3) return false;
  for (uint32_t i : p.indices)
    if (i >= p.positions.size()) return false;
  return true;
}

// The pipeline's bytes per vertex of one class of primitives (from the upload counters), as
// a whole stride: every layout the pipelines upload is whole bytes per vertex.
unsigned strideOf(uint64_t bytes, uint64_t vertices) {
  return vertices ? unsigned(std::lround(double(bytes) / double(vertices))) : 0;
}

}  // namespace

std::string cacheModelText(const CacheModel& m) {
  return "post-transform cache: " + std::to_string(m.cacheSize) + "-entry FIFO, warps of " +
         std::to_string(m.warpSize) + " vertices, primitive groups of " + std::to_string(m.primgroupSize) +
         " triangles (meshopt_analyzeVertexCache); vertex fetch: 64-byte lines through a 128 KiB "
         "direct-mapped cache (meshopt_analyzeVertexFetch)";
}

FetchFigures analyzePrimitive(const Primitive& p, unsigned stride, const CacheModel& model) {
  FetchFigures f;
  if (!p.patchPoints.empty()) return f;  // patches: no index buffer to analyse
  if (!analysable(p, stride)) {
    f.skippedPrimitives = 1;
    return f;
  }
  const size_t count = p.indices.size() / 3 * 3;  // a trailing partial triangle is not drawn
  const meshopt_VertexFetchStatistics fetch =
      meshopt_analyzeVertexFetch(p.indices.data(), count, p.positions.size(), stride);
  const meshopt_VertexCacheStatistics cache = meshopt_analyzeVertexCache(
      p.indices.data(), count, p.positions.size(), model.cacheSize, model.warpSize, model.primgroupSize);
  std::vector<bool> seen(p.positions.size(), false);
  for (size_t i = 0; i < count; ++i) {
    if (!seen[p.indices[i]]) ++f.verticesReferenced;
    seen[p.indices[i]] = true;
  }
  f.bytesFetched = fetch.bytes_fetched;
  f.uniqueVertexBytes = f.verticesReferenced * stride;
  f.verticesTransformed = cache.vertices_transformed;
  f.triangles = count / 3;
  return f;
}

// Per kind of content: bytes fetched, unique vertex bytes (the upload those vertices need)
// and vertices referenced per frame.
static json byKindJson(const std::map<std::string, FetchFigures>& byKind) {
  json out = json::object();
  for (const auto& [key, f] : byKind)
    out[key] = {{"bytesFetchedPerFrame", f.bytesFetched}, {"uniqueVertexBytesPerFrame", f.uniqueVertexBytes},
                {"verticesReferencedPerFrame", f.verticesReferenced}};
  return out;
}

json vertexFetchJson(const Scene& scene, const PipelineStats& s, const CacheModel& model) {
  const unsigned mapped = strideOf(s.normalMappedVertexBytes, s.normalMappedVertices);
  const unsigned other = strideOf(s.vertexBytes - s.normalMappedVertexBytes, s.vertices - s.normalMappedVertices);
  FetchFigures sum;
  std::map<std::string, FetchFigures> byKind;  // content_kinds.h: material and deformation kinds
  for (const gl::DrawItem& d : gl::buildDrawList(scene)) {
    const Primitive& p = scene.meshes[size_t(d.mesh)].primitives[size_t(d.primitive)];
    const uint64_t times = std::max<uint64_t>(1, scene.nodes[size_t(d.node)].instances.size());
    const FetchFigures f = analyzePrimitive(p, gl::normalMapped(scene, p) ? mapped : other, model);
    const ContentKind kind = contentKindOf(scene, scene.nodes[size_t(d.node)], p);
    for (const std::string& key : {materialKey(kind), kind.deformation}) {
      byKind[key].bytesFetched += times * f.bytesFetched;
      byKind[key].uniqueVertexBytes += times * f.uniqueVertexBytes;
      byKind[key].verticesReferenced += times * f.verticesReferenced;
    }
    sum.bytesFetched += times * f.bytesFetched;
    sum.uniqueVertexBytes += times * f.uniqueVertexBytes;
    sum.verticesReferenced += times * f.verticesReferenced;
    sum.verticesTransformed += times * f.verticesTransformed;
    sum.triangles += times * f.triangles;
    sum.skippedPrimitives += f.skippedPrimitives;
  }
  auto ratio = [](uint64_t a, uint64_t b) { return b ? json(double(a) / double(b)) : json(nullptr); };
  return {{"bytesFetchedPerFrame", sum.bytesFetched},
          {"uniqueVertexBytesPerFrame", sum.uniqueVertexBytes},
          {"overfetch", ratio(sum.bytesFetched, sum.uniqueVertexBytes)},
          {"bytesFetchedPerVertex", ratio(sum.bytesFetched, sum.verticesReferenced)},
          {"verticesReferencedPerFrame", sum.verticesReferenced},
          {"verticesTransformedPerFrame", sum.verticesTransformed},
          {"trianglesPerFrame", sum.triangles},
          {"acmr", ratio(sum.verticesTransformed, sum.triangles)},
          {"atvr", ratio(sum.verticesTransformed, sum.verticesReferenced)},
          {"strideBytes", {{"normalMapped", mapped ? json(mapped) : json(nullptr)},
                           {"other", other ? json(other) : json(nullptr)}}},
          {"skippedPrimitives", sum.skippedPrimitives},
          {"byKind", byKindJson(byKind)},
          {"model", cacheModelText(model)}};
}

json overdrawJson(const Scene& scene) {
  uint64_t covered = 0, shaded = 0, skipped = 0;
  for (const gl::DrawItem& d : gl::buildDrawList(scene)) {
    const Primitive& p = scene.meshes[size_t(d.mesh)].primitives[size_t(d.primitive)];
    if (!p.patchPoints.empty()) continue;
    if (!analysable(p, 12)) {
      ++skipped;
      continue;
    }
    const meshopt_OverdrawStatistics o = meshopt_analyzeOverdraw(
        p.indices.data(), p.indices.size() / 3 * 3, &p.positions[0].x, p.positions.size(), sizeof(p.positions[0]));
    covered += o.pixels_covered;
    shaded += o.pixels_shaded;
  }
  return {{"overdraw", covered ? json(double(shaded) / double(covered)) : json(nullptr)},
          {"pixelsCovered", covered},
          {"pixelsShaded", shaded},
          {"skippedPrimitives", skipped},
          {"model", "meshopt_analyzeOverdraw: each mesh alone, rasterised by meshoptimizer from its fixed "
                    "views in object space; pixels shaded / pixels covered (1 = no overdraw)"}};
}

}  // namespace mb::report
