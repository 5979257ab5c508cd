// Decoding glTF images (PNG, JPEG, and WebP for EXT_texture_webp) from untrusted bytes: our own
// header checks first, then OpenImageIO (libpng, libjpeg-turbo, libwebp). stb_image is not used for decoding: it wrote
// past a table on a JPEG whose Huffman counts sum past 256 (tests/fuzz/regressions/f12_*).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "pipelines/result.h"

namespace mb {

// Images above this many pixels (8192 x 8192, 256 MiB as RGBA8) are not decoded: the header
// alone decides, so a few-hundred-byte file claiming 16000 x 16000 allocates nothing.
constexpr uint64_t kMaxImagePixels = uint64_t(1) << 26;

enum class ImageFormat { Png, Jpeg, Webp };

// What a header declares; nothing is decoded.
struct ImageHeader {
  ImageFormat format = ImageFormat::Png;
  uint32_t width = 0, height = 0;
};

// Reads the PNG IHDR (which must be the first chunk) or the first JPEG frame header (SOFn,
// skipping other segments by their lengths, tolerating junk between markers as libjpeg does).
// Fails, with the reason, on anything that is neither PNG nor JPEG, on a truncated or zero-size
// header, on a PNG whose chunk lengths run past the bytes there are, and on a PNG that ends
// before a complete IEND chunk. WebP: the RIFF size must lie inside the bytes, every chunk inside
// it, and the first chunk be VP8, VP8L or VP8X with its frame size. Reads only inside
// [bytes, bytes + size).
Result<ImageHeader> readImageHeader(const uint8_t* bytes, size_t size);

struct DecodedImage {
  ImageFormat format = ImageFormat::Png;
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // width * height * 4, rows top to bottom, alpha not premultiplied
};

// readImageHeader, the pixel limit, then OpenImageIO's PNG, JPEG or WebP reader alone (never a reader
// guessed from the content), from memory. Channels are expanded as stb_image did before:
// grey -> (g, g, g, 255), grey+alpha -> (g, g, g, a), RGB -> (r, g, b, 255); 16-bit samples
// keep their high byte; PNG palettes, low bit depths and tRNS are expanded by libpng. Alpha is
// returned as stored (unassociated). Fails with a one-line reason; never throws.
Result<DecodedImage> decodeImage(const uint8_t* bytes, size_t size);

}  // namespace mb
