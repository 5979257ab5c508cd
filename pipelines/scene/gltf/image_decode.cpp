// PNG/JPEG/WebP header checks and decoding through OpenImageIO (see image_decode.h).
#include "pipelines/scene/gltf/image_decode.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cstring>

namespace mb {
namespace {

uint32_t be32(const uint8_t* p) { return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | p[3]; }
uint32_t be16(const uint8_t* p) { return (uint32_t(p[0]) << 8) | p[1]; }

const uint8_t kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};

Result<ImageHeader> pngHeader(const uint8_t* b, size_t size) {
  // Signature, then IHDR: length 13, "IHDR", width, height, depth, colour type, ...
  if (size < 8 + 8 + 13) return Result<ImageHeader>::fail("truncated PNG header");
  if (be32(b + 8) != 13 || std::memcmp(b + 12, "IHDR", 4) != 0) return Result<ImageHeader>::fail("PNG does not start with IHDR");
  // Every chunk must lie inside the bytes, up to a complete IEND: a chunk running past the data
  // made stb_image reserve its declared length (finding F11: an IDAT of 1.1 GB in 4 kB), and a
  // PNG ending before IEND makes OpenImageIO 2.4's read callback longjmp (png_error) past a
  // std::string it just built, leaking it (finding F13). libpng reads nothing after IEND.
  bool iend = false;
  for (size_t at = 8; at + 8 <= size && !iend;) {
    uint64_t len = be32(b + at);
    if (len + 12 > size - at) return Result<ImageHeader>::fail("corrupt PNG (a chunk is longer than the image data)");
    iend = std::memcmp(b + at + 4, "IEND", 4) == 0;
    at += size_t(len) + 12;
  }
  if (!iend) return Result<ImageHeader>::fail("truncated PNG (no IEND chunk)");
  ImageHeader h;
  h.format = ImageFormat::Png;
  h.width = be32(b + 16);
  h.height = be32(b + 20);
  return h;
}

// SOF0..SOF15 except DHT (C4), JPG (C8) and DAC (CC) carry the frame size.
bool isSof(uint8_t m) { return m >= 0xC0 && m <= 0xCF && m != 0xC4 && m != 0xC8 && m != 0xCC; }

Result<ImageHeader> jpegHeader(const uint8_t* b, size_t size) {
  size_t at = 2;  // after SOI
  while (at < size) {
    // Like libjpeg's next_marker: skip junk up to a 0xFF, then fill bytes (0xFF 0xFF ...).
    while (at < size && b[at] != 0xFF) ++at;
    while (at < size && b[at] == 0xFF) ++at;
    if (at >= size) break;
    uint8_t m = b[at++];
    if (m == 0x00 || m == 0x01 || (m >= 0xD0 && m <= 0xD8)) continue;  // stuffed, TEM, RSTn, SOI: no length
    if (m == 0xD9 || m == 0xDA) return Result<ImageHeader>::fail("JPEG has no frame header before its scan data");
    if (at + 2 > size) break;
    uint32_t len = be16(b + at);
    if (len < 2) return Result<ImageHeader>::fail("corrupt JPEG (segment length below 2)");
    if (isSof(m)) {
      if (len < 8 || at + 7 > size) break;  // length, precision, height, width, components
      ImageHeader h;
      h.format = ImageFormat::Jpeg;
      h.height = be16(b + at + 3);
      h.width = be16(b + at + 5);
      return h;
    }
    at += len;
  }
  return Result<ImageHeader>::fail("truncated JPEG header (no frame header)");
}

uint32_t le32(const uint8_t* p) { return uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16) | (uint32_t(p[3]) << 24); }
uint32_t le24(const uint8_t* p) { return uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16); }

// RIFF container (WebP container specification): "RIFF" size "WEBP", then chunks of
// fourcc + little-endian size + data padded to even length. The frame size comes from the first
// chunk: VP8X (canvas, 24-bit minus one), VP8L (14-bit minus one after signature 0x2F) or VP8
// (14-bit after the key frame start code 9D 01 2A).
Result<ImageHeader> webpHeader(const uint8_t* b, size_t size) {
  using R = Result<ImageHeader>;
  if (size < 12 + 8 + 10) return R::fail("truncated WebP header");
  const uint64_t riff = le32(b + 4);
  if (riff + 8 > size) return R::fail("truncated WebP (RIFF size " + std::to_string(riff) + " runs past the image data)");
  if (riff % 2 || riff < 4 + 8) return R::fail("corrupt WebP (RIFF size " + std::to_string(riff) + ")");
  const size_t end = size_t(riff) + 8;
  for (size_t at = 12; at < end;) {
    if (at + 8 > end) return R::fail("corrupt WebP (a chunk header crosses the RIFF end)");
    const uint64_t len = le32(b + at + 4);
    if (len + (len & 1) > end - at - 8) return R::fail("corrupt WebP (a chunk is longer than the image data)");
    at += 8 + size_t(len + (len & 1));
  }
  const uint8_t* c = b + 20;  // first chunk's data
  const uint64_t len = le32(b + 16);
  ImageHeader h;
  h.format = ImageFormat::Webp;
  if (std::memcmp(b + 12, "VP8X", 4) == 0 && len >= 10) {
    h.width = le24(c + 4) + 1;
    h.height = le24(c + 7) + 1;
  } else if (std::memcmp(b + 12, "VP8L", 4) == 0 && len >= 5 && c[0] == 0x2F) {
    const uint32_t bits = le32(c + 1);
    h.width = (bits & 0x3FFF) + 1;
    h.height = ((bits >> 14) & 0x3FFF) + 1;
  } else if (std::memcmp(b + 12, "VP8 ", 4) == 0 && len >= 10 && c[3] == 0x9D && c[4] == 0x01 && c[5] == 0x2A) {
    h.width = (c[6] | (uint32_t(c[7]) << 8)) & 0x3FFF;
    h.height = (c[8] | (uint32_t(c[9]) << 8)) & 0x3FFF;
  } else {
    return R::fail("WebP has no VP8, VP8L or VP8X frame header first");
  }
  return h;
}

// OpenImageIO messages: one line, printable ASCII (they end up in JSON reports), bounded.
std::string oneLine(std::string s, const std::string& drop) {
  for (size_t p; !drop.empty() && (p = s.find(drop)) != std::string::npos;) s.erase(p, drop.size());
  std::string out;
  for (unsigned char c : s) {
    if (c == '\n') out += "; ";
    else out += (c >= 0x20 && c < 0x7F) ? char(c) : '?';
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
  return out.size() > 300 ? out.substr(0, 300) + "..." : out;
}

}  // namespace

Result<ImageHeader> readImageHeader(const uint8_t* bytes, size_t size) {
  Result<ImageHeader> h = Result<ImageHeader>::fail("not a PNG, JPEG or WebP image");
  if (size >= 8 && std::memcmp(bytes, kPngSignature, 8) == 0) h = pngHeader(bytes, size);
  else if (size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF) h = jpegHeader(bytes, size);
  else if (size >= 12 && std::memcmp(bytes, "RIFF", 4) == 0 && std::memcmp(bytes + 8, "WEBP", 4) == 0)
    h = webpHeader(bytes, size);
  if (h && (h->width == 0 || h->height == 0))
    return Result<ImageHeader>::fail("image header declares " + std::to_string(h->width) + "x" + std::to_string(h->height) + " pixels");
  return h;
}

Result<DecodedImage> decodeImage(const uint8_t* bytes, size_t size) {
  using R = Result<DecodedImage>;
  Result<ImageHeader> h = readImageHeader(bytes, size);
  if (!h) return R::fail(h.error());
  if (uint64_t(h->width) * h->height > kMaxImagePixels)
    return R::fail(std::to_string(h->width) + "x" + std::to_string(h->height) + " pixels is too large (limit " +
                   std::to_string(kMaxImagePixels) + ")");
  static const char* readers[] = {"png", "jpeg", "webp"};
  static const char* formatNames[] = {"PNG", "JPEG", "WebP"};
  const int f = int(h->format);
  // A name no file has: the reader must take its bytes from the proxy, never from disk.
  const std::string name = std::string("/nonexistent/motorbench-memory.") + readers[f];
  const std::string quoted = " (\"" + name + "\")";
  OIIO::Filesystem::IOMemReader memory(bytes, size);
  OIIO::Filesystem::IOProxy* proxy = &memory;
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);  // PNG alpha as stored, not premultiplied
  config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
  // The reader by format name: never a reader guessed from the content.
  auto in = OIIO::ImageInput::create(readers[f], false, &config, proxy);
  if (!in) return R::fail("OpenImageIO has no " + std::string(formatNames[f]) + " reader: " + oneLine(OIIO::geterror(), quoted));
  in->threads(1);
  OIIO::ImageSpec spec;
  if (!in->open(name, spec, config)) return R::fail(oneLine(in->geterror(), quoted));
  if (spec.width != int(h->width) || spec.height != int(h->height) || spec.depth != 1 || spec.nchannels < 1 ||
      spec.nchannels > 4)
    return R::fail("decoder reports " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + "x" +
                   std::to_string(spec.nchannels) + ", header " + std::to_string(h->width) + "x" + std::to_string(h->height));
  const int channels = spec.nchannels;
  const bool wide = spec.format == OIIO::TypeDesc::UINT16;  // 16-bit PNG: keep the high byte, as before
  const size_t pixels = size_t(h->width) * h->height;
  std::vector<uint8_t> raw(pixels * size_t(channels) * (wide ? 2 : 1));
  if (!in->read_image(0, 0, 0, channels, wide ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8, raw.data())) {
    std::string e = oneLine(in->geterror(), quoted);
    return R::fail(e.empty() ? "decoding failed" : e);
  }
  in->close();
  (void)in->geterror();  // warnings of a successful read are not kept in OIIO's error state
  DecodedImage out;
  out.format = h->format;
  out.width = int(h->width);
  out.height = int(h->height);
  out.rgba.resize(pixels * 4);
  for (size_t i = 0; i < pixels; ++i) {
    uint8_t c[4] = {0, 0, 0, 255};
    for (int k = 0; k < channels; ++k) {
      size_t at = i * size_t(channels) + size_t(k);
      c[k] = wide ? uint8_t(reinterpret_cast<const uint16_t*>(raw.data())[at] >> 8) : raw[at];
    }
    if (channels <= 2) {  // grey (+ alpha)
      c[3] = channels == 2 ? c[1] : 255;
      c[1] = c[2] = c[0];
    }
    std::memcpy(&out.rgba[i * 4], c, 4);
  }
  return out;
}

}  // namespace mb
