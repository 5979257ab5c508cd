// Compressed versions of a GLB, made with the codecs' own encoders: every triangle
// primitive through Draco's encoder (KHR_draco_mesh_compression), every vertex and index
// bufferView through meshoptimizer's (EXT_meshopt_compression), or every image re-encoded as
// lossless WebP by OpenImageIO (EXT_texture_webp, the texture naming it only in the extension). The bytes the compressed file no
// longer reads are zeroed, so a loader that ignored the extension would draw garbage, not the
// original. Handles what the built-in scenes write: tightly packed attributes (float, unsigned
// byte/short/int), unsigned 16/32-bit indices. Used by tests/scene, tests/render, tests/cli and the
// fuzz seeds; compiled once (compressed_gltf.cpp), so Draco's encoder and OpenImageIO's headers
// are not parsed by every test file that includes this one (through tests/hostile/hostile_cases.h).
#pragma once
#include <string>

#include "pipelines/scene/gltf/image_decode.h"
#include "tests/hostile/gltf_builder.h"

namespace mb::compressed {

using hostile::Bytes;
using hostile::Json;

struct Glb {
  Json json;
  Bytes bin;
};

Glb splitGlb(const Bytes& glb);
Bytes joinGlb(Glb g);

int componentBytes(int type);
int typeComponents(const std::string& t);

// Where accessor `a`'s tightly packed elements lie in the BIN chunk.
struct Span {
  size_t offset = 0, elementBytes = 0, count = 0;
};
Span accessorSpan(const Glb& g, int a);

// Quantisation bits of the Draco encoder: positions (max error: the largest axis extent of a
// primitive / (2^bits - 1) / 2 per coordinate), normals (octahedral), texture coordinates.
// Other attributes (tangents, joints, weights) are stored losslessly.
struct DracoBits {
  int position = 14, normal = 10, texcoord = 12;
};

// Every primitive with indices -> KHR_draco_mesh_compression (sequential connectivity, so the
// point order and count stay those of the accessors). The accessors keep count, type and
// min/max and lose their bufferView, as the extension's files have them.
Bytes dracoCompressed(const Bytes& glb, DracoBits bits = {});

// Every bufferView a primitive reads (attributes: ATTRIBUTES mode; indices: TRIANGLES) ->
// EXT_meshopt_compression (lossless: no filters). The views move to buffer 1, the fallback
// buffer without data; the compressed bytes are appended to buffer 0 (the BIN chunk).
Bytes meshoptCompressed(const Bytes& glb);

// RGBA8 pixels as a WebP in OpenImageIO's lossless mode (VP8L), written to memory. OpenImageIO
// 2.4's writer is not bit-exact even so (measured: channels off by up to a few steps / 255).
Bytes losslessWebp(int width, int height, const Bytes& rgba);

Bytes base64Decode(const std::string& s);

// The encoded bytes of `image`: its base64 data: URI or its bufferView.
Bytes imageBytes(const Glb& g, const Json& image);

// `image` decoded by the loader's decoder (image_decode.h); throws when it does not decode.
DecodedImage decodedImage(const Glb& g, const Json& image);

// Every image (PNG or JPEG, in a bufferView or a base64 data: URI) re-encoded as lossless WebP,
// kept where it was (a data: URI becomes data:image/webp); each texture names its image only
// inside EXT_texture_webp (no `source`), as files that require the extension do.
Bytes webpTextured(const Bytes& glb);

// The reference for a webpTextured file: the same file with each WebP image replaced by a PNG of
// the pixels it decodes to (stored, lossless) and the textures' `source` restored, so rendering
// both must give identical images if WebP textures take the PNG path through every pipeline.
Bytes pngOfWebpTextured(const Bytes& webpGlb);

}  // namespace mb::compressed
