// GPU-relevant evidence without a GPU: what one frame of a scene makes a GPU's
// vertex stage fetch and transform, for a pipeline's own vertex layout, from meshoptimizer's
// analyzers run on the scene's index buffers. Measured on the mesh and the layout, not timed.
#pragma once
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "pipelines/pipeline.h"
#include "pipelines/scene/scene.h"

namespace mb::report {

// The post-transform cache model of meshopt_analyzeVertexCache: a FIFO of `cacheSize`
// vertices, flushed when a warp of `warpSize` vertices fills or after `primgroupSize`
// triangles. The fetch model is meshoptimizer's own (64-byte lines, 128 KiB direct-mapped).
struct CacheModel {
  unsigned cacheSize = 16, warpSize = 32, primgroupSize = 128;
};
std::string cacheModelText(const CacheModel& m = {});

// One primitive's analysis with an interleaved vertex of `strideBytes`.
struct FetchFigures {
  uint64_t bytesFetched = 0;       // cache lines missed x 64 bytes
  uint64_t uniqueVertexBytes = 0;  // vertices the indices reference x stride (a perfect fetch)
  uint64_t verticesReferenced = 0;
  uint64_t verticesTransformed = 0;  // vertex shader invocations after the post-transform cache
  uint64_t triangles = 0;
  uint64_t skippedPrimitives = 0;  // indices out of range or a stride meshoptimizer cannot model
};

// Analyses `p` (its triangle list) as a GPU with `model` would fetch and shade it.
FetchFigures analyzePrimitive(const Primitive& p, unsigned strideBytes, const CacheModel& model = {});

// Per frame, for the pipeline whose uploads `stats` counted: every primitive a drawn node
// draws, times its instances, with the pipeline's stride for that primitive (its shading-
// attribute bytes per uploaded vertex, normal-mapped and other primitives apart: the matrix
// pipeline uploads a tangent only on the former). Skin and optional streams are shared by all
// pipelines and left out. JSON: bytesFetchedPerFrame, uniqueVertexBytesPerFrame, overfetch,
// bytesFetchedPerVertex, verticesTransformedPerFrame, acmr, atvr, strideBytes, skippedPrimitives,
// byKind {kind: {bytesFetchedPerFrame, uniqueVertexBytesPerFrame, verticesReferencedPerFrame}} per
// kind of content (content_kinds.h: normalMapped, notNormalMapped, rigid, skinned, morph).
nlohmann::json vertexFetchJson(const Scene& scene, const PipelineStats& stats, const CacheModel& model = {});

// The mesh alone (the same for every pipeline): meshopt_analyzeOverdraw summed over the drawn
// primitives (pixels shaded / pixels covered, from meshoptimizer's fixed views of each mesh).
nlohmann::json overdrawJson(const Scene& scene);

}  // namespace mb::report
